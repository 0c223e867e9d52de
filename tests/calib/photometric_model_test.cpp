// Response models (calib/core/photometric_model.h): inverse pairs, the black and saturation ends,
// and the LUT the daemon uses per frame.
#include "calib/core/photometric_model.h"

#include <cmath>

#include <gtest/gtest.h>

#include "support/test_cameras.h"

namespace vem::calib {
namespace {

TEST(PhotometricModel, LogResponseCodeAndLuminanceAreInverses) {
  const PhotometricCalibration p = testing::logSensorTruth(3);
  for (double code = 65.0; code < 4095.0; code += 97.3) {
    for (int c = 0; c < 3; ++c) {
      const double l = luminanceFromCode(p, c, code, 1000.0, 1.0);
      EXPECT_NEAR(codeFromLuminance(p, c, l, 1000.0, 1.0), code, 1e-9);
    }
  }
}

TEST(PhotometricModel, LogSensorSpansEightDecadesWithoutOverflow) {
  const PhotometricCalibration p = testing::logSensorTruth(1);
  EXPECT_NEAR(luminanceFromCode(p, 0, 64.0 + 1e-9, 1.0, 1.0), 1e-3, 1e-6);
  EXPECT_NEAR(luminanceFromCode(p, 0, 4095.0, 1.0, 1.0), 1e5, 1.0);
}

TEST(PhotometricModel, CodesAtOrBelowBlackReadZeroAndAboveSaturationReadTheClip) {
  const PhotometricCalibration p = testing::logSensorTruth(1);
  EXPECT_EQ(luminanceFromCode(p, 0, 0.0, 1000.0, 1.0), 0.0);
  EXPECT_EQ(luminanceFromCode(p, 0, 64.0, 1000.0, 1.0), 0.0);
  EXPECT_EQ(luminanceFromCode(p, 0, 65535.0, 1000.0, 1.0), luminanceFromCode(p, 0, 4095.0, 1000.0, 1.0));
  EXPECT_EQ(codeFromLuminance(p, 0, 0.0, 1000.0, 1.0), 64.0);
  EXPECT_EQ(codeFromLuminance(p, 0, 1e12, 1000.0, 1.0), 4095.0);
  EXPECT_TRUE(std::isfinite(luminanceFromCode(p, 0, 4095.0, 1000.0, 1.0)));
}

TEST(PhotometricModel, LinearResponseScalesWithExposureAndGain) {
  PhotometricCalibration p;
  p.blackLevelCode = 100.0;
  p.saturationCode = 65535.0;
  p.response = LinearResponse{{0.01, 0.02, 0.03}};
  EXPECT_NEAR(luminanceFromCode(p, 1, 100.0 + 0.02 * 5.0 * 1000.0 * 2.0, 1000.0, 2.0), 5.0, 1e-12);
  EXPECT_NEAR(codeFromLuminance(p, 2, 5.0, 500.0, 1.0), 100.0 + 0.03 * 5.0 * 500.0, 1e-12);
}

TEST(PhotometricModel, TabulatedResponseInterpolatesBetweenCodesBothWays) {
  PhotometricCalibration p;
  p.blackLevelCode = 0.0;
  p.saturationCode = 255.0;
  TabulatedResponse table;
  for (auto& channel : table.exposureByCode) {
    for (int code = 0; code < 256; ++code) channel.push_back(std::pow(code / 255.0, 2.2) * 4.0);
  }
  p.response = table;
  const double l = luminanceFromCode(p, 0, 100.5, 1000.0, 1.0);
  const double expected =
      0.5 * (std::pow(100 / 255.0, 2.2) + std::pow(101 / 255.0, 2.2)) * 4.0 / 1000.0;
  EXPECT_NEAR(l, expected, 1e-12);
  EXPECT_NEAR(codeFromLuminance(p, 0, l, 1000.0, 1.0), 100.5, 1e-9);
}

TEST(PhotometricModel, LutAgreesWithTheModelAtEveryCode) {
  const PhotometricCalibration p = testing::logSensorTruth(3);
  const CodeToLuminanceLut lut = buildCodeToLuminanceLut(p, {3, 12}, 1000.0, 1.0);
  ASSERT_EQ(lut.size, 4096u);
  for (std::uint32_t code = 0; code < lut.size; code += 13) {
    for (int c = 0; c < 3; ++c) {
      const double expected = luminanceFromCode(p, c, code, 1000.0, 1.0);
      EXPECT_NEAR(lut.luminanceCdM2[std::size_t(c) * lut.size + code], expected, expected * 1e-6);
    }
  }
}

}  // namespace
}  // namespace vem::calib
