#include "plate_output.h"

#include <cmath>
#include <numbers>

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <glm/matrix.hpp>

#include "calib/core/board_detection.h"
#include "calib/core/plate_probe_yaw.h"
#include "calib/io/plate_camera_file.h"
#include "calib/io/raw_frame_file.h"
#include "frame_arguments.h"

namespace vem::calibtool {

std::expected<std::optional<calib::PlateCamera>, std::string> loadPlateToMerge(
    const std::filesystem::path& path) {
  auto existing = calib::io::loadPlateCameraFile(path);
  if (existing) return std::optional(std::move(*existing));
  if (existing.error().cause == calib::io::CalibFileError::NotFound) return std::nullopt;
  return std::unexpected(existing.error().message +
                         " (the output file must load before it is updated)");
}

std::expected<calib::PlateCamera, std::string> loadPlateToUpdate(const std::filesystem::path& path,
                                                                 const std::string& what) {
  auto existing = calib::io::loadPlateCameraFile(path);
  if (existing) return std::move(*existing);
  if (existing.error().cause == calib::io::CalibFileError::NotFound)
    return std::unexpected(fmt::format("{}: no such file ({}: run vemcalib plate intrinsics first)",
                                       path.string(), what));
  return std::unexpected(existing.error().message +
                         " (the output file must load before it is updated)");
}

std::expected<BoardImages, std::string> findBoardsInImages(const std::vector<std::string>& images,
                                                           const calib::Checkerboard& board,
                                                           std::optional<int> bits,
                                                           bool skipMissing) {
  BoardImages found;
  std::optional<RawFrame> first;
  for (const std::string& image : images) {
    auto frame = calib::io::loadRawFrame(image, bits);
    if (!frame) return std::unexpected(frame.error().message);
    if (first && (frame->width != first->width || frame->height != first->height ||
                  frame->format != first->format))
      return std::unexpected(
          fmt::format("{}: the image is {} but {} is {} (every --image must share size and format)",
                      image, describeFrame(*frame), images.front(), describeFrame(*first)));
    if (!first) first = *frame;
    std::optional<std::vector<glm::dvec2>> corners = calib::detectCheckerboard(*frame, board);
    if (!corners) {
      const std::string what = fmt::format("{}: no {}x{} checkerboard was found", image,
                                           board.innerCols, board.innerRows);
      if (!skipMissing) return std::unexpected(what + " (--skip-missing leaves such images out)");
      spdlog::warn("{}; skipped (--skip-missing)", what);
      continue;
    }
    spdlog::info("{}: found the board", image);
    found.frames.push_back(std::move(*frame));
    found.corners.push_back(std::move(*corners));
    found.names.push_back(image);
  }
  return found;
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
