#include "client/mqtt_transport.h"

#include <mosquitto.h>
#include <mqtt_protocol.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <condition_variable>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "util/mosquitto_client.h"
#include "client/mqtt_url.h"
#include "client/server_message_decoder.h"
#include "proto/stream_protocol.h"
#include "util/backoff.h"

namespace vem::client {
namespace {

using Clock = std::chrono::steady_clock;

constexpr int kKeepAliveS = 10;    // the broker drops a silent client after 1.5 times this
constexpr int kLoopWakeMs = 1000;  // the loop's longest wait (publish() and stop() also wake it)
constexpr std::chrono::milliseconds kGoodbyeLimit{1000};  // stop()'s wait for DISCONNECT to go out
constexpr std::size_t kMaxLoggedRefusals = 64;  // distinct refusal sentences logged, then silence

struct Topics {
  explicit Topics(const util::MqttUrl& url, const std::string& clientId)
      : hello(cameraTopic(url, "hello")),
        lights(cameraTopic(url, "lights")),
        status(cameraTopic(url, "status")),
        cubemap(cameraTopic(url, "cubemap")),
        control(cameraTopic(url, "control")),
        reply(cameraTopic(url, "reply/" + clientId)) {}
  std::string hello, lights, status, cubemap, control, reply;
};

// How one connection ended.
struct SessionEnd {
  std::string reason;
  bool established = false;  // it reached Connected
  bool fatal = false;        // do not retry
};

// The correlation data of a request: its id's 8 bytes, most significant first.
std::array<unsigned char, 8> correlationData(std::uint64_t requestId) {
  std::array<unsigned char, 8> bytes{};
  for (int i = 7; i >= 0; --i, requestId >>= 8) bytes[std::size_t(i)] = requestId & 0xffU;
  return bytes;
}

class MqttTransport final : public StreamTransport {
 public:
  MqttTransport(const StreamClientOptions& options, ClientState& state, util::MqttUrl url,
                util::MosquittoClient client)
      : options_(options),
        state_(state),
        url_(std::move(url)),
        client_(std::move(client)),
        topics_(url_, client_.id) {}
  ~MqttTransport() override { stop(); }
  MqttTransport(const MqttTransport&) = delete;
  MqttTransport& operator=(const MqttTransport&) = delete;

  void start();
  void stop() override;
  std::future<ControlResult> sendControl(const stream::Control& control) override;

 private:
  // What the callbacks learn about the current connection (network thread only).
  struct Session {
    bool connected = false;                                  // CONNACK success
    bool established = false;                                // both SUBACKs: Connected
    std::map<int, std::vector<std::string>> awaitedSubacks;  // by message id, their topics
    bool ended = false;                                      // a callback ended it: reason, fatal
    std::string reason;
    bool fatal = false;
    int disconnectCode = MOSQ_ERR_SUCCESS;
  };

  mosquitto* mosq() const { return client_.handle.get(); }

  // ---- network thread
  void run();
  SessionEnd connectOnce(bool first);
  std::string endReason(int loopCode, int loopErrno) const;
  void closeConnection();
  void waitBackoff(std::chrono::milliseconds delay);
  void subscribe();
  void subscribeTo(const std::vector<std::string>& topics, int qos);
  void endSession(std::string reason, bool fatal);

  // ---- libmosquitto's callbacks (network thread)
  void onConnect(int reasonCode);
  void onDisconnect(int code) { session_.disconnectCode = code; }
  void onSubscribe(int mid, int count, const int* granted);
  void onMessage(const mosquitto_message& message);
  void onPublish(int mid, int reasonCode);
  void onLog(int level, const char* text);
  void handle(std::string_view topic, DecodeResult decoded);
  void logRefusal(std::string_view topic, const std::string& why);

  // ---- controls (any thread)
  void settleControl(std::uint64_t requestId, int reasonCode);
  void forgetControls();

  const StreamClientOptions& options_;
  ClientState& state_;
  const util::MqttUrl url_;
  util::MosquittoClient client_;
  const Topics topics_;
  std::thread thread_;
  bool stopped_ = false;  // stop() ran (caller's thread)

  std::mutex wakeMutex_;
  std::condition_variable wake_;  // the backoff's wait, cut short by stop()
  std::atomic<bool> stopping_{false};

  Session session_;
  std::set<std::string> loggedRefusals_;

  mutable std::mutex logMutex_;
  std::string firstLoggedError_;  // of the current attempt (libmosquitto logs from any thread)

  // The published controls awaiting their PUBACK, by message id, and the PUBACKs that arrived
  // before sendControl() learnt its message id.
  std::mutex controlsMutex_;
  std::map<int, std::uint64_t> controlsByMid_;
  std::map<int, int> earlyPubacks_;
};

void MqttTransport::start() {
  mosquitto* m = mosq();
  mosquitto_user_data_set(m, this);
  mosquitto_threaded_set(m, true);  // publish() from the caller's thread only queues and wakes
  mosquitto_connect_v5_callback_set(
      m, [](mosquitto*, void* self, int rc, int, const mosquitto_property*) {
        static_cast<MqttTransport*>(self)->onConnect(rc);
      });
  mosquitto_disconnect_v5_callback_set(
      m, [](mosquitto*, void* self, int rc, const mosquitto_property*) {
        static_cast<MqttTransport*>(self)->onDisconnect(rc);
      });
  mosquitto_subscribe_v5_callback_set(m, [](mosquitto*, void* self, int mid, int count,
                                            const int* granted, const mosquitto_property*) {
    static_cast<MqttTransport*>(self)->onSubscribe(mid, count, granted);
  });
  mosquitto_message_v5_callback_set(
      m, [](mosquitto*, void* self, const mosquitto_message* message, const mosquitto_property*) {
        static_cast<MqttTransport*>(self)->onMessage(*message);
      });
  mosquitto_publish_v5_callback_set(
      m, [](mosquitto*, void* self, int mid, int rc, const mosquitto_property*) {
        static_cast<MqttTransport*>(self)->onPublish(mid, rc);
      });
  mosquitto_log_callback_set(m, [](mosquitto*, void* self, int level, const char* text) {
    static_cast<MqttTransport*>(self)->onLog(level, text);
  });
  thread_ = std::thread([this] { run(); });
}

void MqttTransport::stop() {
  if (stopped_) return;
  stopped_ = true;
  {
    std::lock_guard lock(wakeMutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  // Wakes the loop at once (libmosquitto's way for another thread); the network thread then says
  // goodbye itself, bounded by kGoodbyeLimit.
  mosquitto_disconnect(mosq());
  if (thread_.joinable()) thread_.join();
}

void MqttTransport::run() {
  util::Backoff backoff(options_.initialBackoff, options_.maxBackoff);
  for (bool first = true; !stopping_; first = false) {
    state_.setState(ConnectionState::Connecting, "");
    const SessionEnd end = connectOnce(first);
    if (stopping_) break;
    // The state changes before the pending controls fail: a control accepted while Connected is
    // failed below, any later one is refused at once (ClientState::addPendingControl).
    if (end.fatal) {
      state_.setState(ConnectionState::Refused, end.reason);
      state_.failPendingControls("the client was refused before the daemon replied");
      forgetControls();
      break;
    }
    if (end.established) backoff.reset();
    const std::chrono::milliseconds delay = backoff.next();
    state_.setState(ConnectionState::Waiting, end.reason);
    state_.failPendingControls("the connection to the broker ended before the daemon replied");
    forgetControls();
    waitBackoff(delay);
  }
}

SessionEnd MqttTransport::connectOnce(bool first) {
  session_ = Session{};
  {
    std::lock_guard lock(logMutex_);
    firstLoggedError_.clear();
  }
  errno = 0;
  // Resolving and the TCP connection run here; the TLS handshake, CONNECT and CONNACK in the loop.
  const int rc = first ? mosquitto_connect_bind_async(mosq(), url_.host.c_str(), url_.port,
                                                      kKeepAliveS, nullptr)
                       : mosquitto_reconnect_async(mosq());
  const int connectErrno = errno;
  if (rc != MOSQ_ERR_SUCCESS) {
    // Invalid arguments before any address was kept: no later attempt can do better.
    const bool fatal = first && (rc == MOSQ_ERR_INVAL || rc == MOSQ_ERR_NOMEM);
    return {endReason(rc, connectErrno), false, fatal};
  }
  const Clock::time_point deadline = Clock::now() + options_.connectTimeout;
  int loopCode = MOSQ_ERR_SUCCESS;
  int loopErrno = 0;
  while (true) {
    int waitMs = kLoopWakeMs;
    if (!session_.established) {
      const auto left = std::chrono::ceil<std::chrono::milliseconds>(deadline - Clock::now());
      waitMs = int(std::clamp<std::int64_t>(left.count(), 0, kLoopWakeMs));
    }
    errno = 0;
    loopCode = mosquitto_loop(mosq(), waitMs, 1);
    loopErrno = errno;
    if (stopping_) {
      closeConnection();
      return {};
    }
    if (session_.ended || loopCode != MOSQ_ERR_SUCCESS) break;
    if (!session_.established && Clock::now() >= deadline) {
      endSession(fmt::format("the connection to the broker {} failed: no answer within {} ms",
                             brokerHostPort(url_), options_.connectTimeout.count()),
                 false);
      break;
    }
  }
  if (session_.ended) closeConnection();  // this client's decision: say goodbye
  const std::string reason = session_.ended ? session_.reason : endReason(loopCode, loopErrno);
  return {reason, session_.established, session_.fatal};
}

// The sentence for a connection that failed (before CONNACK) or was lost (after it).
std::string MqttTransport::endReason(int loopCode, int loopErrno) const {
  std::string logged;
  {
    std::lock_guard lock(logMutex_);
    logged = firstLoggedError_;
  }
  const int code = session_.disconnectCode;
  if (session_.connected) {
    if (code >= MQTT_RC_UNSPECIFIED) {  // the broker's DISCONNECT and its reason
      return fmt::format("the broker {} ended the connection: {}", brokerHostPort(url_),
                         util::brokerReasonText(code));
    }
    if (loopCode == MOSQ_ERR_CONN_LOST || loopCode == MOSQ_ERR_SUCCESS) {
      return fmt::format("the connection to the broker {} was lost", brokerHostPort(url_));
    }
    return fmt::format("the connection to the broker {} was lost ({})", brokerHostPort(url_),
                       util::mosquittoFailureText(loopCode, loopErrno, logged));
  }
  return fmt::format("the connection to the broker {} failed: {}", brokerHostPort(url_),
                     util::mosquittoFailureText(loopCode, loopErrno, logged));
}

// DISCONNECT, then the loop until the socket closes (bounded): the broker sees a client that left.
void MqttTransport::closeConnection() {
  if (mosquitto_socket(mosq()) == -1) return;
  mosquitto_disconnect(mosq());  // again: stop()'s may have come between two connections
  const Clock::time_point deadline = Clock::now() + kGoodbyeLimit;
  while (mosquitto_socket(mosq()) != -1 && Clock::now() < deadline) {
    if (mosquitto_loop(mosq(), 100, 1) != MOSQ_ERR_SUCCESS) break;
  }
}

void MqttTransport::waitBackoff(std::chrono::milliseconds delay) {
  std::unique_lock lock(wakeMutex_);
  wake_.wait_for(lock, delay, [this] { return stopping_.load(); });
}

void MqttTransport::endSession(std::string reason, bool fatal) {
  if (session_.ended) return;
  session_.ended = true;
  session_.reason = std::move(reason);
  session_.fatal = fatal;
}

void MqttTransport::onConnect(int reasonCode) {
  if (reasonCode != MQTT_RC_SUCCESS) {
    const bool forGood =
        reasonCode == MQTT_RC_BAD_USERNAME_OR_PASSWORD || reasonCode == MQTT_RC_NOT_AUTHORIZED;
    endSession(fmt::format("the broker {} refused the connection: {}", brokerHostPort(url_),
                           util::brokerReasonText(reasonCode)),
               forGood);
    return;
  }
  session_.connected = true;
  subscribe();
}

void MqttTransport::subscribe() {
  std::vector<std::string> data{topics_.hello, topics_.status};
  if (options_.subscription.lights) data.push_back(topics_.lights);
  if (options_.subscription.cubemapRateHz > 0.0) data.push_back(topics_.cubemap);
  subscribeTo(data, 0);
  subscribeTo({topics_.reply}, 1);
}

void MqttTransport::subscribeTo(const std::vector<std::string>& topics, int qos) {
  std::vector<char*> names;
  for (const std::string& topic : topics) names.push_back(const_cast<char*>(topic.c_str()));
  int mid = 0;
  const int rc =
      mosquitto_subscribe_multiple(mosq(), &mid, int(names.size()), names.data(), qos, 0, nullptr);
  if (rc != MOSQ_ERR_SUCCESS) {
    endSession(fmt::format("cannot subscribe to {} at the broker {}: {}", topics.front(),
                           brokerHostPort(url_), util::mosquittoFailureText(rc, errno, "")),
               false);
    return;
  }
  session_.awaitedSubacks.emplace(mid, topics);
}

void MqttTransport::onSubscribe(int mid, int count, const int* granted) {
  const auto it = session_.awaitedSubacks.find(mid);
  if (it == session_.awaitedSubacks.end()) return;
  for (int i = 0; i < count && std::size_t(i) < it->second.size(); ++i) {
    if (granted[i] >= MQTT_RC_UNSPECIFIED) {
      logRefusal(it->second[std::size_t(i)],
                 fmt::format("the broker refused the subscription to {}: {}",
                             it->second[std::size_t(i)], util::brokerReasonText(granted[i])));
    }
  }
  session_.awaitedSubacks.erase(it);
  if (session_.awaitedSubacks.empty() && !session_.established && !session_.ended) {
    session_.established = true;
    state_.countConnection();
    state_.setState(ConnectionState::Connected, "");
  }
}

void MqttTransport::onMessage(const mosquitto_message& message) {
  if (session_.ended || message.payloadlen <= 0) return;  // empty: a retained message cleared
  const std::string_view bytes(static_cast<const char*>(message.payload),
                               std::size_t(message.payloadlen));
  handle(message.topic, decodeServerMessage(bytes));
}

void MqttTransport::handle(std::string_view topic, DecodeResult decoded) {
  if (!decoded.ok()) {
    state_.countDecodeError();
    if (decoded.unsupportedMajor) {
      endSession(decoded.error, true);
    } else {
      logRefusal(decoded.error,
                 fmt::format("the payload on {} is refused: {}", topic, decoded.error));
    }
    return;
  }
  std::visit(
      [this](auto& event) {
        using Event = std::decay_t<decltype(event)>;
        if constexpr (std::is_same_v<Event, Hello>) state_.keepHello(std::move(event));
        if constexpr (std::is_same_v<Event, LightFrame>) state_.onLightFrame(std::move(event));
        if constexpr (std::is_same_v<Event, EnvironmentFrame>) {
          state_.onEnvironmentFrame(std::move(event));
        }
        if constexpr (std::is_same_v<Event, Status>) state_.onStatus(std::move(event));
        if constexpr (std::is_same_v<Event, ControlReply>) state_.onControlReply(std::move(event));
      },
      decoded.event);
}

// One warning per distinct `key` (a refusal's reason), up to kMaxLoggedRefusals of them.
void MqttTransport::logRefusal(std::string_view key, const std::string& sentence) {
  if (loggedRefusals_.size() >= kMaxLoggedRefusals) return;
  if (!loggedRefusals_.emplace(key).second) return;
  spdlog::warn("stream {}: {}", options_.url, sentence);
}

void MqttTransport::onLog(int level, const char* text) {
  if (level != MOSQ_LOG_ERR) return;
  std::lock_guard lock(logMutex_);
  if (firstLoggedError_.empty()) firstLoggedError_ = text;
}

std::future<ControlResult> MqttTransport::sendControl(const stream::Control& control) {
  std::promise<ControlResult> promise;
  std::future<ControlResult> future = promise.get_future();
  const std::optional<std::uint64_t> id = state_.addPendingControl(
      std::move(promise), "the client is not connected to the broker", true);
  if (!id) return future;
  stream::ClientMessage message;
  message.set_protocol_major(stream::kProtocolMajor);
  message.set_protocol_minor(stream::kProtocolMinor);
  message.set_request_id(*id);
  *message.mutable_control() = control;
  const std::string bytes = message.SerializeAsString();
  const std::array<unsigned char, 8> correlation = correlationData(*id);
  mosquitto_property* properties = nullptr;
  mosquitto_property_add_string(&properties, MQTT_PROP_RESPONSE_TOPIC, topics_.reply.c_str());
  mosquitto_property_add_binary(&properties, MQTT_PROP_CORRELATION_DATA, correlation.data(),
                                std::uint16_t(correlation.size()));
  int mid = 0;
  errno = 0;
  const int rc = mosquitto_publish_v5(mosq(), &mid, topics_.control.c_str(), int(bytes.size()),
                                      bytes.data(), 1, false, properties);
  const int publishErrno = errno;
  mosquitto_property_free_all(&properties);
  if (rc != MOSQ_ERR_SUCCESS) {
    state_.failPendingControl(*id, fmt::format("the control message could not be sent: {}",
                                               util::mosquittoFailureText(rc, publishErrno, "")));
    return future;
  }
  std::optional<int> earlyPuback;
  {
    std::lock_guard lock(controlsMutex_);
    if (const auto it = earlyPubacks_.find(mid); it != earlyPubacks_.end()) {
      earlyPuback = it->second;
      earlyPubacks_.erase(it);
    } else {
      controlsByMid_[mid] = *id;
    }
  }
  if (earlyPuback) settleControl(*id, *earlyPuback);
  return future;
}

void MqttTransport::onPublish(int mid, int reasonCode) {
  std::optional<std::uint64_t> requestId;
  {
    std::lock_guard lock(controlsMutex_);
    if (const auto it = controlsByMid_.find(mid); it != controlsByMid_.end()) {
      requestId = it->second;
      controlsByMid_.erase(it);
    } else {
      earlyPubacks_[mid] = reasonCode;  // sendControl() has not recorded its message id yet
    }
  }
  if (requestId) settleControl(*requestId, reasonCode);
}

// A PUBACK of 128 and above is the broker's refusal; "no matching subscribers" (16) means no vemd
// listens on the control topic, so no reply will come; any other accepts the control (its reply
// comes on the reply topic).
void MqttTransport::settleControl(std::uint64_t requestId, int reasonCode) {
  if (reasonCode == MQTT_RC_NO_MATCHING_SUBSCRIBERS) {
    state_.failPendingControl(
        requestId, fmt::format("no daemon listens on {}: the broker found no matching subscribers",
                               topics_.control));
  } else if (reasonCode >= MQTT_RC_UNSPECIFIED) {
    state_.failPendingControl(requestId, fmt::format("the broker refused the control message: {}",
                                                     util::brokerReasonText(reasonCode)));
  }
}

void MqttTransport::forgetControls() {
  std::lock_guard lock(controlsMutex_);
  controlsByMid_.clear();
  earlyPubacks_.clear();
}

}  // namespace

std::expected<std::unique_ptr<StreamTransport>, std::string> startMqttTransport(
    const StreamClientOptions& options, ClientState& state) {
  auto url = parseMqttCameraUrl(options.url);
  if (!url) return std::unexpected(url.error());
  const util::MqttSecurity security{options.username, options.password, options.caFile, options.certFile,
                              options.keyFile};
  // The callbacks' userdata is set once the transport exists (start()).
  auto client = util::newMosquittoClient(*url, security, nullptr);
  if (!client) return std::unexpected(client.error());
  auto transport =
      std::make_unique<MqttTransport>(options, state, std::move(*url), std::move(*client));
  transport->start();
  return transport;
}

}  // namespace vem::client
