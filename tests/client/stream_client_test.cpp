// StreamClient against an in-test WebSocket server (test_stream_server.h) on 127.0.0.1: what it
// keeps, counts, sends and how it recovers (client/stream_client.h). Waits are bounded by generous
// timeouts only to fail instead of hanging; nothing asserts a duration.
#include "client/stream_client.h"

#include <gtest/gtest.h>

#include "client/stream_test_messages.h"
#include "client/test_stream_server.h"

namespace vem::client {
namespace {

using namespace std::chrono_literals;
using test::bytesOf;
using test::lightFrameMessage;
using test::TestStreamServer;

constexpr auto kWait = 10s;

std::unique_ptr<StreamClient> startClient(const std::string& url, std::string token = "",
                                          Subscription subscription = {}) {
  StreamClientOptions options;
  options.url = url;
  options.token = std::move(token);
  options.subscription = subscription;
  options.initialBackoff = 10ms;
  options.maxBackoff = 100ms;
  auto client = StreamClient::start(std::move(options));
  EXPECT_TRUE(client.has_value()) << client.error();
  return client ? std::move(*client) : nullptr;
}

// Waits until the client has subscribed on `server` (its first message there).
void waitSubscribed(const TestStreamServer& server, std::size_t messages = 1) {
  ASSERT_TRUE(server.waitForClientMessages(messages, kWait));
}

TEST(StreamClient, SubscribesAfterHelloAndKeepsTheLatestLightFrame) {
  TestStreamServer server;
  auto client = startClient(server.url());
  waitSubscribed(server);
  const stream::ClientMessage subscribe = server.clientMessages().at(0);
  ASSERT_TRUE(subscribe.has_subscribe());
  EXPECT_EQ(subscribe.protocol_major(), 1U);
  EXPECT_TRUE(subscribe.subscribe().lights());
  EXPECT_EQ(subscribe.subscribe().cubemap_rate_hz(), 0.0);
  ASSERT_TRUE(client->waitForState(ConnectionState::Connected, kWait));
  ASSERT_TRUE(client->hello().has_value());
  EXPECT_EQ(client->hello()->server, "fixture 1.0");

  for (std::uint64_t seq : {1, 2, 3}) server.send(bytesOf(lightFrameMessage(seq, 4)));
  const auto frame = client->waitForLightFrame(2, kWait);
  ASSERT_TRUE(frame.has_value());
  EXPECT_EQ(frame->frame.seq, 3U);
  EXPECT_EQ(frame->frame.lights.lights.size(), 4U);
  EXPECT_EQ(client->latestLightFrame()->frame.seq, 3U);
  EXPECT_GE(client->latestLightFrame()->age(), 0ns);
  const ClientStats stats = client->stats();
  EXPECT_EQ(stats.received, 3U);
  EXPECT_EQ(stats.skipped, 0U);
  EXPECT_EQ(stats.latency.samples, 3U);
  EXPECT_EQ(stats.reconnects, 0U);
}

TEST(StreamClient, CountsSeqGapsAsSkipped) {
  TestStreamServer server;
  auto client = startClient(server.url());
  waitSubscribed(server);
  for (std::uint64_t seq : {1, 2, 5, 9}) server.send(bytesOf(lightFrameMessage(seq)));
  ASSERT_TRUE(client->waitForLightFrame(8, kWait).has_value());
  EXPECT_EQ(client->stats().received, 4U);
  EXPECT_EQ(client->stats().skipped, 2U + 3U);
}

TEST(StreamClient, KeepsTheLatestEnvironmentFrameItSubscribedTo) {
  TestStreamServer server;
  Subscription subscription;
  subscription.cubemapRateHz = 2.0;
  subscription.cubemapFacePx = 8;
  auto client = startClient(server.url(), "", subscription);
  waitSubscribed(server);
  EXPECT_EQ(server.clientMessages().at(0).subscribe().cubemap_rate_hz(), 2.0);
  EXPECT_EQ(server.clientMessages().at(0).subscribe().cubemap_face_px(), 8U);
  server.send(bytesOf(test::environmentMessage(5, 8, 2)));
  server.send(bytesOf(lightFrameMessage(6)));  // arrives after the environment frame
  ASSERT_TRUE(client->waitForLightFrame(5, kWait).has_value());
  const auto environment = client->latestEnvironmentFrame();
  ASSERT_TRUE(environment.has_value());
  EXPECT_EQ(environment->frame.seq, 5U);
  ASSERT_EQ(environment->frame.cube.levels.size(), 2U);
  EXPECT_EQ(environment->frame.cube.levels[1].facePx, 4);
  EXPECT_EQ(client->stats().environmentFrames, 1U);
}

TEST(StreamClient, ReconnectsAfterTheServerDropsAndRestartsOnTheSamePort) {
  auto server = std::make_unique<TestStreamServer>();
  const std::uint16_t port = server->port();
  auto client = startClient(server->url());
  waitSubscribed(*server);
  server->send(bytesOf(lightFrameMessage(1)));
  ASSERT_TRUE(client->waitForLightFrame(std::nullopt, kWait).has_value());

  server.reset();  // the daemon dies: every connection drops
  ASSERT_TRUE(client->waitForState(ConnectionState::Waiting, kWait));
  server = std::make_unique<TestStreamServer>(port);
  waitSubscribed(*server);
  ASSERT_TRUE(client->waitForState(ConnectionState::Connected, kWait));
  server->send(bytesOf(lightFrameMessage(10)));
  const auto frame = client->waitForLightFrame(1, kWait);
  ASSERT_TRUE(frame.has_value());
  EXPECT_EQ(frame->frame.seq, 10U);
  EXPECT_EQ(client->stats().reconnects, 1U);
}

TEST(StreamClient, SendsTheBearerTokenInTheHandshake) {
  TestStreamServer server(0, "s3cret");
  auto client = startClient(server.url(), "s3cret");
  waitSubscribed(server);
  ASSERT_FALSE(server.authorizations().empty());
  EXPECT_EQ(server.authorizations().front(), "Bearer s3cret");
}

TEST(StreamClient, SendsNoAuthorizationWithoutAToken) {
  TestStreamServer server;
  auto client = startClient(server.url());
  waitSubscribed(server);
  EXPECT_EQ(server.authorizations().front(), "");
}

TEST(StreamClient, StopsWithTheSentenceWhenTheServerSpeaksMajor2) {
  TestStreamServer server(0, "", bytesOf(test::helloMessage(), 2));
  auto client = startClient(server.url());
  ASSERT_TRUE(client->waitForState(ConnectionState::Refused, kWait));
  EXPECT_EQ(client->stateReason(),
            "protocol major version 2 is not supported (this client speaks 1)");
  EXPECT_EQ(client->stats().decodeErrors, 1U);
  EXPECT_FALSE(client->waitForLightFrame(std::nullopt, 1ms).has_value());
  EXPECT_FALSE(server.waitForConnections(2, 300ms));  // it does not retry
}

TEST(StreamClient, StopsWhenTheServerRefusesTheToken) {
  TestStreamServer server(0, "right");
  auto client = startClient(server.url(), "wrong");
  ASSERT_TRUE(client->waitForState(ConnectionState::Refused, kWait));
  EXPECT_EQ(client->stateReason(), "the daemon refused the token (HTTP 401)");
  EXPECT_EQ(client->stats().decodeErrors, 0U);
}

TEST(StreamClient, ReconnectsAfterAMalformedMessage) {
  TestStreamServer server;
  auto client = startClient(server.url());
  waitSubscribed(server);
  stream::ServerMessage bad = lightFrameMessage(1);
  bad.mutable_lights()->set_dirs(0, 7.0F);
  server.send(bytesOf(bad));
  ASSERT_TRUE(server.waitForConnections(2, kWait));
  waitSubscribed(server, 2);
  server.send(bytesOf(lightFrameMessage(2)));
  const auto frame = client->waitForLightFrame(std::nullopt, kWait);
  ASSERT_TRUE(frame.has_value());
  EXPECT_EQ(frame->frame.seq, 2U);
  EXPECT_EQ(client->stats().decodeErrors, 1U);
  EXPECT_EQ(client->stats().received, 1U);
}

TEST(StreamClient, StopEndsTheConnectionWithAClosingHandshakeNotADroppedSocket) {
  TestStreamServer server;
  auto client = startClient(server.url());
  waitSubscribed(server);
  ASSERT_TRUE(client->waitForState(ConnectionState::Connected, kWait));
  client->stop();
  ASSERT_TRUE(server.waitForEndings(1, kWait));
  EXPECT_EQ(server.endings(), std::vector<std::string>{"close 1000"});
  EXPECT_EQ(client->state(), ConnectionState::Stopped);
}

TEST(StreamClient, MalformedMessageClosesWithProtocolError1002) {
  TestStreamServer server;
  auto client = startClient(server.url());
  waitSubscribed(server);
  stream::ServerMessage bad = lightFrameMessage(1);
  bad.mutable_lights()->set_dirs(0, 7.0F);
  server.send(bytesOf(bad));
  ASSERT_TRUE(server.waitForEndings(1, kWait));
  EXPECT_EQ(server.endings().at(0), "close 1002");
}

TEST(StreamClient, RefusesToSendControlWithoutAToken) {
  TestStreamServer server;
  auto client = startClient(server.url());
  waitSubscribed(server);
  stream::Control control;
  control.set_set_light_count(16);
  const ControlResult result = client->sendControl(control).get();
  ASSERT_FALSE(result.has_value());
  EXPECT_NE(result.error().find("need the daemon's token"), std::string::npos) << result.error();
  EXPECT_FALSE(server.waitForClientMessages(2, 100ms));  // nothing went out after Subscribe
}

TEST(StreamClient, SendsControlWithTheTokenAndReturnsTheReply) {
  TestStreamServer server(0, "s3cret");
  auto client = startClient(server.url(), "s3cret");
  waitSubscribed(server);
  ASSERT_TRUE(client->waitForState(ConnectionState::Connected, kWait));
  stream::Control control;
  control.set_set_filter("paper9");
  auto future = client->sendControl(control);
  ASSERT_EQ(future.wait_for(kWait), std::future_status::ready);
  const ControlResult result = future.get();
  ASSERT_TRUE(result.has_value()) << result.error();
  EXPECT_TRUE(result->ok);
  const stream::ClientMessage sent = server.clientMessages().at(1);
  EXPECT_EQ(sent.control().set_filter(), "paper9");
  EXPECT_EQ(result->requestId, sent.request_id());
}

TEST(StreamClient, RefusesAnUnusableUrlWithASentence) {
  StreamClientOptions options;
  options.url = "http://127.0.0.1:1/";
  const auto client = StreamClient::start(std::move(options));
  ASSERT_FALSE(client.has_value());
  EXPECT_NE(client.error().find("is not a stream address"), std::string::npos);
}

}  // namespace
}  // namespace vem::client
