// What `vemtool synth` and `vemtool import` share: the camera they render through (a camera file or
// the built-in example, daemon/synth/default_camera.h), the header of the recording they write,
// and that recording written so that a failure leaves nothing at --out: frames go to a hidden
// temporary file beside it, which is linked (or, with overwrite, renamed) into place only when
// complete, and removed otherwise.
#pragma once

#include <cstdint>
#include <expected>
#include <filesystem>
#include <optional>
#include <string>

#include "calib/core/camera_calibration.h"
#include "frames/raw_frame.h"
#include "recording/recording_header.h"
#include "recording/recording_writer.h"

namespace vem::tool {

// The camera at `path` (or the built-in example without one), refused in one sentence when it
// cannot render frames (no photometric or geometric section).
[[nodiscard]] std::expected<calib::CameraCalibration, std::string> loadRenderingCamera(
    const std::optional<std::string>& path);

// Header for frames of `camera` at `rateHz`, with the camera file's TOML and the writer's name.
[[nodiscard]] recording::RecordingHeader renderedRecordingHeader(
    const calib::CameraCalibration& camera, double rateHz, const std::string& writerName);

// Frame seq's capture time: seq x 1e9 / rateHz ns, rounded.
[[nodiscard]] std::int64_t frameTimestampNs(std::uint64_t seq, double rateHz);

class PendingRecording {
 public:
  // Refuses (one sentence naming `out`) an existing `out` unless `overwrite`, a missing folder,
  // or a temporary file that cannot be made.
  [[nodiscard]] static std::expected<PendingRecording, std::string> create(
      const std::filesystem::path& out, const recording::RecordingHeader& header, bool overwrite);

  PendingRecording(PendingRecording&&) noexcept;
  PendingRecording& operator=(PendingRecording&&) = delete;
  PendingRecording(const PendingRecording&) = delete;
  ~PendingRecording();  // removes the temporary file unless committed

  [[nodiscard]] std::expected<void, std::string> append(std::uint64_t seq, std::int64_t timestampNs,
                                                        const RawFrame& frame);
  // Closes the recording and puts it at `out`.
  [[nodiscard]] std::expected<void, std::string> commit();
  [[nodiscard]] std::uint64_t bytesWritten() const;

 private:
  PendingRecording(std::filesystem::path out, std::filesystem::path temporary,
                   recording::RecordingWriter writer, bool overwrite);
  [[nodiscard]] std::string aboutOut(std::string message) const;

  std::filesystem::path out_;
  std::filesystem::path temporary_;
  std::optional<recording::RecordingWriter> writer_;
  bool overwrite_ = false;
  bool committed_ = false;
  std::uint64_t bytes_ = 0;
};

}  // namespace vem::tool
