#include "client/mqtt_url.h"

#include <fmt/format.h>

namespace vem::client {

bool isMqttUrl(std::string_view url) {
  return url.starts_with("mqtt://") || url.starts_with("mqtts://");
}

std::expected<util::MqttUrl, std::string> parseMqttCameraUrl(std::string_view url) {
  auto parsed = util::parseMqttUrl(url);
  if (parsed && (parsed->prefix.empty() || parsed->camera.empty())) {
    return std::unexpected(
        fmt::format("the MQTT address {} is refused: a camera's address ends with /PREFIX/CAMERA "
                    "(mqtt://[USER@]HOST[:PORT]/PREFIX/CAMERA)",
                    url.substr(0, 200)));
  }
  return parsed;
}

std::expected<util::MqttUrl, std::string> parseMqttBrokerUrl(std::string_view url) {
  auto parsed = util::parseMqttUrl(url);
  if (!parsed) return parsed;
  if (!parsed->camera.empty()) {
    return std::unexpected(fmt::format(
        "the MQTT address {} is refused: a broker's address names at most a prefix, no camera "
        "(mqtt://[USER@]HOST[:PORT][/PREFIX])",
        url.substr(0, 200)));
  }
  if (parsed->prefix.empty()) parsed->prefix = kDefaultMqttPrefix;
  return parsed;
}

std::string brokerHostPort(const util::MqttUrl& url) {
  const bool ipv6 = url.host.find(':') != std::string::npos;
  return ipv6 ? fmt::format("[{}]:{}", url.host, url.port)
              : fmt::format("{}:{}", url.host, url.port);
}

std::string cameraTopic(const util::MqttUrl& url, std::string_view leaf) {
  return fmt::format("{}/{}/{}", url.prefix, url.camera, leaf);
}

}  // namespace vem::client
