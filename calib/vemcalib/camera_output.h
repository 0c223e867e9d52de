// The camera file a vemcalib command writes into: an existing file is loaded first and only the
// command's own section is replaced (commands.h); a new one starts from the frames' sensor.
#pragma once

#include <expected>
#include <filesystem>
#include <optional>
#include <string>

#include "calib/core/camera_calibration.h"
#include "calib/core/raw_frame.h"

namespace vem::calibtool {

// Exit status of every command: 0 done, kExitRefused when the calibration was refused or could not
// be written (nothing written), kExitBadInput when an input file or option could not be used.
inline constexpr int kExitRefused = 1;
inline constexpr int kExitBadInput = 2;

// Logs `sentence` as the command's one error line and returns `exitCode`.
int reportFailure(const std::string& sentence, int exitCode);

// The calibration already at `path` (nullopt when there is no file), or the loader's sentence: a
// file that does not load is never overwritten.
[[nodiscard]] std::expected<std::optional<calib::CameraCalibration>, std::string> loadCameraToMerge(
    const std::filesystem::path& path);

// A new calibration for the sensor that took `frame`: model and serial "unknown", no sections.
[[nodiscard]] calib::CameraCalibration newCameraFor(const calib::RawFrame& frame);

// "<path>: the frames are 640 x 480 Mono12 but the camera is 1280 x 1024 RGB12", or nothing when
// the frame fits the camera.
[[nodiscard]] std::optional<std::string> frameMismatch(const calib::CameraIdentity& camera,
                                                       const std::string& cameraPath,
                                                       const calib::RawFrame& frame);

// Now, UTC, ISO 8601 to the second: "2026-01-31T12:00:00Z".
[[nodiscard]] std::string utcDateNow();

}  // namespace vem::calibtool
