#include "vemd/pipeline_setup.h"

#include <utility>

#include <fmt/format.h>

#include "calib/io/camera_file.h"

namespace vem::vemd {

std::expected<calib::CameraCalibration, std::string> sourceCalibration(
    const std::string& calibrationToml, const std::string& sourceName) {
  if (calibrationToml.empty()) {
    return std::unexpected(fmt::format(
        "{}: no calibration comes with the frames (vemd needs a camera file with photometric and "
        "geometric sections)",
        sourceName));
  }
  auto calibration = calib::io::parseCameraFile(calibrationToml, sourceName);
  if (!calibration) return std::unexpected(calibration.error().message);
  return std::move(*calibration);
}

std::expected<Pipeline, std::string> pipelineFromCameraFile(
    const std::string& calibrationToml, const std::string& sourceName,
    const ProcessingOptions& options, const std::function<bool()>& stopRequested) {
  if (auto problem = processingOptionsProblem(options)) return std::unexpected(*problem);
  auto calibration = sourceCalibration(calibrationToml, sourceName);
  if (!calibration) return std::unexpected(calibration.error());
  return Pipeline::create(std::move(*calibration), sourceName, options, stopRequested);
}

}  // namespace vem::vemd
