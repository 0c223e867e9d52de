// Frame encoding: light frames carry exactly the published lights (the JSON-lines sink's rule),
// environment frames carry the cube map's levels in order, serialize() stamps version 1.0, and the
// polar preview is oriented as documented.
#include "stream/frame_encoding.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <cstddef>
#include <numbers>

#include <glm/geometric.hpp>

#include "core/cube_map.h"
#include "proto/stream_protocol.h"
#include "proto/texel_packing.h"

namespace vem::stream {
namespace {

LightSet makeSet(std::uint32_t count, float scale) {
  LightSet set;
  for (std::uint32_t i = 0; i < count; ++i) {
    const double theta = 0.2 + 0.3 * i;
    const double phi = 1.1 * i;
    set.lights.push_back({i, glm::vec3(directionFromAngles(theta, phi)),
                          glm::vec3(scale * float(i + 1), 2.0F * scale, 0.5F)});
  }
  set.luminanceSr = 12.5 * double(scale);
  return set;
}

struct Fixture {
  vem::CapturedFrame captured;
  vem::ProcessedFrame frame;
  Fixture() {
    captured.seq = 100;
    captured.captureTsNs = 123456789;
    frame.captured = &captured;
    frame.lights = makeSet(3, 1.0F);
  }
};

LightFrameStamp stamp() {
  return {1'700'000'000'000'000'001, 1'700'000'000'002'000'001, SOURCE_STATE_OK, 4.0};
}

void expectLights(const LightFrame& out, const LightSet& set) {
  ASSERT_EQ(out.ids_size(), int(set.lights.size()));
  ASSERT_EQ(out.dirs_size(), 3 * out.ids_size());
  ASSERT_EQ(out.rgb_size(), 3 * out.ids_size());
  for (int i = 0; i < out.ids_size(); ++i) {
    const Light& light = set.lights[std::size_t(i)];
    EXPECT_EQ(out.ids(i), light.id);
    const glm::vec3 dir{out.dirs(3 * i), out.dirs(3 * i + 1), out.dirs(3 * i + 2)};
    EXPECT_EQ(dir, light.dir);
    EXPECT_NEAR(glm::length(dir), 1.0F, 1e-6F);
    EXPECT_EQ(glm::vec3(out.rgb(3 * i), out.rgb(3 * i + 1), out.rgb(3 * i + 2)), light.rgb);
  }
  EXPECT_DOUBLE_EQ(out.total_luminance_sr(), set.luminanceSr);
  EXPECT_EQ(out.black(), set.black);
}

TEST(FrameEncoding, LightFrameCarriesTheFilteredSetNotTheRawOneWhenPresent) {
  Fixture f;
  f.frame.filtered = makeSet(5, 3.0F);
  f.frame.filteredSeq = 96;
  const ServerMessage message = lightFrameMessage(f.frame, stamp());
  ASSERT_TRUE(message.has_lights());
  const LightFrame& out = message.lights();
  expectLights(out, *f.frame.filtered);
  EXPECT_TRUE(out.filtered());
  EXPECT_EQ(out.seq(), 100U);
  EXPECT_EQ(out.lights_seq(), 96U);
  EXPECT_FALSE(out.has_clusters());
}

TEST(FrameEncoding, LightFrameCarriesTheFramesOwnLightsAndTimesWithoutFilter) {
  Fixture f;
  f.frame.lights.black = true;
  const LightFrameStamp s{11, 22, SOURCE_STATE_NO_SIGNAL, 0.0};
  const LightFrame out = lightFrameMessage(f.frame, s).lights();
  expectLights(out, f.frame.lights);
  EXPECT_FALSE(out.filtered());
  EXPECT_EQ(out.seq(), 100U);
  EXPECT_EQ(out.lights_seq(), 100U);
  EXPECT_EQ(out.capture_ts_ns(), 123456789);
  EXPECT_EQ(out.capture_unix_ns(), 11);
  EXPECT_EQ(out.publish_unix_ns(), 22);
  EXPECT_EQ(out.status(), SOURCE_STATE_NO_SIGNAL);
  EXPECT_DOUBLE_EQ(out.filter_delay_frames(), 0.0);
}

TEST(FrameEncoding, LightFrameCarriesTheClusteringOfThePublishedSet) {
  Fixture f;
  f.frame.filtered = makeSet(4, 1.0F);
  f.frame.filteredSeq = 96;
  Clustering clustering;
  clustering.clusters = makeSet(2, 7.0F);
  clustering.clusterOfLight = {0, 0, 1, 1};
  clustering.radiusRad = 0.25;
  f.frame.clustering = clustering;
  const LightFrame out = lightFrameMessage(f.frame, stamp()).lights();
  EXPECT_DOUBLE_EQ(out.filter_delay_frames(), 4.0);
  ASSERT_TRUE(out.has_clusters());
  const Clusters& clusters = out.clusters();
  EXPECT_DOUBLE_EQ(clusters.radius_rad(), 0.25);
  ASSERT_EQ(clusters.dirs_size(), 6);
  ASSERT_EQ(clusters.rgb_size(), 6);
  for (int c = 0; c < 2; ++c) {
    const Light& cluster = clustering.clusters.lights[std::size_t(c)];
    EXPECT_EQ(glm::vec3(clusters.dirs(3 * c), clusters.dirs(3 * c + 1), clusters.dirs(3 * c + 2)),
              cluster.dir);
    EXPECT_EQ(glm::vec3(clusters.rgb(3 * c), clusters.rgb(3 * c + 1), clusters.rgb(3 * c + 2)),
              cluster.rgb);
  }
  ASSERT_EQ(clusters.member_of_size(), 4);
  for (int i = 0; i < 4; ++i)
    EXPECT_EQ(clusters.member_of(i), clustering.clusterOfLight[std::size_t(i)]);
}

TEST(FrameEncoding, ClusteringOfAnotherSetIsLeftOutRatherThanMisattributed) {
  Fixture f;  // 3 published lights, a clustering of 4
  Clustering clustering;
  clustering.clusters = makeSet(1, 1.0F);
  clustering.clusterOfLight = {0, 0, 0, 0};
  f.frame.clustering = clustering;
  EXPECT_FALSE(lightFrameMessage(f.frame, stamp()).lights().has_clusters());
}

TEST(FrameEncoding, SerializeStampsThisBuildsProtocolVersion) {
  Fixture f;
  const std::string bytes = serialize(lightFrameMessage(f.frame, stamp()));
  ServerMessage parsed;
  ASSERT_TRUE(parsed.ParseFromString(bytes));
  EXPECT_EQ(parsed.protocol_major(), 1U);
  EXPECT_EQ(parsed.protocol_minor(), 1U);
  EXPECT_EQ(parsed.protocol_major(), kProtocolMajor);
  ASSERT_TRUE(parsed.has_lights());
  EXPECT_EQ(parsed.lights().ids_size(), 3);
}

TEST(FrameEncoding, EnvironmentFrameHoldsEveryLevelsFacesInOrder) {
  EnvMap map = EnvMap::filled(MapLayout::Hemisphere, 128, 32, glm::vec3(0.0F));
  for (int y = 0; y < map.height; ++y) {
    for (int x = 0; x < map.width; ++x)
      map.set(x, y, glm::vec3(float(1 + x), float(1 + y), 100.0F));
  }
  const CubeMap cube = cubeMapFromEnvMap(map, 16, 3);
  const ServerMessage message = environmentFrameMessage(cube, 77, 55, 66, 3);
  ASSERT_TRUE(message.has_environment());
  const EnvironmentFrame& out = message.environment();
  EXPECT_EQ(out.seq(), 77U);
  EXPECT_EQ(out.capture_ts_ns(), 55);
  EXPECT_EQ(out.publish_unix_ns(), 66);
  EXPECT_EQ(out.face_px(), 16U);
  EXPECT_EQ(out.levels(), 3U);
  EXPECT_EQ(out.raw_bytes(), cubeRawBytes(16, 3));
  EXPECT_FALSE(out.has_preview());
  const UnpackResult unpacked = unpackTexels(out.texels_zstd(), out.raw_bytes());
  ASSERT_TRUE(unpacked.ok()) << unpacked.error;
  std::size_t i = 0;
  for (const CubeMapLevel& level : cube.levels) {
    for (const std::vector<float>& face : level.faces) {
      for (const float v : face) {
        ASSERT_NEAR(unpacked.rgb[i], v, 1e-3 * double(std::abs(v))) << "value " << i;
        ++i;
      }
    }
  }
  EXPECT_EQ(i, unpacked.rgb.size());
}

TEST(FrameEncoding, SunBeyondTheHalfRangeSurvivesThroughTheTexelScale) {
  CubeMap cube = cubeMapFromEnvMap(EnvMap::filled(MapLayout::Sphere, 16, 8, glm::vec3(1.0F)), 8, 1);
  cube.levels[0].faces[2][0] = 1.6e9F;  // the sun in cd/m^2, 1.6e9 times the sky
  std::size_t clamped = 0;
  const ServerMessage message = environmentFrameMessage(cube, 1, 0, 0, 3, &clamped);
  EXPECT_EQ(clamped, 0U);
  const float scale = message.environment().texel_scale();
  EXPECT_GE(scale, 1.6e9F / kMaxHalf);
  EXPECT_EQ(scale, std::exp2(std::round(std::log2(scale))));  // a power of two: exact division
  const UnpackResult unpacked =
      unpackTexels(message.environment().texels_zstd(), message.environment().raw_bytes());
  ASSERT_TRUE(unpacked.ok());
  const std::size_t sun = 2 * 8 * 8 * 3;
  EXPECT_NEAR(unpacked.rgb[sun] * scale, 1.6e9, 1.6e9 * 1e-3);
  EXPECT_NEAR(unpacked.rgb[sun + 1] * scale, 1.0, 2e-3);  // the sky next to it keeps its precision
}

TEST(FrameEncoding, OrdinaryMapIsSentWithTexelScaleOne) {
  const CubeMap cube =
      cubeMapFromEnvMap(EnvMap::filled(MapLayout::Sphere, 16, 8, glm::vec3(3000.0F)), 8, 1);
  EXPECT_EQ(environmentFrameMessage(cube, 1, 0, 0, 3).environment().texel_scale(), 1.0F);
}

TEST(FrameEncoding, InfiniteTexelIsClampedAndCountedNotSentAsInfinity) {
  CubeMap cube = cubeMapFromEnvMap(EnvMap::filled(MapLayout::Sphere, 16, 8, glm::vec3(1.0F)), 8, 1);
  cube.levels[0].faces[0][0] = std::numeric_limits<float>::infinity();
  std::size_t clamped = 0;
  const ServerMessage message = environmentFrameMessage(cube, 1, 0, 0, 3, &clamped);
  EXPECT_EQ(clamped, 1U);
  const UnpackResult unpacked =
      unpackTexels(message.environment().texels_zstd(), message.environment().raw_bytes());
  ASSERT_TRUE(unpacked.ok());
  EXPECT_EQ(unpacked.rgb[0], kMaxHalf);
}

// The preview's byte at (column, row), red channel.
int red(const PolarPreview& preview, int column, int row) {
  return static_cast<unsigned char>(
      preview.srgb8()[3 * std::size_t(row * int(preview.width_px()) + column)]);
}

TEST(FrameEncoding, PolarPreviewPutsTheZenithInTheCentreAndPlusXRightPlusZDown) {
  EnvMap map = EnvMap::filled(MapLayout::Hemisphere, 256, 64, glm::vec3(0.01F));
  const auto brighten = [&map](glm::dvec3 dir) {
    for (int y = 0; y < map.height; ++y) {
      for (int x = 0; x < map.width; ++x) {
        if (glm::dot(pixelCentreDirection(map, x, y), dir) > std::cos(0.15))
          map.set(x, y, glm::vec3(50.0F));
      }
    }
  };
  brighten({0, 1, 0});
  brighten(directionFromAngles(1.2, 0.0));                   // +X, above the horizon
  brighten(directionFromAngles(1.2, std::numbers::pi / 2));  // +Z
  ServerMessage message = environmentFrameMessage(cubeMapFromEnvMap(map, 8, 1), 1, 0, 0, 3);
  constexpr int kWidth = 64;
  attachPolarPreview(message, map, kWidth);
  ASSERT_TRUE(message.environment().has_preview());
  const PolarPreview& preview = message.environment().preview();
  ASSERT_EQ(preview.width_px(), std::uint32_t(kWidth));
  ASSERT_EQ(preview.height_px(), std::uint32_t(kWidth));
  ASSERT_EQ(preview.srgb8().size(), std::size_t(3 * kWidth * kWidth));
  const int r = int(std::lround(1.2 / (std::numbers::pi / 2) * kWidth / 2));
  const int centre = kWidth / 2;
  const int dim = red(preview, centre - r, centre);  // -X: not lit
  EXPECT_GT(red(preview, centre, centre), dim + 50);
  EXPECT_GT(red(preview, centre + r, centre), dim + 50);  // +X to the right
  EXPECT_GT(red(preview, centre, centre + r), dim + 50);  // +Z downward
  EXPECT_LT(red(preview, centre, centre - r), dim + 10);  // -Z upward: not lit
  EXPECT_EQ(red(preview, 0, 0), 0);                       // outside the disc
}

TEST(FrameEncoding, UnixNowIsOnTheRealtimeClock) {
  // After 2020-01-01 and before 2100: catches a steady (boot-relative) clock.
  EXPECT_GT(unixNowNs(), 1'577'836'800'000'000'000);
  EXPECT_LT(unixNowNs(), 4'102'444'800'000'000'000);
}

}  // namespace
}  // namespace vem::stream
