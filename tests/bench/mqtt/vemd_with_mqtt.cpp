#include "bench/mqtt/vemd_with_mqtt.h"

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <fstream>
#include <vector>

#include <fmt/format.h>

#include "stream_e2e/small_camera.h"

namespace vem::bench {

namespace {

constexpr std::chrono::seconds kStartTimeout{60};

std::string configToml(const VemdMqttSetup& s) {
  std::string toml = fmt::format(
      "version = 1\n[stream]\nlisten = \"127.0.0.1:0\"\nmax_clients = {0}\nmax_handshakes = "
      "{0}\nmax_handshakes_per_address = {0}\n[mqtt]\nurl = \"mqtt://127.0.0.1:{1}\"\n"
      "camera_id = \"{2}\"\n",
      s.maxClients, s.brokerPort, s.cameraId);
  if (s.cubemapRateHz > 0.0) {
    toml += fmt::format("cubemap_rate_hz = {}\ncubemap_face_px = {}\ncubemap_levels = {}\n",
                        s.cubemapRateHz, s.cubemapFacePx, s.cubemapLevels);
  }
  return toml;
}

}  // namespace

std::expected<std::unique_ptr<VemdWithMqtt>, std::string> VemdWithMqtt::start(
    const std::string& vemdPath, const VemdMqttSetup& setup) {
  static std::atomic<int> runs{0};
  std::unique_ptr<VemdWithMqtt> vemd(new VemdWithMqtt());
  vemd->dir_ = std::filesystem::temp_directory_path() /
               fmt::format("vem_mqtt_bench_{}_{}", ::getpid(), runs++);
  std::filesystem::create_directories(vemd->dir_);
  const std::filesystem::path camera = vemd->dir_ / "camera.toml";
  const std::filesystem::path config = vemd->dir_ / "vemd.toml";
  std::ofstream(camera) << e2e::smallCameraToml();
  std::ofstream(config) << configToml(setup);
  const std::vector<std::string> args{"--config",      config.string(),
                                      "--camera",      camera.string(),
                                      "--source",      "synthetic:sky",
                                      "--rate",        fmt::format("{}", setup.rateHz),
                                      "--lights",      std::to_string(setup.lights),
                                      "--stats-every", "0"};
  auto spawned = e2e::VemdProcess::spawn(vemdPath, args);
  if (!spawned) return std::unexpected(spawned.error());
  vemd->process_ = std::move(*spawned);
  const auto port = vemd->process_->waitForPort(kStartTimeout);
  if (!port) return std::unexpected("vemd did not start streaming: " + vemd->stderrText());
  vemd->wsPort_ = *port;
  if (!vemd->process_->waitForStderr("mqtt: connected to", kStartTimeout)) {
    return std::unexpected("vemd did not connect to the broker: " + vemd->stderrText());
  }
  return vemd;
}

VemdWithMqtt::~VemdWithMqtt() {
  if (process_) {
    process_->signal(SIGTERM);
    (void)process_->waitForExit(std::chrono::seconds(30));  // else VemdProcess kills it
  }
  std::error_code ignored;
  std::filesystem::remove_all(dir_, ignored);
}

}  // namespace vem::bench
