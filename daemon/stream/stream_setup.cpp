#include "stream/stream_setup.h"

#include <utility>

#include <fmt/format.h>

#include "core/default_pattern.h"
#include "util/owner_only_file.h"
#include "util/printable.h"

namespace vem::stream {

namespace fs = std::filesystem;

std::expected<std::string, std::string> readTokenFile(const fs::path& path) {
  const std::string name = util::printable(path.string());
  auto text = util::readOwnerOnlyFile(path, "stream.token_file");
  if (!text) return std::unexpected(text.error());
  std::string token = std::move(*text);
  const auto first = token.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) {
    return std::unexpected(fmt::format("stream.token_file: {} is empty", name));
  }
  token = token.substr(first, token.find_last_not_of(" \t\r\n") - first + 1);
  if (auto problem = streamTokenProblem(token)) {
    return std::unexpected(fmt::format("stream.token_file: {}: expected {}, found {}", name,
                                       streamTokenExpected(), *problem));
  }
  return token;
}

std::expected<std::string, std::string> streamToken(const StreamSettings& config) {
  if (!config.tokenFile.empty()) return readTokenFile(config.tokenFile);
  if (config.token.empty()) return config.token;
  if (auto problem = streamTokenProblem(config.token)) {
    return std::unexpected(
        fmt::format("stream.token: expected {}, found {}", streamTokenExpected(), *problem));
  }
  return config.token;
}

std::string calibrationId(const SourceDescription& source) {
  if (source.calibrationToml.empty()) return "none";
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  for (const char c : source.calibrationToml) {
    hash = (hash ^ std::uint8_t(c)) * 0x100000001b3ULL;
  }
  return fmt::format("{} {} #{:016x}", source.cameraModel, source.cameraSerial, hash);
}

std::expected<StreamServerOptions, std::string> serverOptions(const StreamSettings& config,
                                                              const SourceDescription& source) {
  const auto address = parseListenAddress(config.listen);
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
  options.hello = helloFor(source);
  return options;
}

Hello helloFor(const SourceDescription& source) {
  Hello hello;
  hello.set_server("vemd " VEM_VERSION);
  hello.set_source(source.spec);
  hello.set_calibration_id(calibrationId(source));
  hello.set_max_lights(kMaxLights);
  return hello;
}

}  // namespace vem::stream
