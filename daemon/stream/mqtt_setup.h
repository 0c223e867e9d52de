// MQTT setup: from the [mqtt] settings (mqtt_settings.h) to the options of an MqttPublisher: the
// broker and the topic levels from the URL (util/mqtt_url.h; its prefix and camera win over the
// keys), the camera id defaulting to the host name, the credentials read from their file now.
//
// Refused at start, in one sentence naming the key: a URL that does not parse, a credentials file
// that cannot be read, is readable by group or others, is not TOML or lacks `username`.
#pragma once

#include <expected>
#include <string>

#include "frames/frame_source.h"
#include "stream/mqtt_publisher.h"
#include "stream/mqtt_settings.h"

namespace vem::stream {

// The host name as one topic level: characters outside [A-Za-z0-9._-] become '-', at most 64.
[[nodiscard]] std::string hostCameraId();

[[nodiscard]] std::expected<MqttPublisherOptions, std::string> mqttPublisherOptions(
    const MqttSettings& settings, const SourceDescription& source);

}  // namespace vem::stream
