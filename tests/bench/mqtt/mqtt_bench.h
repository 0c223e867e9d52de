// The MQTT benchmark's measurements (issue 22), each against the real vemd (VemdWithMqtt: the
// synthetic sky at a camera's 30 frames/s, 1024 lights, default processing, its WebSocket server
// and [mqtt] both on) and a real Mosquitto (tests/support/mosquitto_broker.h), all on 127.0.0.1,
// a fresh broker and vemd for each run:
// - fanOut: N subscribers to the light frames, either through the broker (MQTT 5, QoS 0, one
//   libmosquitto client each) or straight from vemd over WebSocket (one raw client each), over a
//   window: per-subscriber rate, seq gaps, latency publish_unix_ns -> receipt (CLOCK_REALTIME;
//   every frame of every subscriber is decoded), vemd's processed frames and drops (its Status on
//   the broker, read by one more subscriber), and the CPU time (/proc/PID/stat) of vemd, the broker
//   and this benchmark's own process, which all share the machine's cores;
// - twoCameras: two vemd (cam1, cam2) on one broker, the subscribers split between them;
// - payloadSizes: the bytes of each payload as the broker delivers it: light frames per light
//   count, cube maps per [mqtt] cubemap_face_px / cubemap_levels, status and hello.
// Each returns one sentence when a process or a client does not come up.
#pragma once

#include <cstddef>
#include <cstdint>
#include <expected>
#include <string>
#include <vector>

#include "bench/mqtt/delivery_tally.h"

namespace vem::bench {

struct MqttBenchSetup {
  std::string vemdPath;
  // The broker's `set_tcp_nodelay true`, as config/mosquitto/vemcast.conf sets it (false:
  // Mosquitto's default, Nagle's algorithm on the broker's sockets to its subscribers).
  bool brokerNoDelay = true;
};

enum class FanOutPath { Mqtt, WebSocket };

// Percent of one core over the window, and per processed frame.
struct CpuUse {
  double percent = 0.0;
  double msPerFrame = 0.0;
};

struct VemdFigures {
  std::string cameraId;
  double processedHz = 0.0;          // its Status: frames processed per second over the window
  std::uint64_t processed = 0;       // ... and how many
  std::uint64_t captureDropped = 0;  // by its capture queue
  std::uint64_t publishDropped = 0;  // by its MQTT publisher (Status.publish_dropped)
  CpuUse cpu;
};

struct FanOutResult {
  FanOutPath path = FanOutPath::Mqtt;
  std::size_t subscribers = 0;
  double windowS = 0.0;
  DeliverySummary delivery;
  std::size_t lostConnections = 0;
  VemdFigures vemd;
  CpuUse broker;
  double brokerUsPerDelivered = 0.0;  // broker CPU per light frame delivered to a subscriber
  double benchCpuPercent = 0.0;       // this process: the subscribers and the status reader
  double machineBusyPercent = 0.0;    // all cores together, kernel included (200 %: 2 cores full)
};

[[nodiscard]] std::expected<FanOutResult, std::string> fanOut(const MqttBenchSetup& setup,
                                                              FanOutPath path,
                                                              std::size_t subscribers,
                                                              double windowS);

struct CameraDelivery {
  VemdFigures vemd;
  DeliverySummary delivery;
};

struct TwoCamerasResult {
  std::size_t subscribers = 0;
  double windowS = 0.0;
  std::vector<CameraDelivery> cameras;  // cam1, cam2
  std::size_t lostConnections = 0;
  double brokerCpuPercent = 0.0;
  double brokerUsPerDelivered = 0.0;
  double benchCpuPercent = 0.0;
  double machineBusyPercent = 0.0;
};

[[nodiscard]] std::expected<TwoCamerasResult, std::string> twoCameras(const MqttBenchSetup& setup,
                                                                      std::size_t subscribers,
                                                                      double windowS);

struct PayloadSize {
  std::string what;            // "light frame, 1024 lights", "cube map 128 px, 8 levels"...
  std::string topic;           // "lights", "cubemap", "status", "hello"
  double bytes = 0.0;          // median payload bytes
  double rateHz = 0.0;         // messages per second on the topic while measured (0: not timed)
  double rawTexelBytes = 0.0;  // cube maps: texels before zstd
};

[[nodiscard]] std::expected<std::vector<PayloadSize>, std::string> payloadSizes(
    const MqttBenchSetup& setup);

}  // namespace vem::bench
