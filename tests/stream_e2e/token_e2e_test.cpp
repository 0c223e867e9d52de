// The stream's token (docs/protocol.md, "Connecting" and "Security"): vemd configured with
// stream.token_file (mode 0600) refuses a wrong token always, no token beyond loopback, and control
// messages from any connection without the token.
#include <csignal>

#include <gtest/gtest.h>

#include "stream_e2e/raw_ws_client.h"
#include "stream_e2e/stream_e2e_fixture.h"
#include "support/network_namespace.h"

namespace vem::e2e {
namespace {

constexpr const char* kToken = "e2e-secret-7f3a-c4d1";  // vemd wants 16 bytes or more

stream::Control setLightCount(std::uint32_t count) {
  stream::Control control;
  control.set_set_light_count(count);
  return control;
}

// Waits (bounded) for a light frame with `count` lights; false when none came.
bool waitForLightCount(const client::StreamClient& client, std::size_t count) {
  const auto deadline = std::chrono::steady_clock::now() + kFrameTimeout;
  std::optional<std::uint64_t> after;
  while (std::chrono::steady_clock::now() < deadline) {
    const auto frame = client.waitForLightFrame(after, 1s);
    if (!frame) continue;
    if (frame->frame.lights.lights.size() == count) return true;
    after = frame->frame.seq;
  }
  return false;
}

// Catches a handshake that lets a wrong or a missing token through on a listener beyond loopback
// (0.0.0.0, reached here through 127.0.0.1), or that refuses the right one: the two bad clients
// end Refused with a sentence (401), the good one connects, may send control, and its
// set_light_count reaches the light frames.
// It listens on 0.0.0.0, so it runs only in a network namespace with loopback alone: ctest's
// vem_stream_e2e_beyond_loopback (tests/support/run_in_netns.sh); elsewhere it skips.
TEST_F(StreamE2eTest, WrongOrMissingTokenIsRefusedBeyondLoopback) {
  if (const auto up = vem::testing::nonLoopbackInterfacesUp(); !up.empty()) {
    GTEST_SKIP() << "listens on 0.0.0.0 while interface " << *up.begin()
                 << " is up; ctest runs it in its own network namespace";
  }
  const auto tokenFile = writeFile("token", std::string(kToken) + "\n");
  const auto port = startVemd(
      {}, "[stream]\nlisten = \"0.0.0.0:0\"\ntoken_file = \"" + tokenFile.string() + "\"\n",
      /*listenOnLoopback=*/false);
  ASSERT_TRUE(port);

  LoggedClient missing = startClient(*port);
  LoggedClient wrong = startClient(*port, "not-the-token");
  LoggedClient right = startClient(*port, kToken);
  ASSERT_TRUE(missing.client && wrong.client && right.client);
  EXPECT_TRUE(missing.client->waitForState(client::ConnectionState::Refused, kStartTimeout))
      << "no token, state " << client::connectionStateName(missing.client->state());
  EXPECT_FALSE(missing.client->stateReason().empty());
  EXPECT_TRUE(wrong.client->waitForState(client::ConnectionState::Refused, kStartTimeout))
      << "a wrong token, state " << client::connectionStateName(wrong.client->state());
  EXPECT_FALSE(wrong.client->stateReason().empty());
  EXPECT_EQ(missing.log->size() + wrong.log->size(), 0U) << "a refused client received frames";

  ASSERT_TRUE(right.client->waitForState(client::ConnectionState::Connected, kStartTimeout));
  ASSERT_TRUE(right.client->hello().has_value());
  EXPECT_TRUE(right.client->hello()->controlAllowed);
  auto reply = right.client->sendControl(setLightCount(64));
  ASSERT_EQ(reply.wait_for(kFrameTimeout), std::future_status::ready);
  const client::ControlResult result = reply.get();
  ASSERT_TRUE(result.has_value()) << result.error();
  EXPECT_TRUE(result->ok) << result->message;
  EXPECT_TRUE(waitForLightCount(*right.client, 64)) << "the light count set by control never came";
  for (LoggedClient* logged : {&missing, &wrong, &right}) logged->client->stop();
  expectCleanExit(SIGTERM);
}

// Catches a daemon that applies control from a connection without the token (a loopback client
// connects read-only): StreamClient's sendControl fails with a sentence, vemd itself answers a raw
// control message with ok = false and "control messages need the token", and the light count stays
// vemd's configured one; a wrong token is refused even on loopback.
TEST_F(StreamE2eTest, ClientWithoutTheTokenCannotSendControl) {
  const auto tokenFile = writeFile("token", kToken);
  const auto port = startVemd({}, "[stream]\ntoken_file = \"" + tokenFile.string() + "\"\n");
  ASSERT_TRUE(port);

  LoggedClient readOnly = startClient(*port);
  ASSERT_TRUE(readOnly.client);
  ASSERT_TRUE(readOnly.client->waitForState(client::ConnectionState::Connected, kStartTimeout));
  ASSERT_TRUE(readOnly.client->hello().has_value());
  EXPECT_FALSE(readOnly.client->hello()->controlAllowed);
  auto refused = readOnly.client->sendControl(setLightCount(16));
  ASSERT_EQ(refused.wait_for(kFrameTimeout), std::future_status::ready);
  const client::ControlResult result = refused.get();
  ASSERT_FALSE(result.has_value());
  EXPECT_GT(result.error().size(), 10U) << "not a sentence: " << result.error();

  RawWsClient raw;
  ASSERT_EQ(raw.connect(*port), 0);
  stream::ClientMessage control;
  control.set_request_id(42);
  *control.mutable_control() = setLightCount(16);
  ASSERT_TRUE(raw.send(control, 20s));
  std::optional<stream::ControlReply> reply;
  const auto deadline = std::chrono::steady_clock::now() + kFrameTimeout;
  while (!reply && std::chrono::steady_clock::now() < deadline) {
    const auto bytes = raw.readBytes(kFrameTimeout);
    stream::ServerMessage message;
    ASSERT_TRUE(bytes && message.ParseFromString(*bytes)) << "the connection ended";
    if (message.has_reply()) reply = message.reply();
  }
  ASSERT_TRUE(reply.has_value()) << "no ControlReply";
  EXPECT_EQ(reply->request_id(), 42U);
  EXPECT_FALSE(reply->ok());
  EXPECT_EQ(reply->message(), "control messages need the token");
  raw.close(5s);

  LoggedClient wrong = startClient(*port, "not-the-token");
  ASSERT_TRUE(wrong.client);
  EXPECT_TRUE(wrong.client->waitForState(client::ConnectionState::Refused, kStartTimeout));

  // Frames published after the refusals still carry the default light count.
  const auto now = readOnly.client->waitForLightFrame(std::nullopt, kFrameTimeout);
  ASSERT_TRUE(now.has_value());
  const auto later = readOnly.client->waitForLightFrame(now->frame.seq + 30, kFrameTimeout);
  ASSERT_TRUE(later.has_value());
  EXPECT_EQ(later->frame.lights.lights.size(), kLightCount);
  readOnly.client->stop();
  wrong.client->stop();
  expectCleanExit(SIGTERM);
}

}  // namespace
}  // namespace vem::e2e
