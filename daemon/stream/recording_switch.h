// RecordingSwitch: the recording that render clients start and stop with control messages
// (proto/vem_stream.proto, StartRecording / StopRecording), as a sink that is always in vemd's
// sink set and records only while switched on, through a RecorderSink (recorder_sink.h) into one
// folder.
//
// - start(name) creates FOLDER/name (".vem" added when the name has no extension; an existing
//   file is refused) or, for "", a new time-stamped file (recordingPathFor); a name outside
//   client_message_handler.h's recordingNameProblem set is refused in one sentence. stop() closes
//   it with its index. Both run on the processing thread between frames (stream_control.h).
// - consume() never fails, so the sink set never drops this sink: a write error stops the
//   recording (the file stays readable, recorder_sink.h) and is handed out once by takeFailure().
#pragma once

#include <expected>
#include <filesystem>
#include <optional>
#include <string>

#include "vemd/sink.h"
#include "vemd/sinks/recorder_sink.h"
#include "vemd/sinks/recording_context.h"

namespace vem::stream {

class RecordingSwitch final : public vemd::Sink {
 public:
  RecordingSwitch(std::filesystem::path folder, vemd::RecordingContext context,
                  recording::WriterOptions options = {});

  [[nodiscard]] std::string name() const override { return "recorder (stream control)"; }
  [[nodiscard]] std::expected<void, vemd::SinkFailure> consume(
      const vemd::ProcessedFrame& frame) override;
  [[nodiscard]] std::expected<void, vemd::SinkFailure> close() override;

  // The path recorded into, or one sentence why not.
  [[nodiscard]] std::expected<std::filesystem::path, std::string> start(const std::string& name);
  // The path that was closed, or one sentence why not.
  [[nodiscard]] std::expected<std::filesystem::path, std::string> stop();

  [[nodiscard]] bool recording() const { return recorder_.has_value(); }
  [[nodiscard]] std::optional<std::string> takeFailure();

 private:
  std::filesystem::path folder_;
  vemd::RecordingContext context_;
  recording::WriterOptions options_;
  std::optional<vemd::RecorderSink> recorder_;
  std::optional<std::string> failure_;
};

}  // namespace vem::stream
