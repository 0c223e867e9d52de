#include "stream/recording_switch.h"

#include <system_error>
#include <utility>

#include <fmt/format.h>

#include "stream/client_message_handler.h"
#include "stream/frame_encoding.h"

namespace vem::stream {

RecordingSwitch::RecordingSwitch(std::filesystem::path folder, vemd::RecordingContext context,
                                 recording::WriterOptions options)
    : folder_(std::move(folder)), context_(std::move(context)), options_(options) {}

std::expected<void, vemd::SinkFailure> RecordingSwitch::consume(const vemd::ProcessedFrame& frame) {
  if (!recorder_) return {};
  if (auto written = recorder_->consume(frame); !written) {
    failure_ = std::move(written.error().message);
    recorder_.reset();  // the recorder closed its file when it failed
  }
  return {};
}

std::expected<void, vemd::SinkFailure> RecordingSwitch::close() {
  if (!recorder_) return {};
  auto closed = recorder_->close();
  recorder_.reset();
  if (!closed) return std::unexpected(std::move(closed.error()));
  return {};
}

std::expected<std::filesystem::path, std::string> RecordingSwitch::start(const std::string& name) {
  if (std::string problem = recordingNameProblem(name); !problem.empty()) {
    return std::unexpected(std::move(problem));
  }
  if (recorder_) {
    return std::unexpected(
        fmt::format("a recording is already running ({})", recorder_->path().string()));
  }
  std::error_code error;
  std::filesystem::create_directories(folder_, error);
  if (error || !std::filesystem::is_directory(folder_)) {
    return std::unexpected(fmt::format("cannot use {} as the recording folder ({})",
                                       folder_.string(),
                                       error ? error.message() : "it is not a folder"));
  }
  std::filesystem::path path;
  if (name.empty()) {
    path = vemd::recordingPathFor(folder_, unixNowNs());
  } else {
    path = folder_ / name;
    if (!path.has_extension()) path += ".vem";
  }
  auto recorder = vemd::RecorderSink::create(path, context_, options_);
  if (!recorder) return std::unexpected(std::move(recorder.error().message));
  recorder_.emplace(std::move(*recorder));
  return path;
}

std::expected<std::filesystem::path, std::string> RecordingSwitch::stop() {
  if (!recorder_) return std::unexpected(std::string("no recording is running"));
  const std::filesystem::path path = recorder_->path();
  if (auto closed = close(); !closed) return std::unexpected(std::move(closed.error().message));
  return path;
}

std::optional<std::string> RecordingSwitch::takeFailure() { return std::exchange(failure_, {}); }

}  // namespace vem::stream
