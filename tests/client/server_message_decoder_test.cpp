// The client's decoder refuses every message the protocol forbids, with one sentence, and decodes
// valid ones exactly (client/server_message_decoder.h).
#include "client/server_message_decoder.h"

#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>
#include <zstd.h>

#include "client/stream_test_messages.h"
#include "proto/stream_protocol.h"
#include "proto/texel_packing.h"

namespace vem::client {
namespace {

using test::bytesOf;
using test::environmentMessage;
using test::lightFrameMessage;

DecodeResult decode(const stream::ServerMessage& message) { return decodeServerMessage(bytesOf(message)); }

void expectRefused(const DecodeResult& result, const std::string& fragment) {
  EXPECT_FALSE(result.ok());
  EXPECT_NE(result.error.find(fragment), std::string::npos) << result.error;
  EXPECT_TRUE(std::holds_alternative<Ignored>(result.event));
}

TEST(ServerMessageDecoder, RefusesUnknownMajorWithTheSentence) {
  const DecodeResult result = decodeServerMessage(bytesOf(lightFrameMessage(1), 2));
  EXPECT_EQ(result.error, "protocol major version 2 is not supported (this client speaks 1)");
  EXPECT_TRUE(result.unsupportedMajor);
}

TEST(ServerMessageDecoder, RefusesAMessageWithoutMajor) {
  const DecodeResult result = decodeServerMessage(bytesOf(lightFrameMessage(1), 0));
  EXPECT_EQ(result.error, "protocol major version 0 is not supported (this client speaks 1)");
}

TEST(ServerMessageDecoder, AcceptsANewerMinor) {
  const DecodeResult result = decodeServerMessage(bytesOf(lightFrameMessage(1), 1, 9));
  EXPECT_TRUE(result.ok()) << result.error;
  EXPECT_TRUE(std::holds_alternative<LightFrame>(result.event));
}

TEST(ServerMessageDecoder, IgnoresABodyFromANewerMinor) {
  const DecodeResult result = decode(stream::ServerMessage{});
  EXPECT_TRUE(result.ok()) << result.error;
  EXPECT_TRUE(std::holds_alternative<Ignored>(result.event));
}

TEST(ServerMessageDecoder, RefusesBytesThatAreNotAServerMessage) {
  expectRefused(decodeServerMessage(std::string("\xff\xff\xff\xff\x0f garbage", 14)),
                "not a vem.stream.ServerMessage");
}

TEST(ServerMessageDecoder, RefusesAMessageOverTheSizeLimit) {
  const std::string huge(stream::kMaxServerMessageBytes + 1, '\0');
  expectRefused(decodeServerMessage(huge), "over the limit");
}

TEST(ServerMessageDecoder, RefusesNaNDirection) {
  stream::ServerMessage message = lightFrameMessage(1);
  message.mutable_lights()->set_dirs(4, std::numeric_limits<float>::quiet_NaN());
  expectRefused(decode(message), "light 1 (id 1) has a non-finite direction");
}

TEST(ServerMessageDecoder, RefusesInfiniteRgb) {
  stream::ServerMessage message = lightFrameMessage(1);
  message.mutable_lights()->set_rgb(2, std::numeric_limits<float>::infinity());
  expectRefused(decode(message), "light 0 (id 0)'s rgb");
}

TEST(ServerMessageDecoder, RefusesNaNLuminance) {
  stream::ServerMessage message = lightFrameMessage(1);
  message.mutable_lights()->set_total_luminance_sr(std::nan(""));
  expectRefused(decode(message), "total_luminance_sr");
}

TEST(ServerMessageDecoder, RefusesNonUnitDirection) {
  stream::ServerMessage message = lightFrameMessage(1);
  message.mutable_lights()->set_dirs(6, message.lights().dirs(6) * 1.002F);
  message.mutable_lights()->set_dirs(8, message.lights().dirs(8) * 1.002F);
  expectRefused(decode(message), "light 2 (id 2)'s direction");
}

TEST(ServerMessageDecoder, AcceptsDirectionsWithinTheTolerance) {
  stream::ServerMessage message = lightFrameMessage(1);
  message.mutable_lights()->set_dirs(0, message.lights().dirs(0) * 1.0009F);
  EXPECT_TRUE(decode(message).ok());
}

TEST(ServerMessageDecoder, RefusesNegativeRgb) {
  stream::ServerMessage message = lightFrameMessage(1);
  message.mutable_lights()->set_rgb(4, -0.001F);
  expectRefused(decode(message), "light 1 (id 1)'s rgb");
}

TEST(ServerMessageDecoder, RefusesDirsLengthMismatch) {
  stream::ServerMessage message = lightFrameMessage(1);
  message.mutable_lights()->add_dirs(0.0F);
  expectRefused(decode(message), "3 ids but 10 dirs");
}

TEST(ServerMessageDecoder, RefusesRgbLengthMismatch) {
  stream::ServerMessage message = lightFrameMessage(1);
  message.mutable_lights()->mutable_rgb()->RemoveLast();
  expectRefused(decode(message), "8 rgb values");
}

TEST(ServerMessageDecoder, RefusesMoreLightsThanTheLimit) {
  stream::ServerMessage message = lightFrameMessage(1, int(stream::kMaxLights) + 1);
  expectRefused(decode(message), "65537 lights, more than the limit");
}

TEST(ServerMessageDecoder, RefusesAClusterMembershipOutOfRange) {
  stream::ServerMessage message = lightFrameMessage(1);
  stream::Clusters& clusters = *message.mutable_lights()->mutable_clusters();
  clusters.set_radius_rad(0.2);
  for (float v : {0.0F, 1.0F, 0.0F}) clusters.add_dirs(v);
  for (float v : {1.0F, 1.0F, 1.0F}) clusters.add_rgb(v);
  for (std::uint32_t m : {0U, 0U, 1U}) clusters.add_member_of(m);
  expectRefused(decode(message), "light 2 is a member of cluster 1, but there are 1 clusters");
}

TEST(ServerMessageDecoder, RefusesAClusterMembershipOfTheWrongLength) {
  stream::ServerMessage message = lightFrameMessage(1);
  stream::Clusters& clusters = *message.mutable_lights()->mutable_clusters();
  for (float v : {0.0F, 1.0F, 0.0F}) clusters.add_dirs(v);
  for (float v : {1.0F, 1.0F, 1.0F}) clusters.add_rgb(v);
  clusters.add_member_of(0);
  expectRefused(decode(message), "member_of has 1 entries for 3 lights");
}

TEST(ServerMessageDecoder, RefusesLyingRawBytesBeforeAllocating) {
  stream::ServerMessage message = environmentMessage(1, 8, 1);
  message.mutable_environment()->set_raw_bytes(std::uint64_t(1) << 50);
  expectRefused(decode(message), "raw_bytes is 1125899906842624");
}

TEST(ServerMessageDecoder, RefusesRawBytesThatMissALevel) {
  stream::ServerMessage message = environmentMessage(1, 16, 2);
  message.mutable_environment()->set_raw_bytes(stream::cubeRawBytes(16, 1));
  expectRefused(decode(message), "raw_bytes");
}

TEST(ServerMessageDecoder, RefusesAFaceOverTheLimit) {
  stream::ServerMessage message = environmentMessage(1, 8, 1);
  message.mutable_environment()->set_face_px(stream::kMaxCubeFacePx * 2);
  message.mutable_environment()->set_raw_bytes(stream::cubeRawBytes(stream::kMaxCubeFacePx * 2, 1));
  expectRefused(decode(message), "face_px is 1024");
}

TEST(ServerMessageDecoder, RefusesLevelsThatDoNotHalveExactly) {
  stream::ServerMessage message = environmentMessage(1, 12, 3);
  message.mutable_environment()->set_levels(4);
  message.mutable_environment()->set_raw_bytes(stream::cubeRawBytes(12, 4));
  expectRefused(decode(message), "4 levels do not fit a face of 12 px");
}

TEST(ServerMessageDecoder, RefusesTexelsThatDecompressToTheWrongSize) {
  stream::ServerMessage message = environmentMessage(1, 8, 1);
  message.mutable_environment()->set_texels_zstd(
      stream::packTexels(test::testTexels(8, 2), 3));  // two levels' texels for one level
  expectRefused(decode(message), "texels are unusable");
}

TEST(ServerMessageDecoder, RefusesCorruptTexels) {
  stream::ServerMessage message = environmentMessage(1, 8, 1);
  std::string texels = message.environment().texels_zstd();
  texels.resize(texels.size() / 2);
  message.mutable_environment()->set_texels_zstd(texels);
  expectRefused(decode(message), "texels are unusable");
}

TEST(ServerMessageDecoder, RefusesNonFiniteTexels) {
  std::string halves(stream::cubeRawBytes(8, 1), '\0');
  halves[7] = '\x7c';  // texel value 3: half 0x7C00, +infinity
  std::string zstd(ZSTD_compressBound(halves.size()), '\0');
  zstd.resize(ZSTD_compress(zstd.data(), zstd.size(), halves.data(), halves.size(), 1));
  stream::ServerMessage message = environmentMessage(1, 8, 1);
  message.mutable_environment()->set_texels_zstd(zstd);
  expectRefused(decode(message), "texel value 3 is inf");
}

TEST(ServerMessageDecoder, RefusesAPreviewWhoseBytesDisagreeWithItsSize) {
  stream::ServerMessage message = environmentMessage(1, 8, 1);
  stream::PolarPreview& preview = *message.mutable_environment()->mutable_preview();
  preview.set_width_px(4);
  preview.set_height_px(2);
  preview.set_srgb8(std::string(23, '\x10'));
  expectRefused(decode(message), "preview of 4 x 2 px holds 23 bytes, not 24");
}

TEST(ServerMessageDecoder, DecodesALightFrameExactly) {
  stream::ServerMessage message = lightFrameMessage(42, 3);
  stream::Clusters& clusters = *message.mutable_lights()->mutable_clusters();
  clusters.set_radius_rad(0.25);
  for (float v : {0.0F, 0.0F, -1.0F, 1.0F, 0.0F, 0.0F}) clusters.add_dirs(v);
  for (float v : {1.0F, 2.0F, 3.0F, 4.0F, 5.0F, 6.0F}) clusters.add_rgb(v);
  for (std::uint32_t m : {1U, 0U, 1U}) clusters.add_member_of(m);
  const DecodeResult result = decode(message);
  ASSERT_TRUE(result.ok()) << result.error;
  const LightFrame& frame = std::get<LightFrame>(result.event);
  const stream::LightFrame& in = message.lights();
  EXPECT_EQ(frame.seq, 42U);
  EXPECT_EQ(frame.lightsSeq, 38U);
  EXPECT_EQ(frame.captureTsNs, in.capture_ts_ns());
  EXPECT_EQ(frame.captureUnixNs, in.capture_unix_ns());
  EXPECT_EQ(frame.publishUnixNs, in.publish_unix_ns());
  EXPECT_EQ(frame.status, SourceState::Ok);
  EXPECT_TRUE(frame.filtered);
  EXPECT_EQ(frame.filterDelayFrames, 4.0);
  EXPECT_EQ(frame.lights.luminanceSr, 12.5);
  EXPECT_FALSE(frame.lights.black);
  ASSERT_EQ(frame.lights.lights.size(), 3U);
  for (int i = 0; i < 3; ++i) {
    const Light& light = frame.lights.lights[std::size_t(i)];
    EXPECT_EQ(light.id, in.ids(i));
    EXPECT_EQ(light.dir, glm::vec3(in.dirs(3 * i), in.dirs(3 * i + 1), in.dirs(3 * i + 2)));
    EXPECT_EQ(light.rgb, glm::vec3(in.rgb(3 * i), in.rgb(3 * i + 1), in.rgb(3 * i + 2)));
  }
  ASSERT_TRUE(frame.clusters.has_value());
  EXPECT_EQ(frame.clusters->radiusRad, 0.25);
  ASSERT_EQ(frame.clusters->clusters.size(), 2U);
  EXPECT_EQ(frame.clusters->clusters[1].dir, glm::vec3(1.0F, 0.0F, 0.0F));
  EXPECT_EQ(frame.clusters->clusters[1].rgb, glm::vec3(4.0F, 5.0F, 6.0F));
  EXPECT_EQ(frame.clusters->memberOf, (std::vector<std::uint32_t>{1, 0, 1}));
}

TEST(ServerMessageDecoder, DecodesAnEnvironmentFrameExactly) {
  stream::ServerMessage message = environmentMessage(7, 16, 3);
  stream::PolarPreview& preview = *message.mutable_environment()->mutable_preview();
  preview.set_width_px(2);
  preview.set_height_px(1);
  preview.set_srgb8("abcdef");
  const DecodeResult result = decode(message);
  ASSERT_TRUE(result.ok()) << result.error;
  const EnvironmentFrame& frame = std::get<EnvironmentFrame>(result.event);
  EXPECT_EQ(frame.seq, 7U);
  EXPECT_EQ(frame.publishUnixNs, message.environment().publish_unix_ns());
  EXPECT_EQ(frame.rawBytes, stream::cubeRawBytes(16, 3));
  EXPECT_EQ(frame.compressedBytes, message.environment().texels_zstd().size());
  ASSERT_EQ(frame.cube.levels.size(), 3U);
  // The texels in order: level 0's faces +X..-Z, then level 1's...; the test values are exact halves.
  const std::vector<float> texels = test::testTexels(16, 3);
  std::size_t at = 0;
  for (int k = 0; k < 3; ++k) {
    const CubeMapLevel& level = frame.cube.levels[std::size_t(k)];
    EXPECT_EQ(level.facePx, 16 >> k);
    for (const std::vector<float>& face : level.faces) {
      ASSERT_EQ(face.size(), std::size_t(level.facePx * level.facePx * 3));
      for (float value : face) ASSERT_EQ(value, texels[at++]) << "at " << at;
    }
  }
  EXPECT_EQ(at, texels.size());
  ASSERT_TRUE(frame.preview.has_value());
  EXPECT_EQ(frame.preview->srgb8, "abcdef");
}

TEST(ServerMessageDecoder, MultipliesTheTexelsByTheTexelScaleSoASunBeyondTheHalfRangeSurvives) {
  stream::ServerMessage message = environmentMessage(7, 8, 2);
  message.mutable_environment()->set_texel_scale(1024.0F);
  const DecodeResult result = decode(message);
  ASSERT_TRUE(result.ok()) << result.error;
  const EnvironmentFrame& frame = std::get<EnvironmentFrame>(result.event);
  const std::vector<float> texels = test::testTexels(8, 2);
  std::size_t at = 0;
  for (const CubeMapLevel& level : frame.cube.levels) {
    for (const std::vector<float>& face : level.faces) {
      for (float value : face) ASSERT_EQ(value, texels[at++] * 1024.0F) << "at " << at;
    }
  }
  EXPECT_EQ(at, texels.size());
}

TEST(ServerMessageDecoder, RefusesATexelScaleThatIsNotAPowerOfTwoAtLeastOne) {
  for (float scale : {3.0F, 0.5F, -2.0F, std::numeric_limits<float>::infinity(),
                      std::numeric_limits<float>::quiet_NaN()}) {
    stream::ServerMessage message = environmentMessage(1, 8, 1);
    message.mutable_environment()->set_texel_scale(scale);
    expectRefused(decode(message), "not a power of two >= 1");
  }
}

TEST(ServerMessageDecoder, DecodesHelloStatusAndReply) {
  const DecodeResult hello = decode(test::helloMessage(true));
  ASSERT_TRUE(hello.ok()) << hello.error;
  EXPECT_EQ(std::get<Hello>(hello.event).server, "fixture 1.0");
  EXPECT_TRUE(std::get<Hello>(hello.event).controlAllowed);

  stream::ServerMessage status;
  status.mutable_status()->set_frame_rate_hz(29.97);
  status.mutable_status()->set_skipped_for_you(5);
  status.mutable_status()->set_state(stream::SOURCE_STATE_NO_DEVICE);
  const DecodeResult s = decode(status);
  ASSERT_TRUE(s.ok()) << s.error;
  EXPECT_EQ(std::get<Status>(s.event).frameRateHz, 29.97);
  EXPECT_EQ(std::get<Status>(s.event).skippedForYou, 5U);
  EXPECT_EQ(std::get<Status>(s.event).state, SourceState::NoDevice);

  stream::ServerMessage reply;
  reply.mutable_reply()->set_request_id(9);
  reply.mutable_reply()->set_message("no such filter");
  const DecodeResult r = decode(reply);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(std::get<ControlReply>(r.event).requestId, 9U);
  EXPECT_FALSE(std::get<ControlReply>(r.event).ok);
  EXPECT_EQ(std::get<ControlReply>(r.event).message, "no such filter");
}

TEST(ServerMessageDecoder, RefusesANonFiniteStatusRate) {
  stream::ServerMessage status;
  status.mutable_status()->set_frame_rate_hz(std::numeric_limits<double>::infinity());
  expectRefused(decode(status), "frame_rate_hz");
}

}  // namespace
}  // namespace vem::client
