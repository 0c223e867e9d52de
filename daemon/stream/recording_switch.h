// RecordingSwitch: the recording that render clients start and stop with control messages
// (proto/vem_stream.proto, StartRecording / StopRecording), as a sink that is always in vemd's
// sink set and records only while switched on, into one folder, through the recording sink that
// vemd's setup lets it open (OpenRecording: vemd's recorder, vemd/sinks/recorder_sink.h).
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
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "frames/sink.h"

namespace vem::stream {

// A recording opened for the switch: the sink that writes it and the file it writes.
struct OpenedRecording {
  std::unique_ptr<Sink> sink;
  std::filesystem::path path;
};

// Opens a new recording in `folder`: the file `fileName` (which must not exist), or, for "", a new
// time-stamped file. Fails with one sentence naming the file.
using OpenRecording = std::function<std::expected<OpenedRecording, SinkFailure>(
    const std::filesystem::path& folder, const std::string& fileName)>;

class RecordingSwitch final : public Sink {
 public:
  RecordingSwitch(std::filesystem::path folder, OpenRecording openRecording);

  [[nodiscard]] std::string name() const override { return "recorder (stream control)"; }
  [[nodiscard]] std::expected<void, SinkFailure> consume(const ProcessedFrame& frame) override;
  [[nodiscard]] std::expected<void, SinkFailure> close() override;

  // The path recorded into, or one sentence why not.
  [[nodiscard]] std::expected<std::filesystem::path, std::string> start(const std::string& name);
  // The path that was closed, or one sentence why not.
  [[nodiscard]] std::expected<std::filesystem::path, std::string> stop();

  [[nodiscard]] bool recording() const { return recorder_.sink != nullptr; }
  [[nodiscard]] std::optional<std::string> takeFailure();

 private:
  std::filesystem::path folder_;
  OpenRecording openRecording_;
  OpenedRecording recorder_;  // sink null: not recording
  std::optional<std::string> failure_;
};

}  // namespace vem::stream
