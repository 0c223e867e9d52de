#include "stream/mqtt_publisher.h"

#include <mosquitto.h>
#include <mqtt_protocol.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <condition_variable>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <filesystem>
#include <map>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>
#include <variant>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "proto/stream_protocol.h"
#include "stream/client_message_handler.h"
#include "stream/cubemap_pacing.h"
#include "stream/frame_encoding.h"
#include "stream/thread_niceness.h"
#include "util/backoff.h"
#include "util/drop_oldest_queue.h"
#include "util/mosquitto_client.h"
#include "util/mqtt_url.h"
#include "util/printable.h"

namespace vem::stream {

namespace {

constexpr int kNetworkLoopTimeoutMs = 200;  // how often the network thread looks at `stopping`
constexpr std::chrono::milliseconds kGoodbyeLimit{1000};

SharedBytes shared(ServerMessage message) {
  return std::make_shared<const std::string>(serialize(std::move(message)));
}

// One message for the sender thread: where it goes and how.
struct Outgoing {
  std::string topic;
  SharedBytes payload;
  int qos = 0;
  bool retain = false;
  std::string correlation;  // MQTT 5 correlation data of a reply ("": none)
};

// Where the reply to one control request goes.
struct ReplyRoute {
  std::string responseTopic;  // "": the request named none (the reply is dropped)
  std::string correlation;
};

}  // namespace

class MqttPublisher::Impl {
 public:
  explicit Impl(MqttPublisherOptions o)
      : options(std::move(o)),
        base(options.prefix + "/" + options.cameraId + "/"),
        queue(options.queueMessages) {}

  // ---- configuration
  MqttPublisherOptions options;
  std::string base;  // "PREFIX/CAMERA/"
  util::MosquittoPtr handle;
  mosquitto* client = nullptr;  // handle's
  SharedBytes helloBytes;
  std::string offlineBytes;  // the will's payload

  // ---- the processing thread's side
  util::DropOldestQueue<Outgoing> queue;
  CubemapPacing cubemapPacing;  // under `mutex`

  // ---- shared, under `mutex`
  mutable std::mutex mutex;
  std::condition_variable changed;  // connected, inFlight, stopping
  bool stopping = false;
  bool connected = false;
  std::size_t inFlight = 0;
  SharedBytes lastStatus;
  MqttCounters counters;
  std::uint64_t droppedWithConnection = 0;
  std::vector<PendingControl> pending;
  std::map<std::uint64_t, ReplyRoute> routes;
  std::uint64_t nextRoute = 1;
  std::string lastLoggedProblem;

  std::thread network;
  std::thread sender;

  [[nodiscard]] std::string topic(const std::string& kind) const { return base + kind; }

  // Hands one message to libmosquitto (any thread; libmosquitto's own lock covers the call).
  // False when it was not taken (no connection).
  bool publishNow(const Outgoing& out) {
    mosquitto_property* properties = nullptr;
    if (!out.correlation.empty()) {
      mosquitto_property_add_binary(&properties, MQTT_PROP_CORRELATION_DATA,
                                    out.correlation.data(),
                                    std::uint16_t(std::min<std::size_t>(out.correlation.size(),
                                                                        65535)));
    }
    int mid = 0;
    const int rc = mosquitto_publish_v5(client, &mid, out.topic.c_str(), int(out.payload->size()),
                                        out.payload->data(), out.qos, out.retain, properties);
    mosquitto_property_free_all(&properties);
    std::lock_guard lock(mutex);
    if (rc != MOSQ_ERR_SUCCESS) {
      ++counters.dropped;
      return false;
    }
    ++counters.published;
    ++inFlight;
    return true;
  }

  void enqueue(Outgoing out) {
    {
      std::lock_guard lock(mutex);
      ++counters.queued;
    }
    // The evicted message (the oldest) is dropped; the queue counts it.
    (void)queue.push(std::move(out));
  }

  // ---- libmosquitto's callbacks (the network thread)
  void onConnect(int reasonCode) {
    if (reasonCode != 0) {
      noteProblem(fmt::format("the MQTT broker {}:{} refused vemd: {}", options.host, options.port,
                              util::brokerReasonText(reasonCode)));
      std::lock_guard lock(mutex);
      ++counters.connectFailures;
      return;
    }
    mosquitto_subscribe_v5(client, nullptr, topic("control").c_str(), 1, 0, nullptr);
    SharedBytes status;
    {
      std::lock_guard lock(mutex);
      connected = true;
      inFlight = 0;
      ++counters.connects;
      counters.connected = true;
      status = lastStatus;
      lastLoggedProblem.clear();
    }
    spdlog::info("mqtt: connected to {}:{}, publishing under {}", options.host, options.port,
                 base);
    // Hello and the newest status first: a new subscriber sees the camera at once.
    publishNow({topic("hello"), helloBytes, 0, true, {}});
    if (status) publishNow({topic("status"), status, 0, true, {}});
    changed.notify_all();
  }

  void onDisconnect(int reasonCode) {
    bool wasConnected = false;
    {
      std::lock_guard lock(mutex);
      wasConnected = connected;
      connected = false;
      counters.connected = false;
      // What libmosquitto still held for the old connection is gone with it.
      if (!stopping) counters.dropped += inFlight;
      inFlight = 0;
      if (stopping) return;
      ++counters.connectFailures;
    }
    const std::string why =
        reasonCode == 0 ? std::string("closed") : util::mosquittoFailureText(reasonCode, errno, "");
    noteProblem(wasConnected ? fmt::format("the connection to the MQTT broker {}:{} was lost ({})",
                                           options.host, options.port, why)
                             : fmt::format("cannot reach the MQTT broker {}:{} ({})", options.host,
                                           options.port, why));
    changed.notify_all();
  }

  void onPublished() {
    {
      std::lock_guard lock(mutex);
      if (inFlight > 0) --inFlight;
      ++counters.written;
    }
    changed.notify_all();
  }

  void onMessage(const mosquitto_message& message, const mosquitto_property* properties) {
    if (topic("control") != message.topic) return;
    ReplyRoute route;
    char* responseTopic = nullptr;
    if (mosquitto_property_read_string(properties, MQTT_PROP_RESPONSE_TOPIC, &responseTopic,
                                       false) != nullptr) {
      route.responseTopic = responseTopic;
      std::free(responseTopic);  // NOLINT(cppcoreguidelines-no-malloc): libmosquitto's malloc
    }
    void* correlation = nullptr;
    std::uint16_t correlationBytes = 0;
    if (mosquitto_property_read_binary(properties, MQTT_PROP_CORRELATION_DATA, &correlation,
                                       &correlationBytes, false) != nullptr) {
      route.correlation.assign(static_cast<const char*>(correlation), correlationBytes);
      std::free(correlation);  // NOLINT(cppcoreguidelines-no-malloc)
    }
    if (std::uint64_t(message.payloadlen) > kMaxClientMessageBytes) {
      refuse(route, 0,
             fmt::format("a control message of at most {} bytes was expected, not {}",
                         kMaxClientMessageBytes, message.payloadlen));
      return;
    }
    const std::string_view bytes(static_cast<const char*>(message.payload),
                                 std::size_t(message.payloadlen));
    // The broker's ACL decided who may publish here: an authorised client's message.
    const ClientAction action = handleClientMessage(bytes, true);
    if (const auto* control = std::get_if<ControlAction>(&action)) {
      if (!takeControl(*control, route)) {
        refuse(route, control->requestId, "too many control requests are waiting; try again");
      }
    } else if (const auto* reply = std::get_if<ReplyAction>(&action)) {
      refuse(route, reply->reply.request_id(), reply->reply.message());
    } else if (const auto* subscribe = std::get_if<SubscribeAction>(&action)) {
      refuse(route, subscribe->requestId,
             "over MQTT a client subscribes at the broker, to the topics of docs/protocol.md");
    } else if (const auto* close = std::get_if<CloseAction>(&action)) {
      refuse(route, 0, close->reason);
    }
  }

  // Hands the request to the processing thread; false when too many wait already.
  bool takeControl(const ControlAction& control, const ReplyRoute& route) {
    std::lock_guard lock(mutex);
    if (pending.size() >= options.maxPendingControls) return false;
    const std::uint64_t id = nextRoute++;
    routes.emplace(id, route);
    pending.push_back({id, control.requestId, control.command});
    ++counters.controlsReceived;
    return true;
  }

  void refuse(const ReplyRoute& route, std::uint64_t requestId, const std::string& why) {
    {
      std::lock_guard lock(mutex);
      ++counters.controlsRefused;
    }
    ControlReply reply;
    reply.set_request_id(requestId);
    reply.set_ok(false);
    reply.set_message(why);
    sendReply(route, reply);
  }

  void sendReply(const ReplyRoute& route, const ControlReply& reply) {
    if (route.responseTopic.empty()) {
      std::lock_guard lock(mutex);
      ++counters.repliesUnrouted;
      return;
    }
    ServerMessage message;
    *message.mutable_reply() = reply;
    enqueue({route.responseTopic, shared(std::move(message)), 1, false, route.correlation});
  }

  // One log line per distinct problem: a broker that stays down is not logged at every retry.
  void noteProblem(const std::string& problem) {
    {
      std::lock_guard lock(mutex);
      if (problem == lastLoggedProblem) return;
      lastLoggedProblem = problem;
    }
    spdlog::warn("mqtt: {}; retrying (capture goes on, messages meanwhile are dropped)",
                 util::printable(problem));
  }

  // ---- threads
  void networkLoop() {
    (void)setThisThreadNice(kIoThreadNice);
    util::Backoff backoff(options.reconnectMin, options.reconnectMax);
    bool first = true;
    while (!isStopping()) {
      // Asynchronous: a broker that does not answer cannot hold up vemd's stop.
      const int rc = first ? mosquitto_connect_async(client, options.host.c_str(), options.port,
                                                     options.keepAliveS)
                           : mosquitto_reconnect_async(client);
      first = false;
      if (rc == MOSQ_ERR_SUCCESS) {
        int loop = MOSQ_ERR_SUCCESS;
        while (loop == MOSQ_ERR_SUCCESS) {
          loop = mosquitto_loop(client, kNetworkLoopTimeoutMs, 1);
          if (isStopping() && !isConnected()) break;
        }
        if (isStopping()) break;
        if (wasEverConnectedSince()) backoff.reset();
      } else {
        std::lock_guard lock(mutex);
        ++counters.connectFailures;
      }
      if (rc != MOSQ_ERR_SUCCESS) {
        noteProblem(fmt::format("cannot reach the MQTT broker {}:{}: {}", options.host,
                                options.port,
                                util::mosquittoFailureText(rc, errno, "")));
      }
      const std::chrono::milliseconds delay = backoff.next();
      std::unique_lock lock(mutex);
      changed.wait_for(lock, delay, [this] { return stopping; });
    }
  }

  // A connection was accepted since the last call (the backoff starts again from its minimum).
  bool wasEverConnectedSince() {
    std::lock_guard lock(mutex);
    const bool any = counters.connects > connectsSeen;
    connectsSeen = counters.connects;
    return any;
  }
  std::uint64_t connectsSeen = 0;

  bool isStopping() const {
    std::lock_guard lock(mutex);
    return stopping;
  }
  bool isConnected() const {
    std::lock_guard lock(mutex);
    return connected;
  }

  void senderLoop() {
    (void)setThisThreadNice(kIoThreadNice);
    for (;;) {
      {
        // Take nothing while it could not go out: the queue keeps the newest meanwhile.
        std::unique_lock lock(mutex);
        changed.wait(lock, [this] {
          return stopping || (connected && inFlight < options.maxInFlight);
        });
        if (stopping) return;
      }
      std::optional<Outgoing> out = queue.popFor(std::chrono::milliseconds(kNetworkLoopTimeoutMs));
      if (!out) {
        if (queue.closed()) return;
        continue;
      }
      publishNow(*out);
    }
  }
};

namespace {

MqttPublisher::Impl& implOf(void* object) { return *static_cast<MqttPublisher::Impl*>(object); }

}  // namespace

std::expected<std::unique_ptr<MqttPublisher>, std::string> MqttPublisher::start(
    MqttPublisherOptions options) {
  if (std::string p = util::topicLevelProblem(options.prefix); !p.empty()) {
    return std::unexpected("mqtt.prefix: " + p);
  }
  if (std::string p = util::topicLevelProblem(options.cameraId); !p.empty()) {
    return std::unexpected("mqtt.camera_id: " + p);
  }
  if (options.queueMessages < 1 || options.maxInFlight < 1) {
    return std::unexpected(std::string(
        "mqtt.queue_messages and mqtt.max_in_flight: at least 1 each was expected"));
  }
  if (options.certFile.empty() != options.keyFile.empty()) {
    return std::unexpected(std::string(
        "mqtt.tls_cert and mqtt.tls_key: both or neither were expected (a client certificate "
        "and its key)"));
  }
  for (const auto& [field, path] : {std::pair{"mqtt.tls_ca", options.caFile},
                                    std::pair{"mqtt.tls_cert", options.certFile},
                                    std::pair{"mqtt.tls_key", options.keyFile}}) {
    std::error_code error;
    if (!path.empty() && !std::filesystem::is_regular_file(path, error)) {
      return std::unexpected(fmt::format("{}: {} is not a readable file", field, path));
    }
  }
  if (!options.tls && !(options.caFile.empty() && options.certFile.empty())) {
    return std::unexpected(std::string(
        "mqtt.tls_ca / tls_cert: TLS files were given for a broker without TLS; use mqtts://"));
  }
  if (options.clientId.empty()) options.clientId = "vemd-" + options.cameraId;
  auto impl = std::make_unique<Impl>(std::move(options));
  Impl& i = *impl;
  const MqttPublisherOptions& o = i.options;
  util::MqttUrl broker;
  broker.tls = o.tls;
  broker.host = o.host;
  broker.port = o.port;
  auto created = util::newMosquittoClient(
      broker, util::MqttSecurity{o.username, o.password, o.caFile, o.certFile, o.keyFile}, &i,
      o.clientId);
  if (!created) return std::unexpected("mqtt: " + created.error());
  i.handle = std::move(created->handle);
  i.client = i.handle.get();
  mosquitto_threaded_set(i.client, true);  // the sender thread publishes beside the network's

  Hello hello = o.hello;
  hello.set_control_allowed(false);
  hello.set_max_client_message_bytes(std::uint32_t(kMaxClientMessageBytes));
  ServerMessage helloMessage;
  *helloMessage.mutable_hello() = hello;
  i.helloBytes = shared(std::move(helloMessage));

  ServerMessage offline;
  offline.mutable_status()->set_source(hello.source());
  offline.mutable_status()->set_calibration_id(hello.calibration_id());
  offline.mutable_status()->set_offline(true);
  i.offlineBytes = serialize(std::move(offline));
  const std::string statusTopic = i.topic("status");
  if (int rc = mosquitto_will_set_v5(i.client, statusTopic.c_str(), int(i.offlineBytes.size()),
                                     i.offlineBytes.data(), 1, true, nullptr);
      rc != MOSQ_ERR_SUCCESS) {
    return std::unexpected(fmt::format("mqtt: cannot set the will: {}", mosquitto_strerror(rc)));
  }
  mosquitto_connect_v5_callback_set(
      i.client, [](mosquitto*, void* object, int rc, int /*flags*/, const mosquitto_property*) {
        implOf(object).onConnect(rc);
      });
  mosquitto_disconnect_v5_callback_set(
      i.client, [](mosquitto*, void* object, int rc, const mosquitto_property*) {
        implOf(object).onDisconnect(rc);
      });
  mosquitto_publish_v5_callback_set(
      i.client, [](mosquitto*, void* object, int /*mid*/, int /*rc*/, const mosquitto_property*) {
        implOf(object).onPublished();
      });
  mosquitto_message_v5_callback_set(i.client, [](mosquitto*, void* object,
                                                 const mosquitto_message* message,
                                                 const mosquitto_property* properties) {
    implOf(object).onMessage(*message, properties);
  });
  i.network = std::thread([&i] { i.networkLoop(); });
  i.sender = std::thread([&i] { i.senderLoop(); });
  return std::unique_ptr<MqttPublisher>(new MqttPublisher(std::move(impl)));
}

MqttPublisher::MqttPublisher(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

MqttPublisher::~MqttPublisher() {
  Impl& i = *impl_;
  i.queue.close();
  {
    std::lock_guard lock(i.mutex);
    i.stopping = true;
  }
  i.changed.notify_all();
  if (i.sender.joinable()) i.sender.join();
  // Goodbye: the offline status, then a clean disconnect (no will), each bounded.
  if (i.isConnected()) {
    std::uint64_t writtenBefore = 0;
    {
      std::lock_guard lock(i.mutex);
      writtenBefore = i.counters.written;
    }
    auto offline = std::make_shared<const std::string>(i.offlineBytes);
    if (i.publishNow({i.topic("status"), offline, 1, true, {}})) {
      std::unique_lock lock(i.mutex);
      i.changed.wait_for(lock, kGoodbyeLimit, [&i, writtenBefore] {
        return i.counters.written > writtenBefore || !i.connected;
      });
    }
    mosquitto_disconnect(i.client);
  }
  if (i.network.joinable()) i.network.join();
  const MqttCounters c = counters();
  spdlog::info(
      "mqtt: stopped: {} messages queued, {} published, {} dropped; {} connections, {} lost or "
      "failed; {} control requests, {} refused",
      c.queued, c.published, c.dropped, c.connects,
      c.connectFailures, c.controlsReceived, c.controlsRefused);
  i.handle.reset();
}

void MqttPublisher::publishLights(SharedBytes message) {
  impl_->enqueue({impl_->topic("lights"), std::move(message), 0, true, {}});
}

void MqttPublisher::publishEnvironment(const CubeVariant& variant, SharedBytes message) {
  Impl& i = *impl_;
  if (i.options.cubemapRateHz <= 0.0 || variant != i.options.cube) return;
  const std::int64_t now = std::chrono::duration_cast<std::chrono::nanoseconds>(
                               std::chrono::steady_clock::now().time_since_epoch())
                               .count();
  {
    std::lock_guard lock(i.mutex);
    if (!i.cubemapPacing.admit(now, i.options.cubemapRateHz)) return;
  }
  i.enqueue({i.topic("cubemap"), std::move(message), 0, false, {}});
}

void MqttPublisher::publishStatus(const Status& status) {
  Impl& i = *impl_;
  ServerMessage message;
  Status& s = *message.mutable_status();
  s = status;
  s.set_clients(0);  // the broker knows its subscribers; vemd does not
  s.set_skipped_for_you(0);
  s.set_offline(false);
  s.set_publish_dropped(counters().dropped);
  SharedBytes bytes = shared(std::move(message));
  {
    std::lock_guard lock(i.mutex);
    i.lastStatus = bytes;
  }
  i.enqueue({i.topic("status"), std::move(bytes), 0, true, {}});
}

CubemapDemand MqttPublisher::cubemapDemand() const {
  CubemapDemand demand;
  if (impl_->options.cubemapRateHz > 0.0) {
    demand.variants.push_back({impl_->options.cube, impl_->options.cubemapRateHz});
  }
  return demand;
}

std::vector<PendingControl> MqttPublisher::takeControls() {
  std::lock_guard lock(impl_->mutex);
  return std::exchange(impl_->pending, {});
}

void MqttPublisher::reply(std::uint64_t connection, const ControlReply& reply) {
  ReplyRoute route;
  {
    std::lock_guard lock(impl_->mutex);
    const auto it = impl_->routes.find(connection);
    if (it == impl_->routes.end()) return;
    route = std::move(it->second);
    impl_->routes.erase(it);
  }
  impl_->sendReply(route, reply);
}

MqttCounters MqttPublisher::counters() const {
  MqttCounters c;
  {
    std::lock_guard lock(impl_->mutex);
    c = impl_->counters;
  }
  c.dropped += impl_->queue.counters().dropped;
  return c;
}

std::string MqttPublisher::note() const {
  const MqttCounters c = counters();
  return fmt::format("mqtt {} {}, {} published, {} dropped", url(),
                     c.connected ? "connected" : "not connected", c.published, c.dropped);
}

std::string MqttPublisher::url() const {
  const MqttPublisherOptions& o = impl_->options;
  util::MqttUrl broker;
  broker.tls = o.tls;
  broker.host = o.host;
  broker.port = o.port;
  return broker.broker() + "/" + o.prefix + "/" + o.cameraId;
}

std::string MqttPublisher::topic(const std::string& kind) const { return impl_->topic(kind); }

}  // namespace vem::stream
