// The stream server on 127.0.0.1, port 0, against Beast WebSocket clients: fan-out, slow clients,
// tokens, bad messages, the connection cap, churn. Counts, never wall-clock times.
#include <atomic>
#include <memory>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <spdlog/spdlog.h>

#include "stream/client_message_handler.h"
#include "stream/frame_encoding.h"
#include "stream/stream_server.h"
#include "ws_test_client.h"

namespace vem::stream {
namespace {

using testing::WsTestClient;

std::unique_ptr<StreamServer> startServer(StreamServerOptions options = {}) {
  spdlog::set_level(spdlog::level::warn);
  options.address = "127.0.0.1";
  options.port = 0;
  auto server = StreamServer::start(std::move(options));
  EXPECT_TRUE(server.has_value()) << server.error();
  return std::move(*server);
}

// A light frame of `seq` with `lights` lights (about 28 bytes each on the wire).
SharedBytes lightsMessage(std::uint64_t seq, int lights = 16) {
  ServerMessage message;
  LightFrame& frame = *message.mutable_lights();
  frame.set_seq(seq);
  for (int i = 0; i < lights; ++i) {
    frame.add_ids(std::uint32_t(i));
    for (int k = 0; k < 3; ++k) {
      frame.add_dirs(k == 1 ? 1.0F : 0.0F);
      frame.add_rgb(float(seq % 7) + float(i));
    }
  }
  return std::make_shared<const std::string>(serialize(std::move(message)));
}

using testing::eventually;

TEST(StreamServer, HelloComesFirstAndSaysWhetherControlIsAllowed) {
  StreamServerOptions options;
  options.token = "secret";
  options.hello.set_server("vemd test");
  auto server = startServer(options);
  WsTestClient withToken, without;
  ASSERT_EQ(withToken.connect(server->boundPort(), "/", "secret"), 0);
  ASSERT_EQ(without.connect(server->boundPort()), 0);
  const ServerMessage* hello = &withToken.hello();
  ASSERT_TRUE(hello->has_hello());
  EXPECT_EQ(hello->protocol_major(), kProtocolMajor);
  EXPECT_EQ(hello->hello().server(), "vemd test");
  EXPECT_TRUE(hello->hello().control_allowed());
  EXPECT_EQ(hello->hello().max_client_message_bytes(), kMaxClientMessageBytes);
  const ServerMessage* otherHello = &without.hello();
  ASSERT_TRUE(otherHello->has_hello());
  EXPECT_FALSE(otherHello->hello().control_allowed());
}

TEST(StreamServer, ThreeClientsReceiveTheSameSequenceOfLightFrames) {
  auto server = startServer();
  std::vector<WsTestClient> clients(3);
  for (auto& c : clients) ASSERT_EQ(c.connect(server->boundPort()), 0);
  ASSERT_TRUE(eventually([&] { return server->counters().clients == 3; }));
  for (std::uint64_t seq = 100; seq < 160; ++seq) {
    server->publishLights(lightsMessage(seq));
    for (auto& c : clients) ASSERT_EQ(c.nextLightsSeq(), seq);
  }
}

TEST(StreamServer, ClientThatNeverReadsDoesNotStopTheOthers) {
  StreamServerOptions options;
  options.sendTimeout = std::chrono::minutes(10);  // keep the stuck client for this test
  options.idleTimeout = std::chrono::minutes(10);
  options.maxClientLag = std::chrono::minutes(10);
  auto server = startServer(options);
  WsTestClient stuck;  // connects, then never reads
  ASSERT_EQ(stuck.connect(server->boundPort()), 0);
  std::vector<WsTestClient> readers(2);
  for (auto& c : readers) ASSERT_EQ(c.connect(server->boundPort()), 0);
  ASSERT_TRUE(eventually([&] { return server->counters().clients == 3; }));
  // 400 frames of about 230 kB: far more than the stuck client's socket buffers hold.
  constexpr int kFrames = 400;
  for (int i = 0; i < kFrames; ++i) {
    server->publishLights(lightsMessage(std::uint64_t(i), 8192));
    for (auto& c : readers) ASSERT_EQ(c.nextLightsSeq(), std::uint64_t(i)) << "frame " << i;
  }
  const ServerCounters counters = server->counters();
  EXPECT_EQ(counters.lightsPublished, std::uint64_t(kFrames));
  // The stuck client's write stalled and its slot kept being replaced: it skipped frames.
  EXPECT_GT(counters.lightsSkipped, 0u);
  EXPECT_EQ(counters.clients, 3u);
}

TEST(StreamServer, SendTimeoutClosesAClientThatStoppedReading) {
  StreamServerOptions options;
  options.sendTimeout = std::chrono::milliseconds(200);
  options.maxClientLag = std::chrono::minutes(10);  // the send timeout, not the lag, closes it
  auto server = startServer(options);
  // The stuck client's receive buffer is small, so that the server's write stalls within a few
  // frames whatever the kernel's buffer tuning (under ThreadSanitizer, after the tests before it,
  // 4000 frames did not fill the default buffers).
  e2e::RawWsClient stuck;
  e2e::RawConnectOptions small;
  small.receiveBufferBytes = 4096;
  ASSERT_EQ(stuck.connect(server->boundPort(), small), 0);
  WsTestClient reader;
  ASSERT_EQ(reader.connect(server->boundPort()), 0);
  std::uint64_t seq = 0;
  // Big frames until the stuck client's write has been pending past the timeout.
  ASSERT_TRUE(eventually([&] {
    server->publishLights(lightsMessage(seq, 8192));
    EXPECT_EQ(reader.nextLightsSeq(), seq);
    ++seq;
    return server->counters().closedByServer == 1;
  }));
  EXPECT_TRUE(eventually([&] { return server->counters().clients == 1; }));
  server->publishLights(lightsMessage(seq));
  EXPECT_EQ(reader.nextLightsSeq(), seq);
}

TEST(StreamServer, PublishingWithoutReadersCoalescesInsteadOfQueueing) {
  auto server = startServer();
  WsTestClient stuck;
  ASSERT_EQ(stuck.connect(server->boundPort()), 0);
  ASSERT_TRUE(eventually([&] { return server->counters().clients == 1; }));
  for (int i = 0; i < 2000; ++i) server->publishLights(lightsMessage(std::uint64_t(i), 4096));
  EXPECT_EQ(server->counters().lightsPublished, 2000u);
  // Every publish returned although nobody read; the client then gets a newer frame, not 2000.
  WsTestClient late;
  ASSERT_EQ(late.connect(server->boundPort()), 0);
  server->publishLights(lightsMessage(5000));
  EXPECT_EQ(late.nextLightsSeq(), 5000u);
}

TEST(StreamServer, WrongTokenIsRefusedWith401) {
  StreamServerOptions options;
  options.token = "secret";
  auto server = startServer(options);
  WsTestClient client;
  EXPECT_EQ(client.connect(server->boundPort(), "/", "not-the-secret"), 401);
  WsTestClient query;
  EXPECT_EQ(query.connect(server->boundPort(), "/?token=nope"), 401);
  EXPECT_EQ(server->counters().refusedUnauthorized, 2u);
}

TEST(StreamServer, TokenInTheQueryIsAccepted) {
  StreamServerOptions options;
  options.token = "s3cr3t";
  options.tokenRequiredToConnect = true;
  auto server = startServer(options);
  WsTestClient client;
  ASSERT_EQ(client.connect(server->boundPort(), "/?token=s3cr3t"), 0);
  EXPECT_TRUE(client.hello().hello().control_allowed());
}

TEST(StreamServer, MissingTokenIsRefusedWhenTheListenerRequiresOne) {
  StreamServerOptions options;
  options.token = "secret";
  options.tokenRequiredToConnect = true;  // as for a listener beyond loopback
  auto server = startServer(options);
  WsTestClient client;
  EXPECT_EQ(client.connect(server->boundPort()), 401);
}

TEST(StreamServer, ControlWithoutTokenIsRefused) {
  StreamServerOptions options;
  options.token = "secret";
  auto server = startServer(options);
  WsTestClient client;
  ASSERT_EQ(client.connect(server->boundPort()), 0);
  ClientMessage control;
  control.set_request_id(9);
  control.mutable_control()->set_set_light_count(12);
  ASSERT_TRUE(client.send(control));
  auto reply = client.nextReply();
  ASSERT_TRUE(reply);
  EXPECT_EQ(reply->request_id(), 9u);
  EXPECT_FALSE(reply->ok());
  EXPECT_EQ(reply->message(), kControlNeedsToken);
  EXPECT_TRUE(server->takeControls().empty());
}

TEST(StreamServer, ControlWithTokenReachesTheInboxAndItsReplyTheClient) {
  StreamServerOptions options;
  options.token = "secret";
  auto server = startServer(options);
  WsTestClient client;
  ASSERT_EQ(client.connect(server->boundPort(), "/", "secret"), 0);
  ClientMessage control;
  control.set_request_id(11);
  control.mutable_control()->set_set_light_count(12);
  ASSERT_TRUE(client.send(control));
  std::vector<PendingControl> pending;
  ASSERT_TRUE(eventually([&] {
    pending = server->takeControls();
    return !pending.empty();
  }));
  ASSERT_EQ(pending.size(), 1u);
  EXPECT_EQ(pending[0].command.set_light_count(), 12u);
  ControlReply answer;
  answer.set_request_id(pending[0].requestId);
  answer.set_ok(true);
  server->reply(pending[0].connection, answer);
  auto reply = client.nextReply();
  ASSERT_TRUE(reply);
  EXPECT_EQ(reply->request_id(), 11u);
  EXPECT_TRUE(reply->ok());
}

// `bad` gets closed with `code`; `good` keeps receiving.
void expectOnlyThatClientClosed(StreamServer& server, WsTestClient& bad, WsTestClient& good,
                                int code) {
  while (bad.read()) {
  }
  EXPECT_EQ(bad.closeCode(), code) << bad.closeReason();
  server.publishLights(lightsMessage(77));
  EXPECT_EQ(good.nextLightsSeq(), 77u);
}

TEST(StreamServer, OversizedMessageClosesThatClientOnly) {
  auto server = startServer();
  WsTestClient bad, good;
  ASSERT_EQ(bad.connect(server->boundPort()), 0);
  ASSERT_EQ(good.connect(server->boundPort()), 0);
  (void)bad.sendRaw(std::string(kMaxClientMessageBytes + 1, 'x'));
  expectOnlyThatClientClosed(*server, bad, good, 1009);
}

TEST(StreamServer, UnknownMajorClosesWith1002) {
  auto server = startServer();
  WsTestClient bad, good;
  ASSERT_EQ(bad.connect(server->boundPort()), 0);
  ASSERT_EQ(good.connect(server->boundPort()), 0);
  ClientMessage message;
  message.set_protocol_major(2);
  message.mutable_subscribe()->set_lights(true);
  ASSERT_TRUE(bad.send(message));
  expectOnlyThatClientClosed(*server, bad, good, 1002);
  EXPECT_EQ(bad.closeReason(), "protocol major version 2 is not supported (vemd speaks 1)");
}

TEST(StreamServer, MalformedBytesCloseThatClientOnlyWith1007) {
  auto server = startServer();
  WsTestClient bad, good;
  ASSERT_EQ(bad.connect(server->boundPort()), 0);
  ASSERT_EQ(good.connect(server->boundPort()), 0);
  ASSERT_TRUE(bad.sendRaw("\xff\xff\xff\xff\xff"));
  expectOnlyThatClientClosed(*server, bad, good, 1007);
}

TEST(StreamServer, TextMessageClosesThatClientOnlyWith1003) {
  auto server = startServer();
  WsTestClient bad, good;
  ASSERT_EQ(bad.connect(server->boundPort()), 0);
  ASSERT_EQ(good.connect(server->boundPort()), 0);
  ASSERT_TRUE(bad.sendRaw("{\"subscribe\":{}}", false));
  expectOnlyThatClientClosed(*server, bad, good, 1003);
}

// The bug this guards: closedByServer was counted by matching the start of the log phrase, so
// rewording a phrase silently moved a close between "closed by vemd" and the rest. Each close is
// now counted by its typed cause: vemd's two closes count, the client's own close and a vanished
// client do not.
TEST(StreamServer, ClosesAreCountedByWhoClosedNotByTheWordingOfTheirLogLine) {
  auto server = startServer();
  WsTestClient oversized, malformed, polite, vanished;
  for (WsTestClient* c : {&oversized, &malformed, &polite, &vanished}) {
    ASSERT_EQ(c->connect(server->boundPort()), 0);
  }
  ASSERT_TRUE(eventually([&] { return server->counters().clients == 4; }));
  // vemd closes these two: 1009 and 1007.
  (void)oversized.sendRaw(std::string(kMaxClientMessageBytes + 1, 'x'));
  ASSERT_TRUE(malformed.sendRaw("\xff\xff\xff\xff\xff"));
  while (oversized.read()) {
  }
  while (malformed.read()) {
  }
  // These two end the connection themselves: a closing handshake whose reason reads like vemd's,
  // and a socket that just goes away.
  polite.closeWith("closed by vemd: so says the client");
  vanished.drop();
  ASSERT_TRUE(eventually([&] { return server->counters().clients == 0; }));
  EXPECT_EQ(oversized.closeCode(), 1009);
  EXPECT_EQ(malformed.closeCode(), 1007);
  EXPECT_EQ(server->counters().closedByServer, 2u);
  EXPECT_EQ(server->counters().closedTooSlow, 0u);
}

TEST(StreamServer, ConnectionsOverTheCapGet503) {
  StreamServerOptions options;
  options.maxClients = 2;
  auto server = startServer(options);
  WsTestClient a, b, c;
  ASSERT_EQ(a.connect(server->boundPort()), 0);
  ASSERT_EQ(b.connect(server->boundPort()), 0);
  EXPECT_EQ(c.connect(server->boundPort()), 503);
  EXPECT_EQ(server->counters().refusedFull, 1u);
  a.close();
  ASSERT_TRUE(eventually([&] { return server->counters().clients == 1; }));
  WsTestClient d;
  EXPECT_EQ(d.connect(server->boundPort()), 0);
}

TEST(StreamServer, CubemapDemandFollowsSubscriptionsAndDisconnects) {
  auto server = startServer();
  EXPECT_FALSE(server->cubemapDemand().any());
  WsTestClient client;
  ASSERT_EQ(client.connect(server->boundPort()), 0);
  ClientMessage subscribe;
  subscribe.set_request_id(1);
  subscribe.mutable_subscribe()->set_lights(true);
  subscribe.mutable_subscribe()->set_cubemap_rate_hz(15.0);
  subscribe.mutable_subscribe()->set_cubemap_face_px(16);
  ASSERT_TRUE(client.send(subscribe));
  auto reply = client.nextReply();
  ASSERT_TRUE(reply && reply->ok());
  const CubemapDemand demand = server->cubemapDemand();
  ASSERT_EQ(demand.variants.size(), 1u);
  EXPECT_EQ(demand.variants[0].variant.facePx, 16);
  EXPECT_DOUBLE_EQ(demand.variants[0].rateHz, 15.0);
  client.drop();
  EXPECT_TRUE(eventually([&] { return !server->cubemapDemand().any(); }));
}

TEST(StreamServer, EnvironmentFramesGoOnlyToSubscribers) {
  auto server = startServer();
  WsTestClient subscriber, other;
  ASSERT_EQ(subscriber.connect(server->boundPort()), 0);
  ASSERT_EQ(other.connect(server->boundPort()), 0);
  ClientMessage subscribe;
  subscribe.mutable_subscribe()->set_lights(true);
  subscribe.mutable_subscribe()->set_cubemap_rate_hz(60.0);
  subscribe.mutable_subscribe()->set_cubemap_face_px(8);
  ASSERT_TRUE(subscriber.send(subscribe));
  ASSERT_TRUE(subscriber.nextReply());
  const CubeVariant variant = server->cubemapDemand().variants.at(0).variant;
  ServerMessage environment;
  environment.mutable_environment()->set_seq(5);
  environment.mutable_environment()->set_face_px(8);
  server->publishEnvironment(variant, std::make_shared<const std::string>(serialize(environment)));
  server->publishLights(lightsMessage(6));
  int subscriberEnvironments = 0, otherEnvironments = 0;
  bool subscriberLights = false;
  while (!subscriberLights || subscriberEnvironments == 0) {  // both, in either order
    auto message = subscriber.read();
    ASSERT_TRUE(message);
    if (message->has_environment()) ++subscriberEnvironments;
    if (message->has_lights()) subscriberLights = true;
  }
  EXPECT_EQ(other.nextLightsSeq(&otherEnvironments), 6u);
  EXPECT_EQ(subscriberEnvironments, 1);
  EXPECT_EQ(otherEnvironments, 0);
}

TEST(StreamServer, StatusCarriesClientsAndThisClientsSkips) {
  auto server = startServer();
  WsTestClient client;
  ASSERT_EQ(client.connect(server->boundPort()), 0);
  ASSERT_TRUE(eventually([&] { return server->counters().clients == 1; }));
  Status status;
  status.set_source("synthetic:sky");
  server->publishStatus(status);
  for (;;) {
    auto message = client.read();
    ASSERT_TRUE(message);
    if (!message->has_status()) continue;
    EXPECT_EQ(message->status().source(), "synthetic:sky");
    EXPECT_EQ(message->status().clients(), 1u);
    EXPECT_EQ(message->status().skipped_for_you(), 0u);
    break;
  }
}

TEST(StreamServer, TwentyClientsChurningLeaveTheServerServing) {
  auto server = startServer();
  std::atomic<bool> publishing{true};
  std::thread publisher([&] {
    for (std::uint64_t seq = 0; publishing.load(); ++seq) {
      server->publishLights(lightsMessage(seq, 64));
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
  });
  constexpr int kClients = 20;
  constexpr int kRounds = 10;  // 200 connections
  std::vector<std::thread> clients;
  std::atomic<int> connected{0};
  for (int c = 0; c < kClients; ++c) {
    clients.emplace_back([&, c] {
      for (int round = 0; round < kRounds; ++round) {
        WsTestClient client;
        if (client.connect(server->boundPort()) != 0) continue;
        ++connected;
        if ((c + round) % 3 == 0) {
          client.close();
        } else if ((c + round) % 3 == 1) {
          client.drop();
        } else {
          (void)client.sendRaw("garbage");
          while (client.read()) {
          }
        }
      }
    });
  }
  for (auto& t : clients) t.join();
  publishing = false;
  publisher.join();
  EXPECT_EQ(connected.load(), kClients * kRounds);
  EXPECT_TRUE(eventually([&] { return server->counters().clients == 0; }));
  WsTestClient last;
  ASSERT_EQ(last.connect(server->boundPort()), 0);
  server->publishLights(lightsMessage(123456));
  EXPECT_EQ(last.nextLightsSeq(), 123456u);
}

TEST(StreamServer, PortInUseIsOneSentence) {
  auto first = startServer();
  StreamServerOptions options;
  options.port = first->boundPort();
  auto second = StreamServer::start(options);
  ASSERT_FALSE(second.has_value());
  EXPECT_NE(second.error().find("cannot listen on 127.0.0.1:"), std::string::npos) << second.error();
}

}  // namespace
}  // namespace vem::stream
