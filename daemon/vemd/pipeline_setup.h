// The pipeline from a source's camera file: the shell around Pipeline::create (pipeline.h), which
// takes a calibration value. Parses the camera file's text (calib/io/camera_file.h) that a source
// describes (SourceDescription::calibrationToml) and builds the pipeline from it.
//
// Fails with one sentence, `sourceName` naming the file: options out of range (checked first),
// no camera file with the frames, a file that does not parse, or what Pipeline::create refuses.
#pragma once

#include <expected>
#include <functional>
#include <string>

#include "calib/core/camera_calibration.h"
#include "frames/processing_options.h"
#include "vemd/pipeline.h"

namespace vem::vemd {

// The calibration in a camera file's text; empty text is refused (vemd needs one).
[[nodiscard]] std::expected<calib::CameraCalibration, std::string> sourceCalibration(
    const std::string& calibrationToml, const std::string& sourceName);

// sourceCalibration, then Pipeline::create.
[[nodiscard]] std::expected<Pipeline, std::string> pipelineFromCameraFile(
    const std::string& calibrationToml, const std::string& sourceName,
    const ProcessingOptions& options, const std::function<bool()>& stopRequested = {});

}  // namespace vem::vemd
