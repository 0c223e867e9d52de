#include "stream/mqtt_setup.h"

#include <unistd.h>

#include <array>
#include <utility>

#include <fmt/format.h>

#include "proto/stream_protocol.h"  // usableCubeLevels
#include "stream/stream_setup.h"
#include "util/mqtt_url.h"
#include "util/owner_only_file.h"
#include "util/toml_reader.h"

namespace vem::stream {

namespace {

struct Credentials {
  std::string username;
  std::string password;
};

std::expected<Credentials, std::string> readCredentials(const std::string& path) {
  auto text = util::readOwnerOnlyFile(path, "mqtt.credentials_file");
  if (!text) return std::unexpected(text.error());
  auto document = util::parseToml(*text, path);
  if (!document) return std::unexpected("mqtt.credentials_file: " + document.error().message);
  util::TomlStatus status{path, std::nullopt};
  util::TomlReader reader(*document, "", status);
  reader.onlyKeys({"username", "password"});
  Credentials credentials;
  credentials.username = reader.string("username");
  reader.optionalText("password", credentials.password);
  if (!status.ok()) return std::unexpected("mqtt.credentials_file: " + status.failure->message);
  return credentials;
}

}  // namespace

std::string hostCameraId() {
  std::array<char, 256> name{};
  if (::gethostname(name.data(), name.size() - 1) != 0 || name[0] == '\0') return "camera";
  std::string id(name.data());
  if (id.size() > 64) id.resize(64);
  for (char& c : id) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '.' || c == '_' || c == '-';
    if (!ok) c = '-';
  }
  return id;
}

std::expected<MqttPublisherOptions, std::string> mqttPublisherOptions(
    const MqttSettings& settings, const SourceDescription& source) {
  auto url = util::parseMqttUrl(settings.url);
  if (!url) return std::unexpected("mqtt.url: " + url.error());
  MqttPublisherOptions options;
  options.host = url->host;
  options.port = url->port;
  options.tls = url->tls;
  options.prefix = url->prefix.empty() ? settings.prefix : url->prefix;
  options.cameraId = !url->camera.empty()       ? url->camera
                     : !settings.cameraId.empty() ? settings.cameraId
                                                  : hostCameraId();
  options.username = url->username;
  if (!settings.credentialsFile.empty()) {
    auto credentials = readCredentials(settings.credentialsFile);
    if (!credentials) return std::unexpected(credentials.error());
    if (!options.username.empty() && options.username != credentials->username) {
      return std::unexpected(fmt::format(
          "mqtt.url: its user {} differs from the user in mqtt.credentials_file", url->username));
    }
    options.username = credentials->username;
    options.password = credentials->password;
  }
  options.caFile = settings.tlsCa;
  options.certFile = settings.tlsCert;
  options.keyFile = settings.tlsKey;
  options.keepAliveS = int(settings.keepAliveS);
  options.queueMessages = std::size_t(settings.queueMessages);
  options.maxInFlight = std::size_t(settings.maxInFlight);
  options.cubemapRateHz = settings.cubemapRateHz;
  options.cube.facePx = int(settings.cubemapFacePx);
  options.cube.levels = usableCubeLevels(options.cube.facePx, int(settings.cubemapLevels));
  options.hello = helloFor(source);
  return options;
}

}  // namespace vem::stream
