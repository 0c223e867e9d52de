// The camera file a vemcalib command writes into: an existing file is loaded first and only the
// command's own section is replaced (commands.h); a new one starts from the frames' sensor.
#pragma once

#include <expected>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>

#include "calib/core/camera_calibration.h"
#include "calib/io/calib_file_failure.h"
#include "frames/raw_frame.h"
#include "util/cli_conventions.h"

namespace vem::calibtool {

// Exit status of every command (util/cli_conventions.h): 0 done, cli::kExitFailure (1) when an
// input could not be used or the calibration was refused or could not be written (nothing is
// written then); 2 is the parser's alone, for a bad flag or value.

// Logs `sentence` as the command's one error line and returns cli::kExitFailure.
int reportFailure(const std::string& sentence);

// The loader's sentence for an output file that exists but does not load, which is never
// overwritten: "<its sentence> (the output file must load before it is updated)".
[[nodiscard]] std::string unloadableOutput(const calib::io::CalibFileFailure& failure);

// What a loader of calib/io returned for the output file, as the file to merge into: nullopt when
// there is no file, or unloadableOutput.
template <typename T>
[[nodiscard]] std::expected<std::optional<T>, std::string> toMerge(
    std::expected<T, calib::io::CalibFileFailure> loaded) {
  if (loaded) return std::optional(std::move(*loaded));
  if (loaded.error().cause == calib::io::CalibFileError::NotFound) return std::nullopt;
  return std::unexpected(unloadableOutput(loaded.error()));
}

// Prints "wrote <path>: <what>" when `saved`, else reports its failure (reportFailure); whether the
// file was written.
[[nodiscard]] bool reportWritten(const std::expected<void, calib::io::CalibFileFailure>& saved,
                                 const std::string& path, const std::string& what);

// The calibration already at `path` (nullopt when there is no file), or the loader's sentence: a
// file that does not load is never overwritten.
[[nodiscard]] std::expected<std::optional<calib::CameraCalibration>, std::string> loadCameraToMerge(
    const std::filesystem::path& path);

// A new calibration for the sensor that took `frame`: model and serial "unknown", no sections.
[[nodiscard]] calib::CameraCalibration newCameraFor(const RawFrame& frame);

// "<path>: the frames are 640 x 480 Mono12 but the camera is 1280 x 1024 RGB12", or nothing when
// the frame fits the camera.
[[nodiscard]] std::optional<std::string> frameMismatch(const calib::CameraIdentity& camera,
                                                       const std::string& cameraPath,
                                                       const RawFrame& frame);

// Now, UTC, ISO 8601 to the second: "2026-01-31T12:00:00Z".
[[nodiscard]] std::string utcDateNow();

}  // namespace vem::calibtool
