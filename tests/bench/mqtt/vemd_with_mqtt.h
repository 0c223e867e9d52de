// VemdWithMqtt: the real vemd run for the MQTT benchmark: the synthetic sky through the small
// 320 x 256 camera of the end-to-end tests (tests/stream_e2e/small_camera.h, so that rendering
// never bounds the rate), default processing otherwise, with both its WebSocket server on
// 127.0.0.1 (a free port) and [mqtt] publishing to a broker on 127.0.0.1, from a configuration file
// in its own scratch folder. start() returns once vemd streams and is connected to the broker.
// The destructor stops vemd (SIGTERM, then SIGKILL after 30 s) and removes the folder.
#pragma once

#include <sys/types.h>

#include <cstddef>
#include <cstdint>
#include <expected>
#include <filesystem>
#include <memory>
#include <string>

#include "stream_e2e/vemd_process.h"

namespace vem::bench {

struct VemdMqttSetup {
  std::uint16_t brokerPort = 0;
  std::string cameraId = "cam1";
  double rateHz = 30.0;
  std::size_t lights = 1024;
  std::size_t maxClients = 64;  // [stream] max_clients, and the handshake limits with it
  double cubemapRateHz = 0.0;   // [mqtt] cubemap_rate_hz (0: none)
  int cubemapFacePx = 64;
  int cubemapLevels = 1;
};

class VemdWithMqtt {
 public:
  [[nodiscard]] static std::expected<std::unique_ptr<VemdWithMqtt>, std::string> start(
      const std::string& vemdPath, const VemdMqttSetup& setup);
  ~VemdWithMqtt();
  VemdWithMqtt(const VemdWithMqtt&) = delete;
  VemdWithMqtt& operator=(const VemdWithMqtt&) = delete;

  [[nodiscard]] pid_t pid() const { return process_->pid(); }
  [[nodiscard]] std::uint16_t wsPort() const { return wsPort_; }
  [[nodiscard]] std::string stderrText() const { return process_->stderrText(); }

 private:
  VemdWithMqtt() = default;

  std::filesystem::path dir_;
  std::unique_ptr<e2e::VemdProcess> process_;
  std::uint16_t wsPort_ = 0;
};

}  // namespace vem::bench
