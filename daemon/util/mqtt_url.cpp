#include "util/mqtt_url.h"

#include <charconv>

namespace vem::util {

namespace {

std::unexpected<std::string> refuse(std::string_view url, const std::string& why) {
  return std::unexpected("the MQTT address " + std::string(url.substr(0, 200)) + " is refused: " +
                         why);
}

}  // namespace

std::string topicLevelProblem(std::string_view level) {
  if (level.empty() || level.size() > 64) {
    return "a topic level of 1 to 64 bytes was expected, not " + std::to_string(level.size());
  }
  for (const char c : level) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '.' || c == '_' || c == '-';
    if (!ok) {
      return "a topic level holds only ASCII letters, digits, '.', '_' and '-' (no '/', '+', "
             "'#' or spaces)";
    }
  }
  return {};
}

std::string MqttUrl::broker() const {
  const bool ipv6 = host.find(':') != std::string::npos;
  return std::string(tls ? "mqtts://" : "mqtt://") + (ipv6 ? "[" : "") + host + (ipv6 ? "]" : "") +
         ":" + std::to_string(port);
}

std::expected<MqttUrl, std::string> parseMqttUrl(std::string_view url) {
  MqttUrl out;
  std::string_view rest;
  if (url.starts_with("mqtt://")) {
    rest = url.substr(7);
  } else if (url.starts_with("mqtts://")) {
    out.tls = true;
    out.port = kMqttsPort;
    rest = url.substr(8);
  } else {
    return refuse(url, "mqtt:// or mqtts:// was expected at its start");
  }
  if (rest.find_first_of("?#") != std::string_view::npos) {
    return refuse(url, "a query or a fragment is not part of an MQTT address");
  }
  const std::size_t slash = rest.find('/');
  std::string_view authority = rest.substr(0, slash);
  std::string_view path = slash == std::string_view::npos ? "" : rest.substr(slash + 1);
  if (const std::size_t at = authority.rfind('@'); at != std::string_view::npos) {
    const std::string_view user = authority.substr(0, at);
    if (user.find(':') != std::string_view::npos) {
      return refuse(url, "a password does not belong in the address; give it in a file");
    }
    if (user.empty()) return refuse(url, "the user name before '@' is empty");
    out.username = std::string(user);
    authority = authority.substr(at + 1);
  }
  std::string_view portText;
  if (authority.starts_with('[')) {
    const std::size_t close = authority.find(']');
    if (close == std::string_view::npos) return refuse(url, "the IPv6 address lacks its ']'");
    out.host = std::string(authority.substr(1, close - 1));
    const std::string_view after = authority.substr(close + 1);
    if (!after.empty() && !after.starts_with(':')) {
      return refuse(url, "':' and a port were expected after the IPv6 address");
    }
    if (!after.empty()) portText = after.substr(1);
    if (!after.empty() && portText.empty()) return refuse(url, "the port after ':' is empty");
  } else {
    const std::size_t colon = authority.find(':');
    out.host = std::string(authority.substr(0, colon));
    if (colon != std::string_view::npos) {
      portText = authority.substr(colon + 1);
      if (portText.empty()) return refuse(url, "the port after ':' is empty");
    }
  }
  if (out.host.empty()) return refuse(url, "the broker's host is missing");
  if (!portText.empty()) {
    unsigned port = 0;
    const auto [end, ec] = std::from_chars(portText.data(), portText.data() + portText.size(), port);
    if (ec != std::errc() || end != portText.data() + portText.size() || port < 1 ||
        port > 65535) {
      return refuse(url, "a port from 1 to 65535 was expected");
    }
    out.port = std::uint16_t(port);
  }
  if (path.ends_with('/')) path.remove_suffix(1);
  if (!path.empty()) {
    const std::size_t split = path.find('/');
    const std::string_view prefix = path.substr(0, split);
    const std::string_view camera =
        split == std::string_view::npos ? std::string_view() : path.substr(split + 1);
    if (std::string p = topicLevelProblem(prefix); !p.empty()) {
      return refuse(url, "its prefix: " + p);
    }
    out.prefix = std::string(prefix);
    if (split != std::string_view::npos) {
      if (std::string p = topicLevelProblem(camera); !p.empty()) {
        return refuse(url, "its camera: " + p);
      }
      out.camera = std::string(camera);
    }
  }
  return out;
}

}  // namespace vem::util
