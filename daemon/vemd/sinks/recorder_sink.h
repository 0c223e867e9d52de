// RecorderSink: records vemd's raw frames, each with the lights computed from it, into a VEM
// recording (docs/vem-format.md) through recording::RecordingWriter.
//
// - The header comes from a RecordingContext (recording_context.h); every frame must have its size
//   and pixel format, and sequence numbers must increase.
// - Each frame is stored with its own lights (ProcessedFrame::lights, not the filtered set, which
//   stands for an earlier frame), so a replay can check the lights computed from the same pixels.
// - The first failure (ENOSPC, EIO, EFBIG, a frame that does not fit the header) stops the
//   recording for good: the writer is closed at once, so the file holds every frame before the
//   failure, readable, and indexed when the index and footer still fit; consume() returns one
//   SinkFailure saying so, and every later consume() and close() is a no-op that succeeds (the
//   failure was reported once).
// - close() writes the index and footer and syncs.
#pragma once

#include <cstdint>
#include <expected>
#include <filesystem>
#include <optional>
#include <string>

#include "frames/sink.h"
#include "recording/recording_writer.h"
#include "vemd/sinks/recording_context.h"

namespace vem::vemd {

class RecorderSink final : public Sink {
 public:
  // Creates the recording at `path` (never overwriting a file) and writes its header.
  [[nodiscard]] static std::expected<RecorderSink, SinkFailure> create(
      const std::filesystem::path& path, const RecordingContext& context,
      recording::WriterOptions options = {});

  [[nodiscard]] std::string name() const override { return "recorder"; }
  // "recording to PATH" (the file created, also when --record named a folder).
  [[nodiscard]] std::string note() const override { return "recording to " + path_.string(); }
  [[nodiscard]] std::expected<void, SinkFailure> consume(const ProcessedFrame& frame) override;
  [[nodiscard]] std::expected<void, SinkFailure> close() override;

  [[nodiscard]] const std::filesystem::path& path() const { return path_; }
  [[nodiscard]] std::uint64_t framesWritten() const { return framesWritten_; }
  [[nodiscard]] bool stopped() const { return !writer_; }

 private:
  RecorderSink(std::filesystem::path path, recording::RecordingWriter writer);

  std::filesystem::path path_;
  std::optional<recording::RecordingWriter> writer_;  // empty once closed or stopped
  std::uint64_t framesWritten_ = 0;
};

// Where to record for a configured path: the path itself, or, when it names a folder, a new file
// "vemd-YYYYMMDDTHHMMSSZ.vem" in it (UTC; "-1", "-2"... added when that name is taken).
[[nodiscard]] std::filesystem::path recordingPathFor(const std::filesystem::path& configured,
                                                     std::int64_t nowUnixNs);

}  // namespace vem::vemd
