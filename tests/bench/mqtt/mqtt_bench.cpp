#include "bench/mqtt/mqtt_bench.h"

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>

#include <fmt/format.h>

#include "bench/measurements.h"
#include "bench/mqtt/mqtt_subscriber_set.h"
#include "bench/mqtt/status_watch.h"
#include "bench/mqtt/vemd_with_mqtt.h"
#include "bench/mqtt/ws_subscriber_set.h"
#include "proto/vem_stream.pb.h"
#include "support/mosquitto_broker.h"

namespace vem::bench {

namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

constexpr auto kSettle = 2s;  // after the last subscriber came, before the window
constexpr std::size_t kSubscriberThreads = 2;
constexpr std::size_t kExtraClients = 16;  // [stream] max_clients beyond the subscribers

std::string topicOf(const std::string& cameraId, const std::string& kind) {
  return "vemcast/" + cameraId + "/" + kind;
}

std::int64_t steadyNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now().time_since_epoch())
      .count();
}

// A broker and the subscriber that reads every camera's Status on it.
struct Broker {
  std::unique_ptr<testing::MosquittoBroker> mosquitto;
  StatusWatch statuses;
  std::unique_ptr<MqttSubscriberSet> statusReader;
};

std::expected<std::unique_ptr<Broker>, std::string> startBroker(bool noDelay) {
  auto broker = std::make_unique<Broker>();
  testing::MosquittoBrokerConfig config;
  if (noDelay) config.extraConfig = "set_tcp_nodelay true";
  auto started = testing::MosquittoBroker::start(config);
  if (!started) return std::unexpected("the broker did not start: " + started.error());
  broker->mosquitto = std::move(*started);
  return broker;
}

std::expected<void, std::string> readStatuses(Broker& broker) {
  MqttSubscriberOptions options;
  options.port = broker.mosquitto->port();
  options.topics = {"vemcast/+/status"};
  options.clientIdPrefix = "vem-mqtt-bench-status";
  options.threads = 1;
  options.onMessage = [&broker](std::size_t, std::string_view topic, std::string_view payload,
                                std::int64_t) { broker.statuses.record(topic, payload); };
  auto reader = MqttSubscriberSet::start(std::move(options));
  if (!reader) return std::unexpected(reader.error());
  broker.statusReader = std::move(*reader);
  return {};
}

// The newest status of `cameraId` that arrived after `afterSteadyNs`, waiting up to 10 s.
std::optional<StatusSample> statusAfter(const StatusWatch& watch, const std::string& cameraId,
                                        std::int64_t afterSteadyNs) {
  const auto deadline = Clock::now() + 10s;
  for (;;) {
    const auto status = watch.latest(cameraId);
    if (status && status->receivedSteadyNs > afterSteadyNs) return status;
    if (Clock::now() > deadline) return std::nullopt;
    std::this_thread::sleep_for(20ms);
  }
}

struct Vemd {
  std::string cameraId;
  std::unique_ptr<VemdWithMqtt> process;
};

// One measuring window: `counting` is on during it; the CPU times and statuses around it.
struct Window {
  double seconds = 0.0;
  std::vector<VemdFigures> vemds;
  double brokerCpuMs = 0.0;
  double benchCpuMs = 0.0;
  double machineBusyMs = 0.0;
};

CpuUse cpuUse(double cpuMs, double seconds, double frames) {
  return {seconds > 0.0 ? cpuMs / (seconds * 1000.0) * 100.0 : 0.0,
          frames > 0.0 ? cpuMs / frames : 0.0};
}

std::expected<Window, std::string> measure(const std::vector<Vemd>& vemds, const Broker& broker,
                                           std::atomic<bool>& counting, double windowS) {
  std::this_thread::sleep_for(kSettle);
  // The statuses: the newest at the window's start (one that came after the settling began) and
  // the first after its end; their difference is what each vemd did over about the window.
  const std::int64_t settledNs = steadyNs() - std::chrono::nanoseconds(kSettle).count() / 2;
  std::vector<StatusSample> before;
  for (const Vemd& vemd : vemds) {
    const auto status = statusAfter(broker.statuses, vemd.cameraId, settledNs);
    if (!status) return std::unexpected("no status from " + vemd.cameraId + " on the broker");
    before.push_back(*status);
  }
  std::vector<double> vemdCpuMs;
  for (const Vemd& vemd : vemds) vemdCpuMs.push_back(processCpuMs(vemd.process->pid()));
  const double brokerCpuMs = processCpuMs(broker.mosquitto->pid());
  const double benchCpuMs = processCpuMs(::getpid());
  const double machineMs = machineBusyMs();
  const auto start = Clock::now();
  counting = true;
  std::this_thread::sleep_for(std::chrono::duration<double>(windowS));
  counting = false;
  Window window;
  window.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  window.brokerCpuMs = processCpuMs(broker.mosquitto->pid()) - brokerCpuMs;
  window.benchCpuMs = processCpuMs(::getpid()) - benchCpuMs;
  window.machineBusyMs = machineBusyMs() - machineMs;
  for (std::size_t v = 0; v < vemds.size(); ++v)
    vemdCpuMs[v] = processCpuMs(vemds[v].process->pid()) - vemdCpuMs[v];
  const std::int64_t endNs = steadyNs();
  for (std::size_t v = 0; v < vemds.size(); ++v) {
    const auto after = statusAfter(broker.statuses, vemds[v].cameraId, endNs);
    if (!after) return std::unexpected("no status from " + vemds[v].cameraId + " after the window");
    const StatusDelta delta = *after - before[v];
    VemdFigures figures;
    figures.cameraId = vemds[v].cameraId;
    figures.processedHz = delta.processedHz();
    figures.processed = std::uint64_t(figures.processedHz * window.seconds + 0.5);
    figures.captureDropped = delta.framesDropped;
    figures.publishDropped = delta.publishDropped;
    figures.cpu = cpuUse(vemdCpuMs[v], window.seconds, figures.processedHz * window.seconds);
    window.vemds.push_back(figures);
  }
  return window;
}

std::expected<Vemd, std::string> startVemd(const std::string& vemdPath, const Broker& broker,
                                           const std::string& cameraId, std::size_t maxClients) {
  VemdMqttSetup setup;
  setup.brokerPort = broker.mosquitto->port();
  setup.cameraId = cameraId;
  setup.maxClients = maxClients;
  auto started = VemdWithMqtt::start(vemdPath, setup);
  if (!started) return std::unexpected(started.error());
  return Vemd{cameraId, std::move(*started)};
}

std::vector<const DeliveryTally*> pointers(const std::vector<DeliveryTally>& tallies,
                                           std::size_t first, std::size_t step) {
  std::vector<const DeliveryTally*> out;
  for (std::size_t i = first; i < tallies.size(); i += step) out.push_back(&tallies[i]);
  return out;
}

}  // namespace

std::expected<FanOutResult, std::string> fanOut(const MqttBenchSetup& setup, FanOutPath path,
                                                std::size_t subscribers, double windowS) {
  auto broker = startBroker(setup.brokerNoDelay);
  if (!broker) return std::unexpected(broker.error());
  std::vector<Vemd> vemds;
  auto vemd = startVemd(setup.vemdPath, **broker, "cam1", subscribers + kExtraClients);
  if (!vemd) return std::unexpected(vemd.error());
  vemds.push_back(std::move(*vemd));
  if (auto reading = readStatuses(**broker); !reading) return std::unexpected(reading.error());

  std::vector<DeliveryTally> tallies(subscribers);
  std::atomic<bool> counting{false};
  std::unique_ptr<MqttSubscriberSet> mqtt;
  std::unique_ptr<WsSubscriberSet> ws;
  if (path == FanOutPath::Mqtt) {
    MqttSubscriberOptions options;
    options.port = (*broker)->mosquitto->port();
    options.topics.assign(subscribers, topicOf("cam1", "lights"));
    options.threads = kSubscriberThreads;
    options.onMessage = [&](std::size_t i, std::string_view, std::string_view payload,
                            std::int64_t receivedNs) {
      tallies[i].record(payload, receivedNs, counting.load());
    };
    auto started = MqttSubscriberSet::start(std::move(options));
    if (!started) return std::unexpected(started.error());
    mqtt = std::move(*started);
  } else {
    WsSubscriberOptions options;
    options.port = vemds.front().process->wsPort();
    options.clients = subscribers;
    options.onMessage = [&](std::size_t i, std::string_view payload, std::int64_t receivedNs) {
      tallies[i].record(payload, receivedNs, counting.load());
    };
    auto started = WsSubscriberSet::start(std::move(options));
    if (!started) return std::unexpected(started.error());
    ws = std::move(*started);
  }
  const auto window = measure(vemds, **broker, counting, windowS);
  if (mqtt) mqtt->stop();
  if (ws) ws->stop();
  if (!window) return std::unexpected(window.error());

  FanOutResult r;
  r.path = path;
  r.subscribers = subscribers;
  r.windowS = window->seconds;
  r.delivery = summarize(pointers(tallies, 0, 1), window->seconds);
  r.lostConnections = mqtt ? mqtt->lost() : ws->lost();
  r.vemd = window->vemds.front();
  r.broker = cpuUse(window->brokerCpuMs, window->seconds, r.vemd.processedHz * window->seconds);
  if (path == FanOutPath::Mqtt && r.delivery.frames > 0) {
    r.brokerUsPerDelivered = window->brokerCpuMs * 1000.0 / double(r.delivery.frames);
  }
  r.benchCpuPercent = cpuUse(window->benchCpuMs, window->seconds, 0.0).percent;
  r.machineBusyPercent = cpuUse(window->machineBusyMs, window->seconds, 0.0).percent;
  return r;
}

std::expected<TwoCamerasResult, std::string> twoCameras(const MqttBenchSetup& setup,
                                                        std::size_t subscribers, double windowS) {
  const std::vector<std::string> cameraIds{"cam1", "cam2"};
  auto broker = startBroker(setup.brokerNoDelay);
  if (!broker) return std::unexpected(broker.error());
  std::vector<Vemd> vemds;
  for (const std::string& id : cameraIds) {
    auto vemd = startVemd(setup.vemdPath, **broker, id, kExtraClients);
    if (!vemd) return std::unexpected(vemd.error());
    vemds.push_back(std::move(*vemd));
  }
  if (auto reading = readStatuses(**broker); !reading) return std::unexpected(reading.error());
  std::vector<DeliveryTally> tallies(subscribers);
  std::atomic<bool> counting{false};
  MqttSubscriberOptions options;
  options.port = (*broker)->mosquitto->port();
  for (std::size_t i = 0; i < subscribers; ++i) {
    options.topics.push_back(topicOf(cameraIds[i % cameraIds.size()], "lights"));
  }
  options.threads = kSubscriberThreads;
  options.onMessage = [&](std::size_t i, std::string_view, std::string_view payload,
                          std::int64_t receivedNs) {
    tallies[i].record(payload, receivedNs, counting.load());
  };
  auto set = MqttSubscriberSet::start(std::move(options));
  if (!set) return std::unexpected(set.error());
  const auto window = measure(vemds, **broker, counting, windowS);
  (*set)->stop();
  if (!window) return std::unexpected(window.error());

  TwoCamerasResult r;
  r.subscribers = subscribers;
  r.windowS = window->seconds;
  r.lostConnections = (*set)->lost();
  std::uint64_t delivered = 0;
  for (std::size_t c = 0; c < cameraIds.size(); ++c) {
    CameraDelivery camera{window->vemds[c],
                          summarize(pointers(tallies, c, cameraIds.size()), window->seconds)};
    delivered += camera.delivery.frames;
    r.cameras.push_back(camera);
  }
  r.brokerCpuPercent = cpuUse(window->brokerCpuMs, window->seconds, 0.0).percent;
  if (delivered > 0) r.brokerUsPerDelivered = window->brokerCpuMs * 1000.0 / double(delivered);
  r.benchCpuPercent = cpuUse(window->benchCpuMs, window->seconds, 0.0).percent;
  r.machineBusyPercent = cpuUse(window->machineBusyMs, window->seconds, 0.0).percent;
  return r;
}

namespace {

// The payloads one subscriber to PREFIX/CAMERA/# saw, per topic kind (the last level); the rate
// of each kind is timed from its second message on (the first may be a retained one of any age).
class PayloadLog {
 public:
  void record(std::string_view topic, std::string_view payload) {
    const std::string kind(topic.substr(topic.rfind('/') + 1));
    std::lock_guard lock(mutex_);
    Kind& k = kinds_[kind];
    k.sizes.push_back(double(payload.size()));
    if (k.sizes.size() > 1) k.arrivals.push_back(Clock::now());  // the first: retained, any age
    if (kind == "cubemap") {
      stream::ServerMessage message;
      if (message.ParseFromArray(payload.data(), int(payload.size())) &&
          message.has_environment()) {
        k.rawBytes.push_back(double(message.environment().raw_bytes()));
        k.levels = message.environment().levels();
        k.facePx = message.environment().face_px();
      }
    }
  }
  [[nodiscard]] std::size_t count(const std::string& kind) const {
    std::lock_guard lock(mutex_);
    const auto it = kinds_.find(kind);
    return it == kinds_.end() ? 0 : it->second.sizes.size();
  }
  // The median size, the rate between the first and the last arrival, and for cube maps the
  // texels before zstd and the levels and face size sent.
  [[nodiscard]] PayloadSize size(const std::string& kind, std::string what) const {
    std::lock_guard lock(mutex_);
    const Kind& k = kinds_.at(kind);
    PayloadSize p{std::move(what), kind, quantile(k.sizes, 0.5), 0.0, quantile(k.rawBytes, 0.5)};
    if (k.arrivals.size() >= 2) {
      const double s =
          std::chrono::duration<double>(k.arrivals.back() - k.arrivals.front()).count();
      if (s > 0.0) p.rateHz = double(k.arrivals.size() - 1) / s;
    }
    if (kind == "cubemap") {
      p.what +=
          fmt::format(" (sent: {} px, {} level{})", k.facePx, k.levels, k.levels == 1 ? "" : "s");
    }
    return p;
  }

 private:
  struct Kind {
    std::vector<double> sizes;
    std::vector<Clock::time_point> arrivals;
    std::vector<double> rawBytes;
    std::uint32_t levels = 0;
    std::uint32_t facePx = 0;
  };
  mutable std::mutex mutex_;
  std::map<std::string, Kind, std::less<>> kinds_;
};

// vemd with `vemd` on a fresh broker until `count` payloads of `kind` came (30 s at most).
std::expected<std::unique_ptr<PayloadLog>, std::string> logPayloads(const MqttBenchSetup& bench,
                                                                    VemdMqttSetup vemd,
                                                                    const std::string& kind,
                                                                    std::size_t count) {
  auto broker = startBroker(bench.brokerNoDelay);
  if (!broker) return std::unexpected(broker.error());
  vemd.brokerPort = (*broker)->mosquitto->port();
  auto process = VemdWithMqtt::start(bench.vemdPath, vemd);
  if (!process) return std::unexpected(process.error());
  auto log = std::make_unique<PayloadLog>();
  MqttSubscriberOptions options;
  options.port = vemd.brokerPort;
  options.topics = {topicOf(vemd.cameraId, "#")};
  options.threads = 1;
  options.onMessage = [&log](std::size_t, std::string_view topic, std::string_view payload,
                             std::int64_t) { log->record(topic, payload); };
  auto reader = MqttSubscriberSet::start(std::move(options));
  if (!reader) return std::unexpected(reader.error());
  const auto deadline = Clock::now() + 30s;
  while (log->count(kind) < count && Clock::now() < deadline) std::this_thread::sleep_for(20ms);
  (*reader)->stop();
  if (log->count(kind) < count) {
    return std::unexpected(fmt::format("only {} {} payloads came in 30 s", log->count(kind), kind));
  }
  return log;
}

}  // namespace

std::expected<std::vector<PayloadSize>, std::string> payloadSizes(const MqttBenchSetup& setup) {
  std::vector<PayloadSize> sizes;
  std::vector<PayloadSize> others;
  for (const std::size_t lights : {64U, 256U, 1024U}) {
    VemdMqttSetup vemd;
    vemd.lights = lights;
    auto log = logPayloads(setup, vemd, "lights", 60);
    if (!log) return std::unexpected(log.error());
    sizes.push_back(
        (*log)->size("lights", fmt::format("light frame, {} lights, clustered (Q = 72)", lights)));
    if (lights == 1024) {
      for (const char* kind : {"status", "hello"}) {
        if ((*log)->count(kind) > 0) others.push_back((*log)->size(kind, kind));
      }
    }
  }
  struct Cube {
    int facePx;
    int levels;
  };
  for (const Cube cube : {Cube{64, 1}, Cube{128, 1}, Cube{128, 8}}) {
    VemdMqttSetup vemd;
    vemd.cubemapRateHz = 5.0;
    vemd.cubemapFacePx = cube.facePx;
    vemd.cubemapLevels = cube.levels;
    auto log = logPayloads(setup, vemd, "cubemap", 10);
    if (!log) return std::unexpected(log.error());
    sizes.push_back(
        (*log)->size("cubemap", fmt::format("cube map {} px, {} level{} at 5 Hz", cube.facePx,
                                            cube.levels, cube.levels == 1 ? "" : "s")));
  }
  sizes.insert(sizes.end(), others.begin(), others.end());
  return sizes;
}

}  // namespace vem::bench
