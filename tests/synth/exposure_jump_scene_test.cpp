// The `exposure-jump` scene: the exposure step shows in a linear camera's codes, not in a log
// sensor's, and the calibrated lights stay steady across it when the calibration uses each frame's
// own exposure.
#include "synth/exposure_jump_scene.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core/color.h"
#include "support/test_cameras.h"
#include "synth/synth_pipeline.h"
#include "synth/synthetic_camera.h"

namespace vem::synth {
namespace {

// A linear 12-bit camera for which the scene (6.7 to 60 cd/m2) stays between black and
// saturation at 1000 and at 250 us.
calib::CameraCalibration linearCamera() {
  calib::CameraCalibration camera = testing::cameraTruth(320, 256, 3);
  calib::PhotometricCalibration photometric;
  photometric.response = calib::LinearResponse{{0.05, 0.05, 0.05}};
  photometric.blackLevelCode = 64.0;
  photometric.saturationCode = 4095.0;
  camera.photometric = photometric;
  return camera;
}

TEST(ExposureJumpScene, ExposureStepsAtTheJumpAndTheWorldDoesNot) {
  const ExposureJumpScene scene;
  EXPECT_EQ(scene.at(0.99).exposureUs, 1000.0);
  EXPECT_EQ(scene.at(1.0).exposureUs, 250.0);
  const glm::dvec3 dir(0.3, 0.8, 0.52);
  EXPECT_EQ(scene.at(0.5).radiance(dir), scene.at(1.5).radiance(dir));
}

TEST(ExposureJumpScene, LinearCameraCodesAboveBlackDropToAQuarter) {
  const calib::CameraCalibration camera = linearCamera();
  SyntheticCamera synthetic(camera);
  const ExposureJumpScene scene;
  const vem::RawFrame before = synthetic.render(scene.at(0.9));
  const vem::RawFrame after = synthetic.render(scene.at(1.1));
  EXPECT_EQ(before.exposureUs, 1000.0);
  EXPECT_EQ(after.exposureUs, 250.0);
  std::vector<double> ratios;
  for (std::size_t i = 0; i < before.codes.size(); ++i) {
    if (before.codes[i] > 1000)
      ratios.push_back((after.codes[i] - 64.0) / (before.codes[i] - 64.0));
  }
  ASSERT_GT(ratios.size(), 10000u);
  std::ranges::sort(ratios);
  EXPECT_NEAR(ratios[ratios.size() / 2], 0.25, 0.005);
  EXPECT_NEAR(ratios.front(), 0.25, 0.01);
  EXPECT_NEAR(ratios.back(), 0.25, 0.01);
}

TEST(ExposureJumpScene, LogSensorCodesDoNotChange) {
  const ExposureJumpScene scene;
  SyntheticCamera synthetic(testing::cameraTruth(320, 256, 3));
  EXPECT_EQ(synthetic.render(scene.at(0.9)).codes, synthetic.render(scene.at(1.1)).codes);
}

TEST(ExposureJumpScene, LightsStaySteadyAcrossTheJumpWhenCalibratedAtEachExposure) {
  const calib::CameraCalibration camera = linearCamera();
  SyntheticCamera synthetic(camera);
  const ExposureJumpScene scene;
  const vem::RawFrame before = synthetic.render(scene.at(0.9));
  const vem::RawFrame after = synthetic.render(scene.at(1.1));
  const LightSet lightsBefore =
      testing::hemisphereLights(testing::calibratedMap(camera, before), 256);
  const LightSet lightsAfter =
      testing::hemisphereLights(testing::calibratedMap(camera, after), 256);
  EXPECT_NEAR(lightsAfter.luminanceSr / lightsBefore.luminanceSr, 1.0, 0.01);
  const Light strongestBefore = testing::strongestCluster(lightsBefore, 72);
  const Light strongestAfter = testing::strongestCluster(lightsAfter, 72);
  EXPECT_LT(testing::angleDeg(glm::dvec3(strongestBefore.dir), glm::dvec3(strongestAfter.dir)),
            1.0);
  EXPECT_NEAR(luminance(strongestAfter.rgb) / luminance(strongestBefore.rgb), 1.0, 0.02);

  // Calibrating the later frame as if it had the earlier exposure would see a 4x darker world.
  vem::RawFrame mislabelled = after;
  mislabelled.exposureUs = before.exposureUs;
  const LightSet wrong =
      testing::hemisphereLights(testing::calibratedMap(camera, mislabelled), 256);
  EXPECT_NEAR(wrong.luminanceSr / lightsBefore.luminanceSr, 0.25, 0.01);
}

}  // namespace
}  // namespace vem::synth
