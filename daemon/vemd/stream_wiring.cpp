#include "vemd/stream_wiring.h"

#include <system_error>
#include <utility>

#include <spdlog/spdlog.h>

#include "stream/frame_encoding.h"
#include "stream/mqtt_setup.h"
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

namespace {

// The WebSocket server, when [stream] asks for one: null when it is off, or when its port cannot
// be bound and output.allow_missing is set.
std::expected<std::unique_ptr<stream::StreamServer>, std::string> startServer(
    const VemdConfig& config, const SourceDescription& source) {
  if (!config.stream.enabled || config.stream.listen.empty()) return nullptr;
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
    return nullptr;
  }
  spdlog::info("streaming on {}", (*server)->url());
  return std::move(*server);
}

std::expected<std::unique_ptr<stream::MqttPublisher>, std::string> startMqtt(
    const VemdConfig& config, const SourceDescription& source) {
  if (config.mqtt.url.empty()) return nullptr;
  auto options = stream::mqttPublisherOptions(config.mqtt, source);
  if (!options) return std::unexpected(options.error());
  auto publisher = stream::MqttPublisher::start(std::move(*options));
  if (!publisher) return std::unexpected(publisher.error());
  spdlog::info("publishing to {}", (*publisher)->url());
  return std::move(*publisher);
}

}  // namespace

std::expected<Streaming, std::string> startStreaming(const VemdConfig& config,
                                                     const SourceDescription& source,
                                                     std::vector<std::unique_ptr<Sink>>& sinks) {
  Streaming streaming;
  auto server = startServer(config, source);
  if (!server) return std::unexpected(server.error());
  auto mqtt = startMqtt(config, source);
  if (!mqtt) return std::unexpected(mqtt.error());
  streaming.server = std::move(*server);
  streaming.mqtt = std::move(*mqtt);
  stream::Publisher* publisher = nullptr;
  if (streaming.server && streaming.mqtt) {
    streaming.both = std::make_unique<stream::PublisherFanOut>(
        std::vector<stream::Publisher*>{streaming.server.get(), streaming.mqtt.get()});
    publisher = streaming.both.get();
  } else if (streaming.server) {
    publisher = streaming.server.get();
  } else if (streaming.mqtt) {
    publisher = streaming.mqtt.get();
  } else {
    return streaming;
  }
  auto sink = std::make_unique<stream::StreamSink>(
      *publisher, stream::StreamSinkOptions{int(config.stream.cubemapZstdLevel), 256});
  recording::WriterOptions writerOptions;
  writerOptions.syncEveryFrames = std::uint32_t(config.output.recordSyncEvery);
  auto recorder = std::make_unique<stream::RecordingSwitch>(
      controlRecordingFolder(config), recorderOpener(recordingContext(source), writerOptions));
  streaming.control = std::make_unique<stream::StreamControl>(
      *publisher, *sink, recorder.get(),
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
