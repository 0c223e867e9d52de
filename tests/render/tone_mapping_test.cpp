#include "client/render/tone_mapping.h"

#include <gtest/gtest.h>
#include <cmath>
#include <limits>

namespace vem::render {
namespace {

LinearImage uniformImage(float value, int w = 32, int h = 16) {
  LinearImage image = LinearImage::black(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      image.set(x, y, glm::vec3(value), true);
    }
  }
  return image;
}

TEST(ToneMapping, FirstFrameTakesItsOwnWorldLuminance) {
  ToneSmoother smoother(0.5);
  const ToneParams p = smoother.update(measureLuminance(uniformImage(4.0F)), 1.0 / 30);
  EXPECT_NEAR(p.worldLuminance, 4.0, 1e-4);
}

TEST(ToneMapping, SunAppearingDoesNotMakeTheNextFrameJump) {
  ToneSmoother smoother(0.5);
  (void)smoother.update(measureLuminance(uniformImage(1.0F)), 1.0 / 30);
  const ToneParams next = smoother.update(measureLuminance(uniformImage(1000.0F)), 1.0 / 30);
  // One frame of 1/30 s with tau 0.5 s moves log Lw by 1 - exp(-1/15) = 6.45 % of the way.
  EXPECT_NEAR(std::log(next.worldLuminance), 0.0645 * std::log(1000.0), 0.01);
  ToneParams settled = next;
  for (int i = 0; i < 150; ++i) {
    settled = smoother.update(measureLuminance(uniformImage(1000.0F)), 1.0 / 30);
  }
  EXPECT_NEAR(settled.worldLuminance, 1000.0, 10.0);
}

TEST(ToneMapping, SmoothingIsTheSameForOneLongStepAndManyShortOnes) {
  ToneSmoother a(0.5);
  ToneSmoother b(0.5);
  (void)a.update(measureLuminance(uniformImage(1.0F)), 0.1);
  (void)b.update(measureLuminance(uniformImage(1.0F)), 0.1);
  const ToneParams one = a.update(measureLuminance(uniformImage(100.0F)), 0.4);
  ToneParams many{};
  for (int i = 0; i < 4; ++i) {
    many = b.update(measureLuminance(uniformImage(100.0F)), 0.1);
  }
  EXPECT_NEAR(std::log(one.worldLuminance), std::log(many.worldLuminance), 1e-9);
}

TEST(ToneMapping, WorldLuminanceMapsToTheKeyOverOnePlusKey) {
  const ToneParams p{5.0, 0.18, 1e6};
  const glm::vec3 display = toneMap(glm::vec3(5.0F), p);
  EXPECT_NEAR(display.x, 0.18 / 1.18, 1e-5);
  EXPECT_NEAR(display.y, 0.18 / 1.18, 1e-5);
}

TEST(ToneMapping, NanAndNegativePixelsGiveBlackAndDoNotPoisonTheStatistics) {
  LinearImage image = uniformImage(2.0F);
  image.set(0, 0, glm::vec3(std::numeric_limits<float>::quiet_NaN()), true);
  image.set(1, 0, glm::vec3(-5.0F), true);
  image.set(2, 0, glm::vec3(std::numeric_limits<float>::infinity()), true);
  const FrameLuminance frame = measureLuminance(image);
  EXPECT_TRUE(std::isfinite(frame.logAverage));
  EXPECT_GT(frame.logAverage, 0.0);
  const ToneParams p = ToneSmoother().update(frame, 0.1);
  EXPECT_EQ(toneMap(image.at(0, 0), p), glm::vec3(0.0F));
  EXPECT_EQ(toneMap(image.at(1, 0), p), glm::vec3(0.0F));
  EXPECT_EQ(toneMap(image.at(2, 0), p), glm::vec3(0.0F));
}

TEST(ToneMapping, BlackFrameGivesFiniteParametersAndBlackPixels) {
  const LinearImage image = uniformImage(0.0F);
  const ToneParams p = ToneSmoother().update(measureLuminance(image), 0.1);
  EXPECT_TRUE(std::isfinite(p.worldLuminance) && p.worldLuminance > 0.0);
  EXPECT_TRUE(std::isfinite(p.key));
  for (std::uint8_t byte : toneMappedSrgb8(image, p)) {
    EXPECT_EQ(byte, 0);
  }
}

TEST(ToneMapping, SunAtTenToTheFiveTimesTheSkyKeepsTheSkyVisible) {
  LinearImage image = uniformImage(1.0F, 100, 100);
  for (int x = 0; x < 40; ++x) {  // 0.4 % of the pixels
    image.set(x, 0, glm::vec3(1e5F), true);
  }
  const ToneParams p = ToneSmoother().update(measureLuminance(image), 0.1);
  EXPECT_GT(toneMap(image.at(50, 50), p).y, 0.08F);
  EXPECT_EQ(toneMap(image.at(0, 0), p).y, 1.0F);
}

TEST(ToneMapping, UncoveredBackgroundDoesNotSetTheExposure) {
  LinearImage image = uniformImage(1.0F);
  for (int x = 0; x < image.widthPx; ++x) {
    for (int y = 0; y < image.heightPx / 2; ++y) {
      image.set(x, y, glm::vec3(1e4F), false);  // a bright sky behind the objects
    }
  }
  EXPECT_NEAR(measureLuminance(image).logAverage, 1.0, 1e-4);
}

TEST(ToneMapping, SrgbEncodingMatchesTheStandardAtItsKnots) {
  EXPECT_NEAR(srgbEncode(0.0F), 0.0F, 1e-7);
  EXPECT_NEAR(srgbEncode(1.0F), 1.0F, 1e-6);
  EXPECT_NEAR(srgbEncode(0.18F), 0.4614F, 1e-3);
  EXPECT_NEAR(srgbEncode(0.002F), 0.02584F, 1e-4);
}

}  // namespace
}  // namespace vem::render
