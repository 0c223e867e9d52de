#include "support/test_mqtt_publisher.h"

#include <mosquitto.h>
#include <mqtt_protocol.h>

#include <cstdlib>

#include <gtest/gtest.h>

#include "proto/stream_protocol.h"

namespace vem::testing {

using namespace std::chrono_literals;

constexpr auto kLimit = 10s;

struct TestMqttPublisher::Callbacks {
  static TestMqttPublisher& self(void* userdata) {
    return *static_cast<TestMqttPublisher*>(userdata);
  }

  static void connected(mosquitto*, void* userdata, int rc, int, const mosquitto_property*) {
    TestMqttPublisher& p = self(userdata);
    {
      std::lock_guard lock(p.mutex_);
      p.connackCode_ = rc;
      p.connected_ = rc == 0;
    }
    p.changed_.notify_all();
  }

  static void finished(TestMqttPublisher& p, int mid) {
    {
      std::lock_guard lock(p.mutex_);
      p.done_.insert(mid);
    }
    p.changed_.notify_all();
  }

  static void published(mosquitto*, void* userdata, int mid, int, const mosquitto_property*) {
    finished(self(userdata), mid);
  }

  static void subscribed(mosquitto*, void* userdata, int mid, int, const int*,
                         const mosquitto_property*) {
    finished(self(userdata), mid);
  }

  // A control: recorded, and answered ok on its response topic with its correlation data.
  static void message(mosquitto* client, void* userdata, const mosquitto_message* m,
                      const mosquitto_property* properties) {
    TestMqttPublisher& p = self(userdata);
    ReceivedControl control;
    control.topic = m->topic;
    control.payload.assign(static_cast<const char*>(m->payload), std::size_t(m->payloadlen));
    control.message.ParseFromArray(m->payload, m->payloadlen);
    char* responseTopic = nullptr;
    if (mosquitto_property_read_string(properties, MQTT_PROP_RESPONSE_TOPIC, &responseTopic,
                                       false) != nullptr) {
      control.responseTopic = responseTopic;
      std::free(responseTopic);
    }
    void* correlation = nullptr;
    std::uint16_t correlationLength = 0;
    if (mosquitto_property_read_binary(properties, MQTT_PROP_CORRELATION_DATA, &correlation,
                                       &correlationLength, false) != nullptr) {
      control.correlationData.assign(static_cast<const char*>(correlation), correlationLength);
      std::free(correlation);
    }
    if (!control.responseTopic.empty()) {
      stream::ServerMessage reply;
      reply.set_protocol_major(stream::kProtocolMajor);
      reply.set_protocol_minor(stream::kProtocolMinor);
      reply.mutable_reply()->set_request_id(control.message.request_id());
      reply.mutable_reply()->set_ok(true);
      const std::string bytes = reply.SerializeAsString();
      mosquitto_property* out = nullptr;
      if (!control.correlationData.empty()) {
        mosquitto_property_add_binary(&out, MQTT_PROP_CORRELATION_DATA,
                                      control.correlationData.data(),
                                      std::uint16_t(control.correlationData.size()));
      }
      mosquitto_publish_v5(client, nullptr, control.responseTopic.c_str(), int(bytes.size()),
                           bytes.data(), 1, false, out);
      mosquitto_property_free_all(&out);
    }
    {
      std::lock_guard lock(p.mutex_);
      p.controls_.push_back(std::move(control));
    }
    p.changed_.notify_all();
  }
};

TestMqttPublisher::TestMqttPublisher() = default;

std::unique_ptr<TestMqttPublisher> TestMqttPublisher::connect(std::uint16_t port,
                                                              const std::string& username,
                                                              const std::string& password) {
  mosquitto_lib_init();
  std::unique_ptr<TestMqttPublisher> p(new TestMqttPublisher());
  p->client_ = mosquitto_new(nullptr, true, p.get());
  if (p->client_ == nullptr) {
    ADD_FAILURE() << "mosquitto_new failed";
    return nullptr;
  }
  mosquitto_int_option(p->client_, MOSQ_OPT_PROTOCOL_VERSION, MQTT_PROTOCOL_V5);
  if (!username.empty()) mosquitto_username_pw_set(p->client_, username.c_str(), password.c_str());
  mosquitto_connect_v5_callback_set(p->client_, Callbacks::connected);
  mosquitto_publish_v5_callback_set(p->client_, Callbacks::published);
  mosquitto_subscribe_v5_callback_set(p->client_, Callbacks::subscribed);
  mosquitto_message_v5_callback_set(p->client_, Callbacks::message);
  const int rc = mosquitto_connect(p->client_, "127.0.0.1", port, 10);
  if (rc != MOSQ_ERR_SUCCESS) {
    ADD_FAILURE() << "the test publisher cannot connect to 127.0.0.1:" << port << ": "
                  << mosquitto_strerror(rc);
    return nullptr;
  }
  mosquitto_loop_start(p->client_);
  std::unique_lock lock(p->mutex_);
  if (!p->changed_.wait_for(lock, kLimit, [&] { return p->connackCode_ >= 0; }) || !p->connected_) {
    ADD_FAILURE() << "the broker did not accept the test publisher (CONNACK " << p->connackCode_
                  << ")";
    return nullptr;
  }
  return p;
}

TestMqttPublisher::~TestMqttPublisher() {
  if (client_ == nullptr) return;
  mosquitto_disconnect(client_);
  mosquitto_loop_stop(client_, false);
  mosquitto_destroy(client_);
}

bool TestMqttPublisher::publish(const std::string& topic, const std::string& payload, bool retain,
                                const std::string& responseTopic,
                                const std::string& correlationData) {
  mosquitto_property* properties = nullptr;
  if (!responseTopic.empty()) {
    mosquitto_property_add_string(&properties, MQTT_PROP_RESPONSE_TOPIC, responseTopic.c_str());
  }
  if (!correlationData.empty()) {
    mosquitto_property_add_binary(&properties, MQTT_PROP_CORRELATION_DATA, correlationData.data(),
                                  std::uint16_t(correlationData.size()));
  }
  int mid = 0;
  const int rc = mosquitto_publish_v5(client_, &mid, topic.c_str(), int(payload.size()),
                                      payload.data(), 1, retain, properties);
  mosquitto_property_free_all(&properties);
  if (rc != MOSQ_ERR_SUCCESS) {
    ADD_FAILURE() << "cannot publish to " << topic << ": " << mosquitto_strerror(rc);
    return false;
  }
  std::unique_lock lock(mutex_);
  const bool left = changed_.wait_for(lock, kLimit, [&] { return done_.contains(mid); });
  done_.erase(mid);
  if (!left) ADD_FAILURE() << "the broker did not acknowledge the payload to " << topic;
  return left;
}

bool TestMqttPublisher::answerControls(const std::string& controlTopic) {
  int mid = 0;
  if (mosquitto_subscribe_v5(client_, &mid, controlTopic.c_str(), 1, 0, nullptr) !=
      MOSQ_ERR_SUCCESS) {
    ADD_FAILURE() << "cannot subscribe to " << controlTopic;
    return false;
  }
  std::unique_lock lock(mutex_);
  const bool subscribed = changed_.wait_for(lock, kLimit, [&] { return done_.contains(mid); });
  done_.erase(mid);
  if (!subscribed) ADD_FAILURE() << "no SUBACK for " << controlTopic;
  return subscribed;
}

bool TestMqttPublisher::waitForControls(std::size_t count,
                                        std::chrono::milliseconds timeout) const {
  std::unique_lock lock(mutex_);
  return changed_.wait_for(lock, timeout, [&] { return controls_.size() >= count; });
}

std::vector<TestMqttPublisher::ReceivedControl> TestMqttPublisher::controls() const {
  std::lock_guard lock(mutex_);
  return controls_;
}

}  // namespace vem::testing
