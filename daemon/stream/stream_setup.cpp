#include "stream/stream_setup.h"

#include <sys/stat.h>

#include <fstream>
#include <sstream>
#include <utility>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "stream/recording_switch.h"
#include "stream/stream_sink.h"
#include "util/printable.h"
#include "vemd/daemon_setup.h"

namespace vem::stream {

namespace fs = std::filesystem;

std::expected<std::string, std::string> readTokenFile(const fs::path& path) {
  const std::string name = util::printable(path.string());
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) {
    return std::unexpected(fmt::format("stream.token_file: {}: cannot read it", name));
  }
  if ((info.st_mode & (S_IRWXG | S_IRWXO)) != 0) {
    return std::unexpected(fmt::format(
        "stream.token_file: {} can be read by group or others (mode {:o}); allow its owner only "
        "(chmod 600)",
        name, info.st_mode & 07777));
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in && !in.eof()) {
    return std::unexpected(fmt::format("stream.token_file: {}: cannot read it", name));
  }
  std::string token = text.str();
  const auto first = token.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) {
    return std::unexpected(fmt::format("stream.token_file: {} is empty", name));
  }
  token = token.substr(first, token.find_last_not_of(" \t\r\n") - first + 1);
  if (auto problem = vemd::streamTokenProblem(token)) {
    return std::unexpected(fmt::format("stream.token_file: {}: expected {}, found {}", name,
                                       vemd::streamTokenExpected(), *problem));
  }
  return token;
}

std::expected<std::string, std::string> streamToken(const vemd::StreamConfig& config) {
  if (!config.tokenFile.empty()) return readTokenFile(config.tokenFile);
  if (config.token.empty()) return config.token;
  if (auto problem = vemd::streamTokenProblem(config.token)) {
    return std::unexpected(
        fmt::format("stream.token: expected {}, found {}", vemd::streamTokenExpected(), *problem));
  }
  return config.token;
}

std::string calibrationId(const vemd::SourceDescription& source) {
  if (source.calibrationToml.empty()) return "none";
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  for (const char c : source.calibrationToml) {
    hash = (hash ^ std::uint8_t(c)) * 0x100000001b3ULL;
  }
  return fmt::format("{} {} #{:016x}", source.cameraModel, source.cameraSerial, hash);
}

std::expected<StreamServerOptions, std::string> serverOptions(
    const vemd::StreamConfig& config, const vemd::SourceDescription& source) {
  const auto address = vemd::parseListenAddress(config.listen);
  if (!address) {
    return std::unexpected(fmt::format("stream.listen: {} is not IP:PORT", config.listen));
  }
  StreamServerOptions options;
  options.address = address->host;
  options.port = address->port;
  auto token = streamToken(config);
  if (!token) return std::unexpected(token.error());
  options.token = std::move(*token);
  options.tokenRequiredToConnect = !address->loopback;
  if (options.tokenRequiredToConnect && options.token.empty()) {
    return std::unexpected(fmt::format(
        "stream.listen: {} is beyond loopback, which needs stream.token or stream.token_file",
        config.listen));
  }
  options.tlsCertFile = config.tlsCert;
  options.tlsKeyFile = config.tlsKey;
  options.maxClients = std::size_t(config.maxClients);
  options.sendTimeout = std::chrono::milliseconds(config.sendTimeoutMs);
  options.handshakeTimeout = std::chrono::milliseconds(config.handshakeTimeoutMs);
  options.maxHandshakes = std::size_t(config.maxHandshakes);
  options.maxHandshakesPerAddress = std::size_t(config.maxHandshakesPerAddress);
  options.maxClientLag = std::chrono::milliseconds(config.maxClientLagMs);
  options.sendBufferBytes = int(config.sendBufferBytes);
  options.cubemapBudget = {int(config.cubemapMaxFacePx), config.cubemapMaxRateHz};
  options.hello.set_server("vemd " VEM_VERSION);
  options.hello.set_source(source.spec);
  options.hello.set_calibration_id(calibrationId(source));
  options.hello.set_max_lights(kMaxLights);
  return options;
}

fs::path controlRecordingFolder(const vemd::VemdConfig& config) {
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

std::expected<Streaming, std::string> startStreaming(
    const vemd::VemdConfig& config, const vemd::SourceDescription& source,
    std::vector<std::unique_ptr<vemd::Sink>>& sinks) {
  Streaming streaming;
  if (!config.stream.enabled || config.stream.listen.empty()) return streaming;
  auto options = serverOptions(config.stream, source);
  if (!options) return std::unexpected(options.error());
  const bool tlsAsked = !options->tlsCertFile.empty();
  auto server = StreamServer::start(std::move(*options));
  if (!server) {
    if (tlsAsked && server.error().starts_with("stream.tls"))
      return std::unexpected(server.error());
    if (!config.output.allowMissing) {
      return std::unexpected(vemd::missingOutputRefused(server.error()));
    }
    spdlog::warn("{}", vemd::missingOutputAllowed(server.error()));
    return streaming;
  }
  streaming.server = std::move(*server);
  spdlog::info("streaming on {}", streaming.server->url());
  auto sink = std::make_unique<StreamSink>(
      *streaming.server, StreamSinkOptions{int(config.stream.cubemapZstdLevel), 256});
  recording::WriterOptions writerOptions;
  writerOptions.syncEveryFrames = std::uint32_t(config.output.recordSyncEvery);
  auto recorder = std::make_unique<RecordingSwitch>(controlRecordingFolder(config),
                                                    vemd::recordingContext(source), writerOptions);
  streaming.control = std::make_unique<StreamControl>(
      *streaming.server, *sink, recorder.get(), StreamIdentity{source.spec, calibrationId(source)});
  sinks.push_back(std::move(recorder));
  sinks.push_back(std::move(sink));
  return streaming;
}

}  // namespace vem::stream
