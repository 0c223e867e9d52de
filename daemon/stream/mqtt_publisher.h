// MqttPublisher: vemd's stream published to an MQTT broker (Mosquitto or any MQTT 5 broker) through
// libmosquitto, under PREFIX/CAMERA/ (docs/protocol.md, "MQTT"): hello, lights and status retained,
// cube maps at a configured rate, all QoS 0; control requests taken from PREFIX/CAMERA/control and
// answered on each request's response topic. The broker does the fan-out, the bridging, the
// authentication and the ACLs; this is one client of it.
//
// The network never slows capture:
// - The processing thread's calls (publishLights, publishStatus, ...) serialize nothing new and put
//   the message into a bounded drop-oldest queue (util/drop_oldest_queue.h); they never wait for the
//   broker.
// - A sender thread takes messages from the queue only while the broker is connected and fewer
//   than maxInFlight of its messages wait in libmosquitto to be written, and hands them to
//   libmosquitto; while the broker is slow, down or restarting the queue keeps the newest and
//   counts what it drops.
// - libmosquitto's own thread (mosquitto_loop_start) does the socket I/O and reconnects after a
//   backoff (reconnectMin doubling to reconnectMax); on each connection the hello and the newest
//   status are published first.
// - A will (a retained Status with offline = true) marks the camera offline when vemd dies; the
//   destructor publishes the same itself and disconnects.
//
// Control: a message on the control topic is checked by handleClientMessage
// (client_message_handler.h, the WebSocket path's one handler) as an authorised client's (the
// broker's ACL decided who may publish there); what WebSocket would close a connection for, and
// a Subscribe, are answered ok = false with the reason.
//
// Threads: every public member is thread-safe.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <expected>
#include <memory>
#include <string>
#include <vector>

#include "stream/publisher.h"
#include "stream/subscription.h"

namespace vem::stream {

struct MqttPublisherOptions {
  std::string host = "127.0.0.1";
  std::uint16_t port = 1883;
  bool tls = false;      // mqtts: the broker verified against caFile (or the system's CAs)
  std::string caFile;    // PEM; "" with tls: the system's CAs
  std::string certFile;  // client certificate (PEM), with keyFile
  std::string keyFile;
  std::string username;  // "": none
  std::string password;
  std::string clientId;  // "": "vemd-CAMERA"
  std::string prefix = "vemcast";
  std::string cameraId;  // one topic level: no '/', '+', '#'
  int keepAliveS = 5;    // the broker publishes the will about 1.5 of these after vemd vanished
  std::size_t queueMessages = 64;
  std::size_t maxInFlight = 8;
  std::size_t maxPendingControls = 64;
  double cubemapRateHz = 0.0;  // 0: no cube maps
  CubeVariant cube;            // the one variant published
  std::chrono::milliseconds reconnectMin{1000};
  std::chrono::milliseconds reconnectMax{30'000};
  Hello hello;  // server, source, calibration_id, max_lights (control_allowed is set false)
};

struct MqttCounters {
  bool connected = false;
  std::uint64_t connects = 0;          // connections the broker accepted
  std::uint64_t connectFailures = 0;   // refused or failed attempts, and lost connections
  std::uint64_t queued = 0;            // messages put into the queue
  std::uint64_t published = 0;         // handed to libmosquitto
  std::uint64_t written = 0;           // written to the broker's socket (QoS 0) or acknowledged
  std::uint64_t dropped = 0;           // evicted from the full queue, or lost with a connection
  std::uint64_t controlsReceived = 0;  // requests handed to the processing thread
  std::uint64_t controlsRefused = 0;   // answered here (malformed, subscribe, too many waiting)
  std::uint64_t repliesUnrouted = 0;   // requests without a response topic: their reply dropped
};

class MqttPublisher final : public Publisher {
 public:
  // Checks the options and the TLS files, and starts connecting (without waiting for the broker:
  // one that is down is retried); one sentence when the options are unusable.
  [[nodiscard]] static std::expected<std::unique_ptr<MqttPublisher>, std::string> start(
      MqttPublisherOptions options);
  // Publishes the offline status, disconnects (at most about 1 s) and joins the threads.
  ~MqttPublisher() override;
  MqttPublisher(const MqttPublisher&) = delete;
  MqttPublisher& operator=(const MqttPublisher&) = delete;

  void publishLights(SharedBytes message) override;
  void publishEnvironment(const CubeVariant& variant, SharedBytes message) override;
  void publishStatus(const Status& status) override;
  [[nodiscard]] CubemapDemand cubemapDemand() const override;
  [[nodiscard]] std::vector<PendingControl> takeControls() override;
  void reply(std::uint64_t connection, const ControlReply& reply) override;
  [[nodiscard]] std::string note() const override;

  [[nodiscard]] MqttCounters counters() const;
  // "mqtt://HOST:PORT/PREFIX/CAMERA" (mqtts with TLS).
  [[nodiscard]] std::string url() const;
  // PREFIX/CAMERA/KIND: "lights", "status", "hello", "cubemap", "control".
  [[nodiscard]] std::string topic(const std::string& kind) const;

  class Impl;

 private:
  explicit MqttPublisher(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace vem::stream
