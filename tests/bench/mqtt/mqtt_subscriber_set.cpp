#include "bench/mqtt/mqtt_subscriber_set.h"

#include <mosquitto.h>
#include <mqtt_protocol.h>
#include <sys/epoll.h>
#include <unistd.h>

#include <array>
#include <mutex>

#include <fmt/format.h>

#include "bench/measurements.h"

namespace vem::bench {

namespace {

constexpr int kWaitMs = 50;                           // how often a thread looks at `stopping`
constexpr std::chrono::milliseconds kMiscEvery{500};  // keep-alive and pending writes
constexpr int kKeepAliveS = 60;

}  // namespace

struct MqttSubscriberSet::Subscriber {
  MqttSubscriberSet* set = nullptr;
  std::size_t index = 0;
  mosquitto* client = nullptr;
  bool alive = false;  // connected and in its thread's epoll set (that thread's to change)
};

MqttSubscriberSet::MqttSubscriberSet(MqttSubscriberOptions options)
    : options_(std::move(options)) {}

std::expected<std::unique_ptr<MqttSubscriberSet>, std::string> MqttSubscriberSet::start(
    MqttSubscriberOptions options) {
  static std::once_flag once;
  std::call_once(once, [] { mosquitto_lib_init(); });
  if (options.threads < 1) options.threads = 1;
  std::unique_ptr<MqttSubscriberSet> set(new MqttSubscriberSet(std::move(options)));
  const MqttSubscriberOptions& o = set->options_;
  for (std::size_t t = 0; t < o.threads; ++t) {
    set->epollFds_.emplace_back(::epoll_create1(EPOLL_CLOEXEC));
    if (!set->epollFds_.back().valid()) return std::unexpected(std::string("epoll_create1 failed"));
  }
  const auto deadline = std::chrono::steady_clock::now() + o.timeout;
  for (std::size_t i = 0; i < o.topics.size(); ++i) {
    auto subscriber = std::make_unique<Subscriber>();
    Subscriber& sub = *subscriber;
    sub.set = set.get();
    sub.index = i;
    const std::string id = fmt::format("{}-{}-{}", o.clientIdPrefix, ::getpid(), i);
    sub.client = mosquitto_new(id.c_str(), true, &sub);
    if (sub.client == nullptr) return std::unexpected("cannot create MQTT client " + id);
    set->subscribers_.push_back(std::move(subscriber));
    mosquitto_int_option(sub.client, MOSQ_OPT_PROTOCOL_VERSION, MQTT_PROTOCOL_V5);
    mosquitto_connect_v5_callback_set(
        sub.client, [](mosquitto* client, void* object, int rc, int, const mosquitto_property*) {
          auto& s = *static_cast<Subscriber*>(object);
          if (rc == 0) {
            mosquitto_subscribe_v5(client, nullptr, s.set->options_.topics[s.index].c_str(), 0, 0,
                                   nullptr);
          }
        });
    mosquitto_subscribe_v5_callback_set(
        sub.client, [](mosquitto*, void* object, int, int, const int*, const mosquitto_property*) {
          ++static_cast<Subscriber*>(object)->set->subscribed_;
        });
    mosquitto_message_v5_callback_set(
        sub.client,
        [](mosquitto*, void* object, const mosquitto_message* message, const mosquitto_property*) {
          const std::int64_t receivedNs = realtimeNs();
          auto& s = *static_cast<Subscriber*>(object);
          s.set->options_.onMessage(s.index, message->topic,
                                    std::string_view(static_cast<const char*>(message->payload),
                                                     std::size_t(message->payloadlen)),
                                    receivedNs);
        });
    // Blocking TCP connect; the CONNECT packet is written here, the rest on the threads, which
    // start once every subscriber is connected (they alone touch a client from then on).
    if (const int rc = mosquitto_connect_bind_v5(sub.client, "127.0.0.1", o.port, kKeepAliveS,
                                                 nullptr, nullptr);
        rc != MOSQ_ERR_SUCCESS) {
      return std::unexpected(fmt::format("MQTT subscriber {} of {} cannot connect to port {}: {}",
                                         i + 1, o.topics.size(), o.port, mosquitto_strerror(rc)));
    }
    sub.alive = true;
    epoll_event event{};
    event.events = EPOLLIN;
    event.data.ptr = &sub;
    const int fd = mosquitto_socket(sub.client);
    if (::epoll_ctl(set->epollFds_[i % o.threads].get(), EPOLL_CTL_ADD, fd, &event) != 0) {
      return std::unexpected("epoll_ctl failed for subscriber " + std::to_string(i));
    }
    if (std::chrono::steady_clock::now() > deadline) break;
  }
  for (std::size_t t = 0; t < o.threads; ++t) {
    set->threads_.emplace_back([&s = *set, t] { s.run(t); });
  }
  while (set->subscribed_.load() < o.topics.size() && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  if (set->subscribed_.load() < o.topics.size()) {
    return std::unexpected(fmt::format("only {} of {} MQTT subscribers subscribed within {} s",
                                       set->subscribed_.load(), o.topics.size(),
                                       o.timeout.count() / 1000));
  }
  return set;
}

void MqttSubscriberSet::lose(Subscriber& subscriber) {
  subscriber.alive = false;
  if (!stopping_.load()) ++lost_;
}

void MqttSubscriberSet::run(std::size_t thread) {
  const int epollFd = epollFds_[thread].get();
  std::array<epoll_event, 64> events{};
  auto nextMisc = std::chrono::steady_clock::now() + kMiscEvery;
  while (!stopping_.load()) {
    const int n = ::epoll_wait(epollFd, events.data(), int(events.size()), kWaitMs);
    for (int e = 0; e < n; ++e) {
      Subscriber& sub = *static_cast<Subscriber*>(events[std::size_t(e)].data.ptr);
      if (!sub.alive) continue;
      if (mosquitto_loop_read(sub.client, 1) != MOSQ_ERR_SUCCESS) {
        lose(sub);  // libmosquitto closed the socket, which left the epoll set with it
        continue;
      }
      if (mosquitto_want_write(sub.client)) (void)mosquitto_loop_write(sub.client, 1);
    }
    if (std::chrono::steady_clock::now() < nextMisc) continue;
    nextMisc = std::chrono::steady_clock::now() + kMiscEvery;
    for (std::size_t i = thread; i < subscribers_.size(); i += options_.threads) {
      Subscriber& sub = *subscribers_[i];
      if (!sub.alive) continue;
      if (mosquitto_loop_misc(sub.client) != MOSQ_ERR_SUCCESS) {
        lose(sub);
        continue;
      }
      if (mosquitto_want_write(sub.client)) (void)mosquitto_loop_write(sub.client, 1);
    }
  }
}

void MqttSubscriberSet::stop() {
  if (stopped_) return;
  stopped_ = true;
  stopping_ = true;
  for (std::thread& thread : threads_) thread.join();
  for (const auto& sub : subscribers_) {
    if (sub->alive) (void)mosquitto_disconnect(sub->client);
    mosquitto_destroy(sub->client);
  }
}

MqttSubscriberSet::~MqttSubscriberSet() { stop(); }

}  // namespace vem::bench
