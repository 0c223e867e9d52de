#include "vemd/sinks/recorder_sink.h"

#include <chrono>
#include <ctime>
#include <system_error>
#include <utility>

#include "util/contract.h"

namespace vem::vemd {
namespace {

std::int64_t unixNowNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

}  // namespace

std::filesystem::path recordingPathFor(const std::filesystem::path& configured,
                                       std::int64_t nowUnixNs) {
  std::error_code error;
  // "runs/" names a folder whether or not it exists yet: made here, as --out makes its folder.
  if (!configured.has_filename()) std::filesystem::create_directories(configured, error);
  if (!std::filesystem::is_directory(configured, error)) return configured;
  const std::time_t seconds = std::time_t(nowUnixNs / 1'000'000'000);
  std::tm utc{};
  ::gmtime_r(&seconds, &utc);
  char stamp[32] = {};
  std::strftime(stamp, sizeof stamp, "%Y%m%dT%H%M%SZ", &utc);
  const std::string stem = std::string("vemd-") + stamp;
  std::filesystem::path path = configured / (stem + ".vem");
  for (int n = 1; std::filesystem::exists(path, error) && n < 1000; ++n) {
    path = configured / (stem + "-" + std::to_string(n) + ".vem");
  }
  return path;
}

std::expected<RecorderSink, SinkFailure> RecorderSink::create(const std::filesystem::path& path,
                                                              const RecordingContext& context,
                                                              recording::WriterOptions options) {
  options.replaceExisting = false;
  auto writer =
      recording::RecordingWriter::create(path, recordingHeader(context, unixNowNs()), options);
  if (!writer) return std::unexpected(SinkFailure{"recorder: " + writer.error().message});
  return RecorderSink(path, std::move(*writer));
}

RecorderSink::RecorderSink(std::filesystem::path path, recording::RecordingWriter writer)
    : path_(std::move(path)), writer_(std::move(writer)) {}

std::expected<void, SinkFailure> RecorderSink::consume(const ProcessedFrame& frame) {
  VEM_EXPECTS(frame.captured != nullptr);  // the pipeline always sets it
  if (!writer_) return {};
  const CapturedFrame& captured = *frame.captured;
  auto appended =
      writer_->append(captured.seq, captured.captureTsNs, captured.frame, &frame.lights);
  framesWritten_ = writer_->framesWritten();  // a frame whose sync failed is still in the file
  if (appended) return {};
  // Stop for good: close now so the file so far is complete (indexed when the index still fits).
  const bool indexed = writer_->close().has_value();
  writer_.reset();
  return std::unexpected(SinkFailure{
      "recorder: " + appended.error().message + "; recording stopped, the file closed " +
      (indexed ? "with an index" : "without an index (`vemtool recover` can add one)")});
}

std::expected<void, SinkFailure> RecorderSink::close() {
  if (!writer_) return {};
  auto closed = writer_->close();
  writer_.reset();
  if (!closed) return std::unexpected(SinkFailure{"recorder: " + closed.error().message});
  return {};
}

}  // namespace vem::vemd
