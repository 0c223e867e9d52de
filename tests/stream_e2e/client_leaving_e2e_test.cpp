// A render client that stops leaves vemd with a WebSocket closing handshake, as the protocol asks
// (docs/protocol.md), so vemd's log tells a client that quit from a connection that broke.
#include <chrono>
#include <csignal>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "stream_e2e/stream_e2e_fixture.h"

namespace vem::e2e {
namespace {

// Catches a StreamClient::stop() that drops its socket without a close frame (vemd then logs
// "left without a closing handshake"): a client that received light frames stops, and vemd's
// log says it closed the connection with code 1000.
TEST_F(StreamE2eTest, StoppedClientLeavesWithAClosingHandshake) {
  const auto port = startVemd({});
  ASSERT_TRUE(port);
  std::vector<LoggedClient> clients;
  clients.push_back(startClient(*port));
  ASSERT_NE(clients[0].client, nullptr);
  ASSERT_TRUE(waitForSeq(clients, 0));
  clients[0].client->stop();

  const std::string closed = "gone: the client closed the connection (1000)";
  const auto deadline = std::chrono::steady_clock::now() + kFrameTimeout;
  while (vemd_->stderrText().find(closed) == std::string::npos &&
         std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(20ms);
  }
  const std::string log = vemd_->stderrText();
  EXPECT_NE(log.find(closed), std::string::npos) << log;
  EXPECT_EQ(log.find("without a closing handshake"), std::string::npos) << log;
  expectCleanExit(SIGTERM);
}

}  // namespace
}  // namespace vem::e2e
