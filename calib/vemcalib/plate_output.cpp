#include "plate_output.h"

#include <cmath>
#include <numbers>

#include <fmt/format.h>
#include <glm/matrix.hpp>

#include "calib/core/plate_probe_yaw.h"
#include "calib/io/plate_camera_file.h"
#include "camera_output.h"

namespace vem::calibtool {

std::expected<std::optional<calib::PlateCamera>, std::string> loadPlateToMerge(
    const std::filesystem::path& path) {
  return toMerge(calib::io::loadPlateCameraFile(path));
}

std::expected<calib::PlateCamera, std::string> loadPlateToUpdate(const std::filesystem::path& path,
                                                                 const std::string& what) {
  auto existing = toMerge(calib::io::loadPlateCameraFile(path));
  if (!existing) return std::unexpected(existing.error());
  if (!*existing)
    return std::unexpected(fmt::format("{}: no such file ({}: run vemcalib plate intrinsics first)",
                                       path.string(), what));
  return std::move(**existing);
}

std::string describePose(const calib::PlatePose& pose) {
  const glm::dmat3 worldFromCamera = glm::transpose(pose.cameraFromWorld);
  const glm::dvec3 forward = worldFromCamera[2];
  const glm::dvec3 right = worldFromCamera[0];
  // Roll: how far the image's +x tilts out of the horizontal plane.
  const double rollDeg = std::asin(std::clamp(right.y, -1.0, 1.0)) * kDegPerRad;
  return fmt::format(
      "({:.4f}, {:.4f}, {:.4f}) m; looking toward azimuth {:.2f} deg, {:.2f} deg below the "
      "horizon, roll {:.2f} deg",
      pose.positionWorldM.x, pose.positionWorldM.y, pose.positionWorldM.z,
      calib::azimuthRad(forward) * kDegPerRad, -calib::elevationRad(forward) * kDegPerRad, rollDeg);
}

}  // namespace vem::calibtool
