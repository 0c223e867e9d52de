// The coherence study's sequences (synth/map_sequences.h): a turn by whole pixels moves columns,
// a sub-pixel turn keeps every row's energy, the noise has the asked spread and is fresh per frame,
// the switch-on ramps only its cap, and a scene's sub-pixel sun keeps its power in the map.
#include "synth/map_sequences.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "core/color.h"
#include "support/test_maps.h"

namespace vem::synth {
namespace {

double rowSum(const EnvMap& map, int y) {
  double sum = 0.0;
  for (int x = 0; x < map.width; ++x) sum += luminance(map.at(x, y));
  return sum;
}

TEST(MapSequences, TurnByWholePixelsMovesColumnsTowardLargerAzimuth) {
  const EnvMap map = testing::proceduralSky(MapLayout::Hemisphere, 64, 16);
  const EnvMap turned = turnedMap(map, 3 * 360.0 / 64);  // three columns
  const EnvMap expected = testing::rotatedColumns(map, 3);
  for (std::size_t i = 0; i < map.rgb.size(); ++i)
    ASSERT_NEAR(turned.rgb[i], expected.rgb[i], 1e-6F);
  // And the motion matrix turns a pixel's direction onto where its content went.
  const glm::dvec3 before = pixelCentreDirection(map, 10, 5);
  const glm::dvec3 after = pixelCentreDirection(map, 13, 5);
  EXPECT_LT(glm::length(turnAboutUp(3 * 360.0 / 64) * before - after), 1e-9);
}

TEST(MapSequences, SubPixelTurnKeepsEachRowsEnergyAndBlendsNeighbours) {
  const EnvMap map = testing::hotPixelMap(MapLayout::Sphere, 32, 16, 5, 7, 100.0F, 1.0F);
  const EnvMap turned = turnedMap(map, 0.25 * 360.0 / 32);  // a quarter pixel
  for (int y = 0; y < map.height; ++y) EXPECT_NEAR(rowSum(turned, y), rowSum(map, y), 1e-3);
  EXPECT_NEAR(turned.at(5, 7).x, 0.75F * 100.0F + 0.25F * 1.0F, 1e-4F);
  EXPECT_NEAR(turned.at(6, 7).x, 0.25F * 100.0F + 0.75F * 1.0F, 1e-4F);
}

TEST(MapSequences, TurningSequenceCarriesTheTrueMotion) {
  const EnvMap map = testing::proceduralSky(MapLayout::Hemisphere, 64, 16);
  const auto frames = turningSequence(map, 0.25, 4);
  ASSERT_EQ(frames.size(), 4U);
  EXPECT_EQ(frames[0].map.rgb, map.rgb);
  for (int k = 1; k < 4; ++k) {
    const glm::dvec3 moved = frames[std::size_t(k)].motionFromPrevious * glm::dvec3(1, 0, 0);
    EXPECT_NEAR(std::atan2(moved.z, moved.x) * 180.0 / std::numbers::pi, 0.25, 1e-9);
  }
}

TEST(MapSequences, NoiseHasTheAskedSpreadAndIsFreshEachFrame) {
  const EnvMap map = EnvMap::filled(MapLayout::Hemisphere, 128, 32, glm::vec3(2.0F));
  const auto frames = noisySequence(map, 0.03, 2, 7);
  double sum = 0.0;
  double sumSq = 0.0;
  for (float v : frames[0].map.rgb) {
    const double r = double(v) / 2.0 - 1.0;
    sum += r;
    sumSq += r * r;
  }
  const double n = double(frames[0].map.rgb.size());  // 12288 samples
  EXPECT_NEAR(sum / n, 0.0, 5 * 0.03 / std::sqrt(n));
  EXPECT_NEAR(std::sqrt(sumSq / n), 0.03, 0.03 * 0.05);
  EXPECT_NE(frames[0].map.rgb, frames[1].map.rgb) << "the noise must be drawn anew each frame";
  EXPECT_EQ(noisySequence(map, 0.03, 2, 7)[1].map.rgb, frames[1].map.rgb)
      << "same seed, same noise";
}

TEST(MapSequences, SwitchOnRampsOnlyTheCapAroundTheBrightestPixel) {
  const EnvMap map = testing::hotPixelMap(MapLayout::Hemisphere, 64, 16, 20, 8, 50.0F, 1.0F);
  const auto frames = switchOnSequence(map, kSwitchOffFrames + kSwitchRampFrames + 2);
  const int off = kSwitchOffFrames;
  EXPECT_EQ(frames[0].map.at(20, 8).x, 0.0F);
  EXPECT_EQ(frames[std::size_t(off - 1)].map.at(20, 8).x, 0.0F);
  EXPECT_NEAR(frames[std::size_t(off)].map.at(20, 8).x, 50.0F / kSwitchRampFrames, 1e-4F);
  EXPECT_NEAR(frames[std::size_t(off + 4)].map.at(20, 8).x, 50.0F * 5 / kSwitchRampFrames, 1e-4F);
  EXPECT_EQ(frames.back().map.at(20, 8).x, 50.0F);
  // Far from the cap nothing changes, in any frame.
  for (const SequenceFrame& f : frames) EXPECT_EQ(f.map.at(52, 3).x, 1.0F);
}

// A scene of one bright disc, smaller than a pixel (1.4 degrees) and moving 0.1 degree per frame
// about +Y, over a dim sky.
constexpr double kDiscRadiusDeg = 0.3;
constexpr double kDiscDegPerFrame = 0.1;
constexpr double kRateHz = 30.0;

class MovingDiscScene final : public SyntheticScene {
 public:
  std::string name() const override { return "disc"; }
  SceneState at(double timeS) const override {
    SceneState s;
    const glm::dvec3 centre =
        turnAboutUp(kDiscDegPerFrame * timeS * kRateHz) * glm::normalize(glm::dvec3(0.3, 0.8, 0.2));
    s.radiance = [centre](const glm::dvec3& dir) {
      return glm::dot(dir, centre) > std::cos(kDiscRadiusDeg * std::numbers::pi / 180.0)
                 ? glm::dvec3(1e6)
                 : glm::dvec3(1.0);
    };
    return s;
  }
};

TEST(MapSequences, SceneMapKeepsAMovingSubPixelSunsPowerEveryFrame) {
  const MovingDiscScene scene;
  const auto frames = sceneSequence(scene, MapLayout::Hemisphere, 256, 64, kRateHz, 10);
  // The disc's power: 1e6 over its solid angle 2 pi (1 - cos r); the map's: the sum over pixels of
  // (value - 1) times the pixel's solid angle. With 4 x 4 samples per pixel it jumped by tens of
  // per cent from frame to frame as the disc crossed the samples.
  const double discSr =
      2 * std::numbers::pi * (1 - std::cos(kDiscRadiusDeg * std::numbers::pi / 180.0));
  for (const SequenceFrame& frame : frames) {
    const EnvMap& m = frame.map;
    double power = 0.0;
    for (int y = 0; y < m.height; ++y) {
      for (int x = 0; x < m.width; ++x)
        power += (double(m.at(x, y).x) - 1.0) * pixelSolidAngleSr(m.layout, m.width, m.height, y);
    }
    EXPECT_NEAR(power / (1e6 * discSr), 1.0, 0.02);
  }
}

}  // namespace
}  // namespace vem::synth
