#include "stream/recording_switch.h"

#include <system_error>
#include <utility>

#include <fmt/format.h>

#include "stream/client_message_handler.h"

namespace vem::stream {

RecordingSwitch::RecordingSwitch(std::filesystem::path folder, OpenRecording openRecording)
    : folder_(std::move(folder)), openRecording_(std::move(openRecording)) {}

std::expected<void, SinkFailure> RecordingSwitch::consume(const ProcessedFrame& frame) {
  if (!recording()) return {};
  if (auto written = recorder_.sink->consume(frame); !written) {
    failure_ = std::move(written.error().message);
    recorder_ = {};  // the recorder closed its file when it failed
  }
  return {};
}

std::expected<void, SinkFailure> RecordingSwitch::close() {
  if (!recording()) return {};
  auto closed = recorder_.sink->close();
  recorder_ = {};
  if (!closed) return std::unexpected(std::move(closed.error()));
  return {};
}

std::expected<std::filesystem::path, std::string> RecordingSwitch::start(const std::string& name) {
  if (std::string problem = recordingNameProblem(name); !problem.empty()) {
    return std::unexpected(std::move(problem));
  }
  if (recording()) {
    return std::unexpected(
        fmt::format("a recording is already running ({})", recorder_.path.string()));
  }
  std::error_code error;
  std::filesystem::create_directories(folder_, error);
  if (error || !std::filesystem::is_directory(folder_)) {
    return std::unexpected(fmt::format("cannot use {} as the recording folder ({})",
                                       folder_.string(),
                                       error ? error.message() : "it is not a folder"));
  }
  std::filesystem::path fileName = name;
  if (!name.empty() && !fileName.has_extension()) fileName += ".vem";
  auto recorder = openRecording_(folder_, fileName.string());
  if (!recorder) return std::unexpected(std::move(recorder.error().message));
  recorder_ = std::move(*recorder);
  return recorder_.path;
}

std::expected<std::filesystem::path, std::string> RecordingSwitch::stop() {
  if (!recording()) return std::unexpected(std::string("no recording is running"));
  const std::filesystem::path path = recorder_.path;
  if (auto closed = close(); !closed) return std::unexpected(std::move(closed.error().message));
  return path;
}

std::optional<std::string> RecordingSwitch::takeFailure() { return std::exchange(failure_, {}); }

}  // namespace vem::stream
