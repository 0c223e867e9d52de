// The cameras an MQTT broker knows (docs/protocol.md, "MQTT"): the retained statuses under
// PREFIX/+/status, one per camera's vemd (offline true once it is gone: its will or its goodbye),
// for `vemtool cameras`. Each payload goes through decodeServerMessage; one that does not decode,
// or is not a Status, is left out with one sentence.
//
// listCameras blocks its caller, like a command-line tool's call: it connects (bounded by
// connectTimeout), subscribes, and then collects for `wait`: the broker sends the retained
// messages right after the subscription, but how many there are it cannot know. libmosquitto 2.0,
// set up as for the stream (util/mosquitto_client.h).
#pragma once

#include <chrono>
#include <expected>
#include <string>
#include <vector>

#include "util/mosquitto_client.h"
#include "client/stream_events.h"

namespace vem::client {

struct CameraListOptions {
  std::string url;  // mqtt://[USER@]HOST[:PORT][/PREFIX] or mqtts://... (client/mqtt_url.h)
  util::MqttSecurity security;
  std::chrono::milliseconds wait{1000};
  std::chrono::milliseconds connectTimeout{5000};  // TCP, TLS, CONNACK and SUBACK
};

struct CameraStatus {
  std::string camera;  // the topic level between PREFIX and status
  Status status;
};

struct CameraList {
  std::vector<CameraStatus> cameras;  // by camera id
  std::vector<std::string> refused;   // one sentence per status left out
};

// The cameras, or one sentence when the address is unusable or the broker cannot be reached or
// refuses the client.
[[nodiscard]] std::expected<CameraList, std::string> listCameras(const CameraListOptions& options);

}  // namespace vem::client
