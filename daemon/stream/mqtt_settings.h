// MqttSettings: vemd's [mqtt] section (config/vemd.toml documents every key; docs/protocol.md,
// "MQTT"): which broker vemd publishes to, under which prefix and camera id, with which
// credentials, and how much it may queue. vemd's configuration holds one; vemd's stream wiring
// turns it into an MqttPublisher (mqtt_publisher.h).
//
// Units are in the names: ...S seconds, ...Hz per second, ...Px texels.
#pragma once

#include <cstdint>
#include <string>

namespace vem::stream {

struct MqttSettings {
  // "": no MQTT. mqtt://[USER@]HOST[:PORT][/PREFIX[/CAMERA]] or mqtts://... (util/mqtt_url.h);
  // a prefix or camera given here wins over the keys below.
  std::string url;
  std::string prefix = "vemcast";
  std::string cameraId;         // "": this machine's host name (made a valid topic level)
  std::string credentialsFile;  // TOML: username, password; owner-only; "": none
  std::string tlsCa;            // PEM CA certificates for mqtts; "": the system's
  std::string tlsCert;          // PEM client certificate, with tls_key
  std::string tlsKey;
  std::int64_t keepAliveS = 5;
  std::int64_t queueMessages = 64;
  std::int64_t maxInFlight = 8;
  double cubemapRateHz = 0.0;  // 0: no cube maps on MQTT
  std::int64_t cubemapFacePx = 64;
  std::int64_t cubemapLevels = 1;
  friend bool operator==(const MqttSettings&, const MqttSettings&) = default;
};

}  // namespace vem::stream
