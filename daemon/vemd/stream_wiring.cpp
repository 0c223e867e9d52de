#include "vemd/stream_wiring.h"

#include <system_error>
#include <utility>

#include <spdlog/spdlog.h>

#include "stream/frame_encoding.h"
#include "stream/stream_setup.h"
#include "stream/stream_sink.h"
#include "vemd/daemon_setup.h"
#include "vemd/sinks/recorder_sink.h"

namespace vem::vemd {

namespace fs = std::filesystem;

fs::path controlRecordingFolder(const VemdConfig& config) {
  if (!config.stream.recordDir.empty()) return config.stream.recordDir;
  const fs::path dir = config.output.dir.empty() ? fs::path(".") : fs::path(config.output.dir);
  if (!config.output.record.empty()) {
    const fs::path record = fs::path(config.output.record).is_absolute()
                                ? fs::path(config.output.record)
                                : dir / config.output.record;
    std::error_code error;
    return fs::is_directory(record, error) ? record : record.parent_path();
  }
  return dir;
}

std::expected<Streaming, std::string> startStreaming(const VemdConfig& config,
                                                     const SourceDescription& source,
                                                     std::vector<std::unique_ptr<Sink>>& sinks) {
  Streaming streaming;
  if (!config.stream.enabled || config.stream.listen.empty()) return streaming;
  auto options = stream::serverOptions(config.stream, source);
  if (!options) return std::unexpected(options.error());
  const bool tlsAsked = !options->tlsCertFile.empty();
  auto server = stream::StreamServer::start(std::move(*options));
  if (!server) {
    if (tlsAsked && server.error().starts_with("stream.tls"))
      return std::unexpected(server.error());
    if (!config.output.allowMissing) {
      return std::unexpected(missingOutputRefused(server.error()));
    }
    spdlog::warn("{}", missingOutputAllowed(server.error()));
    return streaming;
  }
  streaming.server = std::move(*server);
  spdlog::info("streaming on {}", streaming.server->url());
  auto sink = std::make_unique<stream::StreamSink>(
      *streaming.server, stream::StreamSinkOptions{int(config.stream.cubemapZstdLevel), 256});
  recording::WriterOptions writerOptions;
  writerOptions.syncEveryFrames = std::uint32_t(config.output.recordSyncEvery);
  auto recorder = std::make_unique<stream::RecordingSwitch>(
      controlRecordingFolder(config), recorderOpener(recordingContext(source), writerOptions));
  streaming.control = std::make_unique<stream::StreamControl>(
      *streaming.server, *sink, recorder.get(),
      stream::StreamIdentity{source.spec, stream::calibrationId(source)});
  sinks.push_back(std::move(recorder));
  sinks.push_back(std::move(sink));
  return streaming;
}

stream::OpenRecording recorderOpener(RecordingContext context, recording::WriterOptions options) {
  return [context = std::move(context), options](
             const fs::path& folder,
             const std::string& fileName) -> std::expected<stream::OpenedRecording, SinkFailure> {
    const fs::path path =
        fileName.empty() ? recordingPathFor(folder, stream::unixNowNs()) : folder / fileName;
    auto recorder = RecorderSink::create(path, context, options);
    if (!recorder) return std::unexpected(std::move(recorder.error()));
    return stream::OpenedRecording{std::make_unique<RecorderSink>(std::move(*recorder)), path};
  };
}

}  // namespace vem::vemd
