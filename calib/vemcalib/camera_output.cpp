#include "camera_output.h"

#include <chrono>
#include <ctime>

#include <fmt/chrono.h>
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "calib/io/camera_file.h"
#include "frame_arguments.h"

namespace vem::calibtool {

int reportFailure(const std::string& sentence) {
  spdlog::error("{}", sentence);
  return cli::kExitFailure;
}

std::string unloadableOutput(const calib::io::CalibFileFailure& failure) {
  return failure.message + " (the output file must load before it is updated)";
}

bool reportWritten(const std::expected<void, calib::io::CalibFileFailure>& saved,
                   const std::string& path, const std::string& what) {
  if (!saved) {
    reportFailure(saved.error().message);
    return false;
  }
  fmt::print("wrote {}: {}\n", path, what);
  return true;
}

std::expected<std::optional<calib::CameraCalibration>, std::string> loadCameraToMerge(
    const std::filesystem::path& path) {
  return toMerge(calib::io::loadCameraFile(path));
}

calib::CameraCalibration newCameraFor(const RawFrame& frame) {
  calib::CameraCalibration calibration;
  calibration.camera.sensorWidthPx = frame.width;
  calibration.camera.sensorHeightPx = frame.height;
  calibration.camera.pixelFormat = frame.format;
  return calibration;
}

std::optional<std::string> frameMismatch(const calib::CameraIdentity& camera,
                                         const std::string& cameraPath, const RawFrame& frame) {
  if (frame.width == camera.sensorWidthPx && frame.height == camera.sensorHeightPx &&
      frame.format == camera.pixelFormat)
    return std::nullopt;
  return fmt::format("the frames are {} but the camera in {} is {} x {} {}", describeFrame(frame),
                     cameraPath, camera.sensorWidthPx, camera.sensorHeightPx,
                     pixelFormatName(camera.pixelFormat));
}

std::string utcDateNow() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  return fmt::format("{:%Y-%m-%dT%H:%M:%SZ}", fmt::gmtime(now));
}

}  // namespace vem::calibtool
