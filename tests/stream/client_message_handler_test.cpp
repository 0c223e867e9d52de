// The pure rules for client messages (client_message_handler.h), the handshake
// (handshake_auth.h), the newest-only outbox (outbox.h) and the cube-map demand.
#include <gtest/gtest.h>

#include "stream/client_message_handler.h"
#include "stream/cubemap_demand.h"
#include "stream/handshake_auth.h"
#include "stream/outbox.h"

namespace vem::stream {
namespace {

std::string bytesOf(ClientMessage message, std::uint32_t major = kProtocolMajor) {
  message.set_protocol_major(major);
  return message.SerializeAsString();
}

ClientMessage controlMessage(std::uint64_t requestId) {
  ClientMessage m;
  m.set_request_id(requestId);
  m.mutable_control()->set_set_light_count(256);
  return m;
}

TEST(ClientMessageHandler, UnknownMajorClosesWith1002AndNamesTheVersion) {
  const ClientAction action = handleClientMessage(bytesOf(controlMessage(1), 2), true);
  ASSERT_TRUE(std::holds_alternative<CloseAction>(action));
  EXPECT_EQ(std::get<CloseAction>(action).code, 1002);
  EXPECT_EQ(std::get<CloseAction>(action).reason,
            "protocol major version 2 is not supported (vemd speaks 1)");
}

TEST(ClientMessageHandler, MalformedBytesCloseWith1007) {
  const ClientAction action = handleClientMessage("\xff\xff\xff\xff", true);
  ASSERT_TRUE(std::holds_alternative<CloseAction>(action));
  EXPECT_EQ(std::get<CloseAction>(action).code, 1007);
}

TEST(ClientMessageHandler, ControlWithoutTokenIsRefusedWithItsRequestId) {
  const ClientAction action = handleClientMessage(bytesOf(controlMessage(42)), false);
  ASSERT_TRUE(std::holds_alternative<ReplyAction>(action));
  EXPECT_FALSE(std::get<ReplyAction>(action).reply.ok());
  EXPECT_EQ(std::get<ReplyAction>(action).reply.request_id(), 42u);
  EXPECT_EQ(std::get<ReplyAction>(action).reply.message(), kControlNeedsToken);
}

TEST(ClientMessageHandler, ControlWithTokenGoesToTheProcessingThread) {
  const ClientAction action = handleClientMessage(bytesOf(controlMessage(7)), true);
  ASSERT_TRUE(std::holds_alternative<ControlAction>(action));
  EXPECT_EQ(std::get<ControlAction>(action).requestId, 7u);
  EXPECT_EQ(std::get<ControlAction>(action).command.set_light_count(), 256u);
}

TEST(ClientMessageHandler, OutOfRangeControlValuesAreRefused) {
  ClientMessage zero;
  zero.mutable_control()->set_set_light_count(0);
  EXPECT_TRUE(std::holds_alternative<ReplyAction>(handleClientMessage(bytesOf(zero), true)));
  ClientMessage escape;
  escape.mutable_control()->mutable_start_recording()->set_name("../../etc/passwd");
  EXPECT_TRUE(std::holds_alternative<ReplyAction>(handleClientMessage(bytesOf(escape), true)));
  ClientMessage dots;
  dots.mutable_control()->mutable_start_recording()->set_name("..");
  EXPECT_TRUE(std::holds_alternative<ReplyAction>(handleClientMessage(bytesOf(dots), true)));
}

TEST(ClientMessageHandler, SubscribeDefaultsFaceAndClampsLevels) {
  ClientMessage m;
  m.mutable_subscribe()->set_lights(true);
  m.mutable_subscribe()->set_cubemap_rate_hz(10.0);
  m.mutable_subscribe()->set_cubemap_levels(8);
  const ClientAction action = handleClientMessage(bytesOf(m), false);
  ASSERT_TRUE(std::holds_alternative<SubscribeAction>(action));
  const Subscription& s = std::get<SubscribeAction>(action).subscription;
  EXPECT_EQ(s.cube.facePx, 64);
  EXPECT_EQ(s.cube.levels, 7);  // 64 -> 1 texel: 7 levels
  EXPECT_DOUBLE_EQ(s.cubemapRateHz, 10.0);
}

TEST(ClientMessageHandler, SubscribeOutOfRangeKeepsTheOldOneAndSaysWhy) {
  for (auto set : {+[](Subscribe& s) { s.set_cubemap_rate_hz(61.0); },
                   +[](Subscribe& s) { s.set_cubemap_rate_hz(-1.0); },
                   +[](Subscribe& s) { s.set_cubemap_face_px(4); },
                   +[](Subscribe& s) { s.set_cubemap_face_px(1024); },
                   +[](Subscribe& s) { s.set_cubemap_levels(9); }}) {
    ClientMessage m;
    set(*m.mutable_subscribe());
    const ClientAction action = handleClientMessage(bytesOf(m), true);
    ASSERT_TRUE(std::holds_alternative<ReplyAction>(action));
    EXPECT_FALSE(std::get<ReplyAction>(action).reply.ok());
    EXPECT_FALSE(std::get<ReplyAction>(action).reply.message().empty());
  }
}

ClientMessage cubemapSubscribe(std::uint32_t facePx, double rateHz) {
  ClientMessage m;
  m.set_request_id(5);
  m.mutable_subscribe()->set_lights(true);
  m.mutable_subscribe()->set_cubemap_face_px(facePx);
  m.mutable_subscribe()->set_cubemap_rate_hz(rateHz);
  m.mutable_subscribe()->set_cubemap_levels(8);
  return m;
}

// Issue 16, item 1: a read-only client asking for 512 px at 60 Hz starved processing.
TEST(ClientMessageHandler, ReadOnlyClientOverTheCubemapBudgetIsRefusedNamingTheCap) {
  const CubemapBudget budget{256, 10.0};
  const ClientAction big = handleClientMessage(bytesOf(cubemapSubscribe(512, 5.0)), false, budget);
  ASSERT_TRUE(std::holds_alternative<ReplyAction>(big));
  EXPECT_FALSE(std::get<ReplyAction>(big).reply.ok());
  EXPECT_EQ(std::get<ReplyAction>(big).reply.message(),
            "cubemap_face_px 512 is over the 256 this daemon allows clients without the token");
  const ClientAction often =
      handleClientMessage(bytesOf(cubemapSubscribe(128, 60.0)), false, budget);
  ASSERT_TRUE(std::holds_alternative<ReplyAction>(often));
  EXPECT_EQ(std::get<ReplyAction>(often).reply.message(),
            "cubemap_rate_hz 60 is over the 10 this daemon allows clients without the token");
  const ClientAction within =
      handleClientMessage(bytesOf(cubemapSubscribe(256, 10.0)), false, budget);
  ASSERT_TRUE(std::holds_alternative<SubscribeAction>(within));
  EXPECT_EQ(std::get<SubscribeAction>(within).subscription.cube.facePx, 256);
}

TEST(ClientMessageHandler, ClientWithTheTokenMayAskForTheProtocolsLimits) {
  const CubemapBudget budget{256, 10.0};
  const ClientAction action =
      handleClientMessage(bytesOf(cubemapSubscribe(512, 60.0)), true, budget);
  ASSERT_TRUE(std::holds_alternative<SubscribeAction>(action));
  EXPECT_EQ(std::get<SubscribeAction>(action).subscription.cube.facePx, 512);
  EXPECT_DOUBLE_EQ(std::get<SubscribeAction>(action).subscription.cubemapRateHz, 60.0);
}

// Issue 16, item 6: this name forged a log line and made a file with a newline in its name.
TEST(ClientMessageHandler, RecordingNameWithANewlineIsRefusedBeforeItReachesTheRecorder) {
  ClientMessage m;
  m.set_request_id(9);
  m.mutable_control()->mutable_start_recording()->set_name("evil\nvemd info: FAKE LINE.vem");
  const ClientAction action = handleClientMessage(bytesOf(m), true);
  ASSERT_TRUE(std::holds_alternative<ReplyAction>(action));
  EXPECT_EQ(std::get<ReplyAction>(action).reply.message(),
            "the recording name may hold only ASCII letters, digits, '.', '_' and '-'");
}

TEST(ClientMessageHandler, RecordingNamesOutsideTheStatedSetAreRefused) {
  for (const char* bad : {"a b.vem", "../x.vem", "x/y", ".hidden.vem", "-rf.vem", "take.txt",
                          "caf\xc3\xa9.vem", "tab\there", "nul\x01"}) {
    EXPECT_NE(recordingNameProblem(bad), "") << bad;
  }
  EXPECT_NE(recordingNameProblem(std::string(129, 'a')), "");
  for (const char* good : {"", "take-1", "take_2.vem", "Stage.B.2026-12-03.vem", "x"}) {
    EXPECT_EQ(recordingNameProblem(good), "") << good;
  }
  EXPECT_EQ(recordingNameProblem(std::string(128, 'a')), "");
}

TEST(ClientMessageHandler, EmptyBodyIsAnsweredNotClosed) {
  ClientMessage m;
  m.set_request_id(3);
  const ClientAction action = handleClientMessage(bytesOf(m), true);
  ASSERT_TRUE(std::holds_alternative<ReplyAction>(action));
  EXPECT_EQ(std::get<ReplyAction>(action).reply.request_id(), 3u);
}

TEST(HandshakeAuth, TokenFromHeaderOrQuery) {
  EXPECT_EQ(bearerToken("Bearer abc"), "abc");
  EXPECT_EQ(bearerToken("bearer  abc "), "abc");
  EXPECT_EQ(bearerToken("Basic abc"), std::nullopt);
  EXPECT_EQ(bearerToken("Bearer "), std::nullopt);
  EXPECT_EQ(queryToken("/?token=a%2Fb"), "a/b");
  EXPECT_EQ(queryToken("/stream?x=1&token=t"), "t");
  EXPECT_EQ(queryToken("/stream?tokens=t"), std::nullopt);
}

TEST(HandshakeAuth, WrongTokenIsRefusedRightTokenAllowsControl) {
  const AuthPolicy policy{"secret", false};
  EXPECT_FALSE(decideHandshake(policy, std::string("secreT")).accept);
  EXPECT_FALSE(decideHandshake(policy, std::string("secret2")).accept);
  const HandshakeDecision right = decideHandshake(policy, std::string("secret"));
  EXPECT_TRUE(right.accept);
  EXPECT_TRUE(right.controlAllowed);
}

TEST(HandshakeAuth, MissingTokenOnLoopbackConnectsWithoutControl) {
  const HandshakeDecision loopback = decideHandshake({"secret", false}, std::nullopt);
  EXPECT_TRUE(loopback.accept);
  EXPECT_FALSE(loopback.controlAllowed);
  EXPECT_FALSE(decideHandshake({"secret", true}, std::nullopt).accept);
}

TEST(HandshakeAuth, AnyTokenIsWrongWhenNoneIsConfigured) {
  EXPECT_FALSE(decideHandshake({"", false}, std::string("")).accept);
  EXPECT_FALSE(decideHandshake({"", false}, std::string("x")).accept);
}

SharedBytes bytes(const char* text) { return std::make_shared<const std::string>(text); }

TEST(Outbox, ReplacingAnUnsentLightFrameCountsASkip) {
  Outbox outbox;
  outbox.putLights(bytes("1"));
  outbox.putLights(bytes("2"));
  outbox.putLights(bytes("3"), 4);
  EXPECT_EQ(outbox.skippedLights(), 6u);
  EXPECT_EQ(*outbox.next(), "3");
  EXPECT_EQ(outbox.next(), nullptr);
}

TEST(Outbox, RepliesFirstAndStatusNotStarvedByLights) {
  Outbox outbox;
  outbox.putLights(bytes("L1"));
  outbox.putStatus(bytes("S"));
  ASSERT_TRUE(outbox.putReply(bytes("R")));
  EXPECT_EQ(*outbox.next(), "R");
  EXPECT_EQ(*outbox.next(), "L1");
  outbox.putLights(bytes("L2"));
  EXPECT_EQ(*outbox.next(), "S");
  EXPECT_EQ(*outbox.next(), "L2");
}

TEST(Outbox, RepliesAreBounded) {
  Outbox outbox;
  for (std::size_t i = 0; i < Outbox::kMaxReplies; ++i) ASSERT_TRUE(outbox.putReply(bytes("r")));
  EXPECT_FALSE(outbox.putReply(bytes("r")));
}

TEST(CubemapDemand, DistinctVariantsAtTheFastestRate) {
  Subscription lightsOnly;
  Subscription a;
  a.cubemapRateHz = 5.0;
  Subscription b = a;
  b.cubemapRateHz = 20.0;
  Subscription c = a;
  c.cube.preview = true;
  const std::vector<Subscription> all{lightsOnly, a, b, c};
  const CubemapDemand demand = cubemapDemand(all);
  ASSERT_EQ(demand.variants.size(), 2u);
  EXPECT_DOUBLE_EQ(demand.variants[0].rateHz, 20.0);
  EXPECT_DOUBLE_EQ(demand.variants[1].rateHz, 5.0);
  EXPECT_FALSE(cubemapDemand(std::vector<Subscription>{lightsOnly}).any());
}

}  // namespace
}  // namespace vem::stream
