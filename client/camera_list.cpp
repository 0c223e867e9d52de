#include "client/camera_list.h"

#include <mosquitto.h>
#include <mqtt_protocol.h>

#include <algorithm>
#include <cerrno>
#include <map>
#include <optional>

#include <fmt/format.h>

#include "client/mqtt_url.h"
#include "client/server_message_decoder.h"

namespace vem::client {
namespace {

using Clock = std::chrono::steady_clock;

constexpr int kKeepAliveS = 10;

// What the callbacks learn (the caller's thread: libmosquitto runs them inside mosquitto_loop).
struct Listing {
  const util::MqttUrl* url = nullptr;
  std::string statusTopic;
  bool connected = false;
  std::optional<Clock::time_point> subscribedAt;
  std::optional<std::string> failure;  // ends the listing
  std::string firstLoggedError;
  std::map<std::string, Status> statuses;
  std::vector<std::string> refused;
};

Listing& listingOf(void* userdata) { return *static_cast<Listing*>(userdata); }

void onConnect(mosquitto* client, void* userdata, int reasonCode, int, const mosquitto_property*) {
  Listing& l = listingOf(userdata);
  if (reasonCode != MQTT_RC_SUCCESS) {
    l.failure = fmt::format("the broker {} refused the connection: {}", brokerHostPort(*l.url),
                            util::brokerReasonText(reasonCode));
    return;
  }
  l.connected = true;
  const int rc = mosquitto_subscribe_v5(client, nullptr, l.statusTopic.c_str(), 0, 0, nullptr);
  if (rc != MOSQ_ERR_SUCCESS) {
    l.failure = fmt::format("cannot subscribe to {} at the broker {}: {}", l.statusTopic,
                            brokerHostPort(*l.url), util::mosquittoFailureText(rc, errno, ""));
  }
}

void onSubscribe(mosquitto*, void* userdata, int, int count, const int* granted,
                 const mosquitto_property*) {
  Listing& l = listingOf(userdata);
  if (count > 0 && granted[0] >= MQTT_RC_UNSPECIFIED) {
    l.failure = fmt::format("the broker {} refused the subscription to {}: {}",
                            brokerHostPort(*l.url), l.statusTopic, util::brokerReasonText(granted[0]));
    return;
  }
  l.subscribedAt = Clock::now();
}

// PREFIX/CAMERA/status: CAMERA.
std::string cameraOf(std::string_view topic) {
  topic.remove_suffix(std::string_view("/status").size());
  return std::string(topic.substr(topic.find('/') + 1));
}

void onMessage(mosquitto*, void* userdata, const mosquitto_message* message,
               const mosquitto_property*) {
  Listing& l = listingOf(userdata);
  const std::string camera = cameraOf(message->topic);
  if (message->payloadlen <= 0) {  // a retained status cleared: the camera is forgotten
    l.statuses.erase(camera);
    return;
  }
  DecodeResult decoded = decodeServerMessage(std::string_view(
      static_cast<const char*>(message->payload), std::size_t(message->payloadlen)));
  if (!decoded.ok()) {
    l.refused.push_back(
        fmt::format("the status of camera {} is refused: {}", camera, decoded.error));
  } else if (auto* status = std::get_if<Status>(&decoded.event)) {
    l.statuses[camera] = std::move(*status);
  } else {
    l.refused.push_back(
        fmt::format("the status topic of camera {} holds another message than a Status", camera));
  }
}

void onLog(mosquitto*, void* userdata, int level, const char* text) {
  Listing& l = listingOf(userdata);
  if (level == MOSQ_LOG_ERR && l.firstLoggedError.empty()) l.firstLoggedError = text;
}

// Runs the loop until the listing's end: `wait` after the SUBACK, a failure, or the deadline.
std::optional<std::string> collect(mosquitto* client, Listing& l,
                                   const CameraListOptions& options) {
  const Clock::time_point connectDeadline = Clock::now() + options.connectTimeout;
  while (!l.failure) {
    const Clock::time_point end = l.subscribedAt ? *l.subscribedAt + options.wait : connectDeadline;
    const auto left = std::chrono::ceil<std::chrono::milliseconds>(end - Clock::now());
    if (left.count() <= 0) {
      if (l.subscribedAt) return std::nullopt;
      return fmt::format("the connection to the broker {} failed: no answer within {} ms",
                         brokerHostPort(*l.url), options.connectTimeout.count());
    }
    errno = 0;
    const int rc = mosquitto_loop(client, int(std::min<std::int64_t>(left.count(), 1000)), 1);
    if (rc != MOSQ_ERR_SUCCESS && !l.failure) {
      return fmt::format("the connection to the broker {} {}: {}", brokerHostPort(*l.url),
                         l.connected ? "was lost" : "failed",
                         util::mosquittoFailureText(rc, errno, l.firstLoggedError));
    }
  }
  return l.failure;
}

}  // namespace

std::expected<CameraList, std::string> listCameras(const CameraListOptions& options) {
  const auto url = parseMqttBrokerUrl(options.url);
  if (!url) return std::unexpected(url.error());
  Listing listing;
  listing.url = &*url;
  listing.statusTopic = url->prefix + "/+/status";
  auto client = util::newMosquittoClient(*url, options.security, &listing);
  if (!client) return std::unexpected(client.error());
  mosquitto* m = client->handle.get();
  mosquitto_connect_v5_callback_set(m, onConnect);
  mosquitto_subscribe_v5_callback_set(m, onSubscribe);
  mosquitto_message_v5_callback_set(m, onMessage);
  mosquitto_log_callback_set(m, onLog);
  errno = 0;
  const int rc =
      mosquitto_connect_bind_async(m, url->host.c_str(), url->port, kKeepAliveS, nullptr);
  if (rc != MOSQ_ERR_SUCCESS) {
    return std::unexpected(fmt::format("the connection to the broker {} failed: {}",
                                       brokerHostPort(*url),
                                       util::mosquittoFailureText(rc, errno, listing.firstLoggedError)));
  }
  const std::optional<std::string> failure = collect(m, listing, options);
  if (mosquitto_socket(m) != -1 && mosquitto_disconnect(m) == MOSQ_ERR_SUCCESS) {
    for (int i = 0; i < 10 && mosquitto_socket(m) != -1; ++i) mosquitto_loop(m, 100, 1);
  }
  if (failure) return std::unexpected(*failure);
  CameraList out;
  for (auto& [camera, status] : listing.statuses)
    out.cameras.push_back({camera, std::move(status)});
  out.refused = std::move(listing.refused);
  return out;
}

}  // namespace vem::client
