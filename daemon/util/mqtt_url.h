// MqttUrl: where an MQTT broker is and what under it, as vemd (--mqtt, [mqtt] url) and the clients
// (vemview --connect, vemtool subscribe / cameras) take it:
//   mqtt://[USER@]HOST[:PORT][/PREFIX[/CAMERA]]   or mqtts://... (TLS)
// HOST is a name, an IPv4 address or a bracketed IPv6 address ([::1]); PORT defaults to 1883
// (mqtt) or 8883 (mqtts); PREFIX and CAMERA are one topic level each (topicLevelProblem). A
// password never goes into a URL (it would land in logs and process lists): it comes from a file.
// Anything else is refused with one sentence. Pure.
#pragma once

#include <cstdint>
#include <expected>
#include <string>
#include <string_view>

namespace vem::util {

inline constexpr std::uint16_t kMqttPort = 1883;
inline constexpr std::uint16_t kMqttsPort = 8883;

struct MqttUrl {
  bool tls = false;      // mqtts://
  std::string username;  // "": none
  std::string host;      // without IPv6 brackets
  std::uint16_t port = kMqttPort;
  std::string prefix;  // "": not given
  std::string camera;  // "": not given

  // "mqtt://HOST:PORT" (brackets round an IPv6 address; no user, prefix or camera).
  [[nodiscard]] std::string broker() const;
};

[[nodiscard]] std::expected<MqttUrl, std::string> parseMqttUrl(std::string_view url);

// Empty when `level` can be one topic level of vemcast's (a prefix or a camera id): 1 to 64 bytes
// of ASCII letters, digits, '.', '_' and '-'; else why not, in one sentence.
[[nodiscard]] std::string topicLevelProblem(std::string_view level);

}  // namespace vem::util
