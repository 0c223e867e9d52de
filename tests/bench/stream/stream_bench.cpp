#include "bench/stream/stream_bench.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <thread>

#include <fmt/format.h>

#include "bench/measurements.h"
#include "client/stream_client.h"
#include "recording/recording_reader.h"
#include "stream_e2e/raw_ws_client.h"
#include "stream_e2e/small_camera.h"
#include "stream_e2e/vemd_process.h"

namespace vem::bench {

namespace {

using namespace std::chrono_literals;
using e2e::RawWsClient;
using e2e::VemdProcess;

constexpr auto kStartTimeout = 60s;

// vemd and the scratch folder holding its camera file.
struct RunningVemd {
  std::filesystem::path dir;
  std::unique_ptr<VemdProcess> process;
  std::uint16_t port = 0;
  ~RunningVemd() {
    if (process) {
      process->signal(SIGTERM);
      (void)process->waitForExit(30s);  // else the destructor kills it
    }
    std::error_code ignored;
    std::filesystem::remove_all(dir, ignored);
  }
};

std::expected<std::unique_ptr<RunningVemd>, std::string> startVemd(
    const std::string& vemdPath, const std::string& rate, const std::vector<std::string>& extra) {
  auto running = std::make_unique<RunningVemd>();
  running->dir =
      std::filesystem::temp_directory_path() / fmt::format("vem_stream_bench_{}", ::getpid());
  std::filesystem::create_directories(running->dir);
  const std::filesystem::path camera = running->dir / "camera.toml";
  std::ofstream(camera) << e2e::smallCameraToml();
  std::vector<std::string> args{
      "--camera", camera.string(), "--source", "synthetic:sky",   "--rate",
      rate,       "--stats-every", "0",        "--stream-listen", "127.0.0.1:0"};
  args.insert(args.end(), extra.begin(), extra.end());
  auto spawned = VemdProcess::spawn(vemdPath, args);
  if (!spawned) return std::unexpected(spawned.error());
  running->process = std::move(*spawned);
  const auto port = running->process->waitForPort(kStartTimeout);
  if (!port) {
    return std::unexpected("vemd did not start streaming: " + running->process->stderrText());
  }
  running->port = *port;
  return running;
}

std::expected<std::unique_ptr<client::StreamClient>, std::string> startClient(
    std::uint16_t port, client::StreamClientOptions options) {
  options.url = fmt::format("ws://127.0.0.1:{}", port);
  auto started = client::StreamClient::start(std::move(options));
  if (!started) return std::unexpected(started.error());
  if (!(*started)->waitForState(client::ConnectionState::Connected, kStartTimeout)) {
    return std::unexpected("the StreamClient did not connect: " + (*started)->stateReason());
  }
  return std::move(*started);
}

// The median size of the next `count` messages of `bodyCase` (others skipped), within 30 s.
std::expected<MessageSize, std::string> medianSize(RawWsClient& raw,
                                                   stream::ServerMessage::BodyCase bodyCase,
                                                   std::size_t count, std::string what,
                                                   std::uint32_t* levels = nullptr) {
  std::vector<double> sizes, rawBytes;
  const auto deadline = std::chrono::steady_clock::now() + 30s;
  while (sizes.size() < count) {
    if (std::chrono::steady_clock::now() > deadline) {
      return std::unexpected("too few messages for " + what);
    }
    const auto bytes = raw.readBytes(30s);
    if (!bytes) return std::unexpected("the connection ended while measuring " + what);
    stream::ServerMessage message;
    if (!message.ParseFromString(*bytes) || message.body_case() != bodyCase) continue;
    sizes.push_back(double(bytes->size()));
    if (message.has_environment()) {
      rawBytes.push_back(double(message.environment().raw_bytes()));
      if (levels != nullptr) *levels = message.environment().levels();
    }
  }
  return MessageSize{std::move(what), quantile(sizes, 0.5), quantile(rawBytes, 0.5)};
}

std::expected<MessageSize, std::string> lightFrameSize(const std::string& vemdPath,
                                                       std::size_t lights, bool clustering) {
  std::vector<std::string> extra{"--lights", std::to_string(lights)};
  if (!clustering) extra.insert(extra.end(), {"--cluster", "0"});
  auto vemd = startVemd(vemdPath, "30", extra);
  if (!vemd) return std::unexpected(vemd.error());
  RawWsClient raw;
  if (raw.connect((*vemd)->port) != 0) return std::unexpected("no connection to vemd");
  return medianSize(raw, stream::ServerMessage::kLights, 30,
                    fmt::format("light frame, {} lights, {}", lights,
                                clustering ? "clustered (Q = 72)" : "no clustering"));
}

}  // namespace

std::expected<LatencyResult, std::string> networkLatency(const std::string& vemdPath,
                                                         std::size_t frames, double rateHz) {
  auto vemd = startVemd(vemdPath, fmt::format("{}", rateHz), {});
  if (!vemd) return std::unexpected(vemd.error());
  std::mutex mutex;
  std::vector<double> latenciesMs;
  latenciesMs.reserve(frames);
  client::StreamClientOptions options;
  options.onLightFrame = [&](const client::Received<client::LightFrame>& received) {
    std::lock_guard lock(mutex);
    if (latenciesMs.size() < frames) {
      latenciesMs.push_back(double(received.receivedUnixNs - received.frame.publishUnixNs) * 1e-6);
    }
  };
  auto streamClient = startClient((*vemd)->port, std::move(options));
  if (!streamClient) return std::unexpected(streamClient.error());
  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::duration<double>(2.0 * double(frames) / rateHz + 30.0);
  for (;;) {
    std::this_thread::sleep_for(50ms);
    std::lock_guard lock(mutex);
    if (latenciesMs.size() >= frames) break;
    if (std::chrono::steady_clock::now() > deadline) {
      return std::unexpected(fmt::format("only {} light frames arrived", latenciesMs.size()));
    }
  }
  const std::uint64_t skipped = (*streamClient)->stats().skipped;
  (*streamClient)->stop();
  std::lock_guard lock(mutex);
  return LatencyResult{frames,
                       rateHz,
                       quantile(latenciesMs, 0.5),
                       quantile(latenciesMs, 0.99),
                       *std::ranges::max_element(latenciesMs),
                       skipped};
}

std::expected<std::vector<MessageSize>, std::string> messageSizes(const std::string& vemdPath) {
  std::vector<MessageSize> sizes;
  for (const auto& [lights, clustering] : std::vector<std::pair<std::size_t, bool>>{
           {64, true}, {256, true}, {256, false}, {1024, true}}) {
    auto size = lightFrameSize(vemdPath, lights, clustering);
    if (!size) return std::unexpected(size.error());
    sizes.push_back(*size);
  }
  auto vemd = startVemd(vemdPath, "30", {});
  if (!vemd) return std::unexpected(vemd.error());
  RawWsClient raw;
  if (raw.connect((*vemd)->port) != 0) return std::unexpected("no connection to vemd");
  for (const std::uint32_t facePx : {64U, 128U}) {
    for (const std::uint32_t levels : {1U, 8U}) {
      stream::ClientMessage subscribe;
      subscribe.mutable_subscribe()->set_lights(false);
      subscribe.mutable_subscribe()->set_cubemap_rate_hz(10.0);
      subscribe.mutable_subscribe()->set_cubemap_face_px(facePx);
      subscribe.mutable_subscribe()->set_cubemap_levels(levels);
      if (!raw.send(subscribe, 20s)) return std::unexpected("cannot subscribe to cube maps");
      // The first environment frames may still be of the previous subscription: skip two.
      (void)medianSize(raw, stream::ServerMessage::kEnvironment, 2, "");
      std::uint32_t sentLevels = 0;
      auto size = medianSize(raw, stream::ServerMessage::kEnvironment, 5, "cube map", &sentLevels);
      if (!size) return std::unexpected(size.error());
      size->what = fmt::format("cube map {} px, {} level{} (asked {})", facePx, sentLevels,
                               sentLevels == 1 ? "" : "s", levels);
      sizes.push_back(*size);
    }
  }
  return sizes;
}

std::expected<RateResult, std::string> rateWithClients(const std::string& vemdPath,
                                                       const std::string& rate, std::size_t clients,
                                                       double windowS) {
  auto vemd = startVemd(vemdPath, rate, {});
  if (!vemd) return std::unexpected(vemd.error());
  std::atomic<bool> stop{false};
  std::atomic<std::size_t> connected{0};
  std::vector<std::thread> drains;
  for (std::size_t i = 1; i < clients; ++i) {
    drains.emplace_back([&, port = (*vemd)->port] {
      RawWsClient raw;
      if (raw.connect(port) != 0) return;
      ++connected;
      while (!stop.load() && raw.readBytes(5s)) {
      }
    });
  }
  auto streamClient = startClient((*vemd)->port, {});
  const auto joinDrains = [&] {
    stop = true;
    for (std::thread& drain : drains) drain.join();
  };
  if (!streamClient) {
    joinDrains();
    return std::unexpected(streamClient.error());
  }
  const auto connectDeadline = std::chrono::steady_clock::now() + kStartTimeout;
  while (connected.load() + 1 < clients && std::chrono::steady_clock::now() < connectDeadline) {
    std::this_thread::sleep_for(50ms);
  }
  std::this_thread::sleep_for(2s);  // the Status window then covers every client
  const auto startStatus = (*streamClient)->status();
  const client::ClientStats startStats = (*streamClient)->stats();
  const double startCpuMs = processCpuMs((*vemd)->process->pid());
  std::vector<double> rates;
  const auto windowStart = std::chrono::steady_clock::now();
  const auto windowEnd = windowStart + std::chrono::duration<double>(windowS);
  std::optional<std::uint64_t> lastStatusProcessed;
  while (std::chrono::steady_clock::now() < windowEnd) {
    std::this_thread::sleep_for(100ms);
    const auto status = (*streamClient)->status();
    if (status && status->framesProcessed != lastStatusProcessed) {
      lastStatusProcessed = status->framesProcessed;
      rates.push_back(status->frameRateHz);
    }
  }
  const double elapsedS =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - windowStart).count();
  const client::ClientStats endStats = (*streamClient)->stats();
  const auto endStatus = (*streamClient)->status();
  const double cpuMs = processCpuMs((*vemd)->process->pid()) - startCpuMs;
  const std::size_t allConnected = connected.load() + 1;
  (*streamClient)->stop();
  joinDrains();
  if (allConnected < clients) {
    return std::unexpected(fmt::format("only {} of {} clients connected", allConnected, clients));
  }
  RateResult result;
  result.rate = rate;
  result.clients = clients;
  result.processedHz = quantile(rates, 0.5);
  result.receivedHz = double(endStats.received - startStats.received) / elapsedS;
  result.skipped = endStats.skipped - startStats.skipped;
  if (startStatus && endStatus) {
    result.dropped = endStatus->framesDropped - startStatus->framesDropped;
    const std::uint64_t frames = endStatus->framesProcessed - startStatus->framesProcessed;
    if (frames > 0) result.cpuMsPerFrame = cpuMs / double(frames);
  }
  return result;
}

std::expected<CubemapLoadResult, std::string> rateWithCubemapLoad(const std::string& vemdPath,
                                                                  double rateHz,
                                                                  const CubemapLoad& load,
                                                                  double windowS) {
  const std::string token = "bench-token-0123456789abcdef-0123";
  const auto dir =
      std::filesystem::temp_directory_path() / fmt::format("vem_stream_bench_load_{}", ::getpid());
  std::filesystem::create_directories(dir);
  const auto config = dir / "vemd.toml";
  std::ofstream(config) << "version = 1\n[stream]\ntoken = \"" << token << "\"\n";
  std::filesystem::permissions(
      config, std::filesystem::perms::owner_read | std::filesystem::perms::owner_write);
  const auto recording = dir / "during-load.vem";
  CubemapLoadResult result;
  result.load = load;
  {
    auto vemd = startVemd(vemdPath, fmt::format("{}", rateHz),
                          {"--config", config.string(), "--record", recording.string()});
    if (!vemd) return std::unexpected(vemd.error());
    std::atomic<bool> stop{false};
    std::atomic<std::size_t> subscribed{0};
    std::atomic<std::uint64_t> cubemaps{0};
    std::atomic<std::uint64_t> refused{0};
    std::atomic<bool> counting{false};
    std::vector<std::thread> drains;
    for (std::size_t i = 0; i < load.clients; ++i) {
      drains.emplace_back([&, port = (*vemd)->port] {
        RawWsClient raw;
        e2e::RawConnectOptions options;
        if (load.token) options.token = token;
        if (raw.connect(port, options) != 0) return;
        stream::ClientMessage subscribe;
        subscribe.set_request_id(1);
        subscribe.mutable_subscribe()->set_lights(true);
        subscribe.mutable_subscribe()->set_cubemap_face_px(std::uint32_t(load.facePx));
        subscribe.mutable_subscribe()->set_cubemap_levels(std::uint32_t(load.levels));
        subscribe.mutable_subscribe()->set_cubemap_rate_hz(load.rateHz);
        subscribe.mutable_subscribe()->set_preview(i % 2 == 0);
        if (!raw.send(subscribe, 5s)) return;
        ++subscribed;
        while (!stop.load()) {
          auto bytes = raw.readBytes(5s);
          if (!bytes) break;
          stream::ServerMessage message;
          if (!message.ParseFromString(*bytes)) continue;
          if (message.has_reply() && !message.reply().ok()) ++refused;
          if (message.has_environment() && counting.load()) ++cubemaps;
        }
      });
    }
    auto streamClient = startClient((*vemd)->port, {});
    const auto joinDrains = [&] {
      stop = true;
      for (std::thread& drain : drains) drain.join();
    };
    if (!streamClient) {
      joinDrains();
      return std::unexpected(streamClient.error());
    }
    const auto deadline = std::chrono::steady_clock::now() + kStartTimeout;
    while (subscribed.load() < load.clients && std::chrono::steady_clock::now() < deadline) {
      std::this_thread::sleep_for(50ms);
    }
    std::this_thread::sleep_for(2s);
    const auto startStatus = (*streamClient)->status();
    const double startCpuMs = processCpuMs((*vemd)->process->pid());
    counting = true;
    const auto windowStart = std::chrono::steady_clock::now();
    std::this_thread::sleep_for(std::chrono::duration<double>(windowS));
    counting = false;
    const double elapsedS =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - windowStart).count();
    const auto endStatus = (*streamClient)->status();
    const double cpuMs = processCpuMs((*vemd)->process->pid()) - startCpuMs;
    (*streamClient)->stop();
    joinDrains();
    if (subscribed.load() < load.clients) {
      return std::unexpected(
          fmt::format("only {} of {} clients subscribed", subscribed.load(), load.clients));
    }
    if (startStatus && endStatus) {
      const std::uint64_t frames = endStatus->framesProcessed - startStatus->framesProcessed;
      result.processedHz = double(frames) / elapsedS;
      result.dropped = endStatus->framesDropped - startStatus->framesDropped;
      if (frames > 0) result.cpuMsPerFrame = cpuMs / double(frames);
    }
    result.cubemapsPerS = double(cubemaps.load()) / elapsedS;
    result.refused = refused.load();
    // The whole run's drops, from vemd's final statistics line ("..., N dropped, ...").
    (*vemd)->process->signal(SIGTERM);
    (void)(*vemd)->process->waitForExit(30s);
    const std::string log = (*vemd)->process->stderrText();
    const std::size_t final = log.rfind("final ");
    const std::size_t at = final == std::string::npos ? final : log.find(" dropped", final);
    if (at != std::string::npos) {
      const std::size_t begin = log.rfind(' ', at - 1) + 1;
      result.droppedInRun = std::stoull(log.substr(begin, at - begin));
    }
  }  // vemd has stopped: its recording has its index
  auto reader = recording::RecordingReader::open(recording);
  if (!reader) return std::unexpected("cannot read the recording made under load");
  std::optional<std::uint64_t> last;
  for (;;) {
    auto frame = reader->next();
    if (!frame || !*frame) break;
    ++result.recorded;
    if (last && (*frame)->seq != *last + 1) ++result.recordingGaps;
    last = (*frame)->seq;
  }
  std::error_code ignored;
  std::filesystem::remove_all(dir, ignored);
  return result;
}

}  // namespace vem::bench
