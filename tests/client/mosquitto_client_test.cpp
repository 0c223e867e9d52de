// The libmosquitto set-up shared by vemd and the clients (util/mosquitto_client.h), connected to a
// real Mosquitto on 127.0.0.1 (tests/support/mosquitto_broker.h).
#include "util/mosquitto_client.h"

#include <mosquitto.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>

#include <gtest/gtest.h>

#include "support/mosquitto_broker.h"
#include "util/mqtt_url.h"

namespace vem::util {
namespace {

// Without TCP_NODELAY a light frame written while the previous one waited for its ACK waited for
// the broker's delayed ACK: p99 13 ms through a broker on loopback instead of 3
// (docs/BENCHMARKS.md, "MQTT fan-out").
TEST(MosquittoClient, SocketHasNagleOffSoAFrameDoesNotWaitForADelayedAck) {
  auto broker = testing::MosquittoBroker::start();
  ASSERT_TRUE(broker.has_value()) << broker.error();
  const auto url = parseMqttUrl((*broker)->url("/vemcast/cam"));
  ASSERT_TRUE(url.has_value()) << url.error();
  auto client = newMosquittoClient(*url, {}, nullptr);
  ASSERT_TRUE(client.has_value()) << client.error();
  ASSERT_EQ(mosquitto_connect(client->handle.get(), "127.0.0.1", (*broker)->port(), 10),
            MOSQ_ERR_SUCCESS);
  const int fd = mosquitto_socket(client->handle.get());
  ASSERT_GE(fd, 0);
  int noDelay = 0;
  socklen_t size = sizeof noDelay;
  ASSERT_EQ(::getsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &noDelay, &size), 0);
  EXPECT_NE(noDelay, 0);
  mosquitto_disconnect(client->handle.get());
}

}  // namespace
}  // namespace vem::util
