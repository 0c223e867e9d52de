// The MQTT addresses a client takes (docs/protocol.md, "MQTT"), over util::parseMqttUrl
// (daemon/util/mqtt_url.h: scheme, user, host, port, topic levels; the one parser vemd shares):
// - a camera's stream: mqtt://[USER@]HOST[:PORT]/PREFIX/CAMERA or mqtts://..., both levels
//   required; its topics are PREFIX/CAMERA/hello, /lights, /status, /cubemap, /control and
//   /reply/CLIENT_ID;
// - a broker, to list its cameras (`vemtool cameras`): mqtt://[USER@]HOST[:PORT][/PREFIX], the
//   prefix "vemcast" when absent, no camera.
// Anything else is refused with one sentence. Pure.
#pragma once

#include <expected>
#include <string>
#include <string_view>

#include "util/mqtt_url.h"

namespace vem::client {

inline constexpr std::string_view kDefaultMqttPrefix = "vemcast";

// The scheme is mqtt:// or mqtts:// (the rest unchecked).
[[nodiscard]] bool isMqttUrl(std::string_view url);

[[nodiscard]] std::expected<util::MqttUrl, std::string> parseMqttCameraUrl(std::string_view url);
[[nodiscard]] std::expected<util::MqttUrl, std::string> parseMqttBrokerUrl(std::string_view url);

// "host:port", the host bracketed when it is an IPv6 address: the broker in a sentence.
[[nodiscard]] std::string brokerHostPort(const util::MqttUrl& url);

// PREFIX/CAMERA/leaf
[[nodiscard]] std::string cameraTopic(const util::MqttUrl& url, std::string_view leaf);

}  // namespace vem::client
