#include "vemd/sinks/sink_factory.h"

#include <chrono>
#include <utility>

#include "vemd/sinks/jsonl_light_sink.h"
#include "vemd/sinks/preview_sink.h"
#include "vemd/sinks/recorder_sink.h"

namespace vem::vemd {
namespace {

// Adds the opened sink; a failure goes to *missing when given (and adding goes on), else back.
template <typename S>
std::expected<void, std::string> add(std::vector<std::unique_ptr<Sink>>& sinks,
                                     std::expected<S, SinkFailure> sink,
                                     std::vector<std::string>* missing) {
  if (!sink && missing != nullptr) {
    missing->push_back(std::move(sink.error().message));
    return {};
  }
  if (!sink) return std::unexpected(std::move(sink.error().message));
  sinks.push_back(std::make_unique<S>(std::move(*sink)));
  return {};
}

std::int64_t unixNowNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

}  // namespace

std::expected<std::vector<std::unique_ptr<Sink>>, std::string> makeSinks(
    const SinkConfig& config, const RecordingContext& recordingContext,
    std::vector<std::string>* missing) {
  std::vector<std::unique_ptr<Sink>> sinks;
  if (config.jsonl) {
    auto added = add(sinks, JsonlLightSink::open(*config.jsonl), missing);
    if (!added) return std::unexpected(std::move(added.error()));
  }
  if (config.record) {
    recording::WriterOptions options;
    options.syncEveryFrames = config.recordSyncEveryFrames;
    auto added = add(sinks,
                     RecorderSink::create(recordingPathFor(*config.record, unixNowNs()),
                                          recordingContext, options),
                     missing);
    if (!added) return std::unexpected(std::move(added.error()));
  }
  if (config.previewDir) {
    PreviewOptions options;
    options.every = config.previewEvery;
    options.numbered = config.previewNumbered;
    options.style.scale = config.previewScale;
    auto added = add(sinks, PreviewSink::create(*config.previewDir, options), missing);
    if (!added) return std::unexpected(std::move(added.error()));
  }
  return sinks;
}

}  // namespace vem::vemd
