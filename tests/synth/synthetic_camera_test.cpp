// The synthetic camera against calib::simulateFrame (its reference), its response table against
// codeFromLuminance, and its noise and reproducibility.
#include "synth/synthetic_camera.h"

#include <cmath>
#include <cstdlib>
#include <numeric>
#include <vector>

#include <gtest/gtest.h>

#include "calib/core/camera_simulator.h"
#include "calib/core/photometric_model.h"
#include "support/test_cameras.h"
#include "synth/sensor_code_table.h"
#include "synth/sky_scene.h"

namespace vem::synth {
namespace {

calib::CameraCalibration linearCamera(int width, int height, int channels) {
  calib::CameraCalibration camera = testing::cameraTruth(width, height, channels);
  calib::PhotometricCalibration photometric;
  photometric.response = calib::LinearResponse{{0.05, 0.052, 0.048}};
  photometric.blackLevelCode = 64.0;
  photometric.saturationCode = 4095.0;
  camera.photometric = photometric;
  return camera;
}

// The largest code difference between two frames of the same size.
int largestDifference(const vem::RawFrame& a, const vem::RawFrame& b) {
  EXPECT_EQ(a.codes.size(), b.codes.size());
  int largest = 0;
  for (std::size_t i = 0; i < a.codes.size(); ++i) {
    largest = std::max(largest, std::abs(int(a.codes[i]) - int(b.codes[i])));
  }
  return largest;
}

void expectLikeSimulateFrame(const calib::CameraCalibration& camera, const SceneState& state,
                             int samples) {
  SyntheticCamera synthetic(camera, {samples, {}});
  const vem::RawFrame fast = synthetic.render(state);
  calib::SimulationOptions options;
  options.exposureUs = state.exposureUs;
  options.gain = state.gain;
  options.supersamples = samples;
  const vem::RawFrame reference = calib::simulateFrame(state.radiance, camera, options);
  EXPECT_EQ(fast.width, reference.width);
  EXPECT_EQ(fast.format, reference.format);
  EXPECT_EQ(fast.exposureUs, reference.exposureUs);
  EXPECT_EQ(fast.gain, reference.gain);
  // The tabulated response may round the other way at a half code.
  EXPECT_LE(largestDifference(fast, reference), 1);
}

TEST(SyntheticCamera, MatchesSimulateFrameForLogLinearMonoAndSupersampledCameras) {
  SceneState state = SkyScene().at(20.0);
  expectLikeSimulateFrame(testing::cameraTruth(160, 128, 3), state, 1);
  expectLikeSimulateFrame(testing::cameraTruth(160, 128, 3), state, 2);
  expectLikeSimulateFrame(testing::cameraTruth(160, 128, 1), state, 1);
  calib::CameraCalibration tilted = testing::cameraTruth(160, 128, 3);
  tilted.orientation = {30.0, 20.0, 45.0};
  expectLikeSimulateFrame(tilted, state, 1);
  state.exposureUs = 500.0;
  state.gain = 2.0;
  state.radiance = [](const glm::dvec3& dir) { return glm::dvec3(10.0 + 20.0 * dir.y); };
  expectLikeSimulateFrame(linearCamera(160, 128, 3), state, 1);
}

TEST(SyntheticCamera, ResponseTableMatchesCodeFromLuminance) {
  const calib::CameraCalibration log = testing::cameraTruth(8, 8, 3);
  const calib::CameraCalibration linear = linearCamera(8, 8, 3);
  const SensorCodeTable logTable(*log.photometric, log.camera.pixelFormat, 1000.0, 1.0);
  const SensorCodeTable linearTable(*linear.photometric, linear.camera.pixelFormat, 700.0, 1.5);
  double worstLog = 0.0;
  double worstLinear = 0.0;
  for (double l = 1e-5; l < 1e7; l *= 1.0137) {
    for (int c = 0; c < 3; ++c) {
      const auto lf = float(l);
      worstLog = std::max(worstLog, std::abs(double(logTable.idealCode(c, lf)) -
                                             calib::codeFromLuminance(*log.photometric, c,
                                                                      double(lf), 1000.0, 1.0)));
      worstLinear = std::max(
          worstLinear,
          std::abs(double(linearTable.idealCode(c, lf)) -
                   calib::codeFromLuminance(*linear.photometric, c, double(lf), 700.0, 1.5)));
    }
  }
  EXPECT_LT(worstLog, 2e-3);
  EXPECT_LT(worstLinear, 2e-3);
  EXPECT_EQ(logTable.idealCode(0, 0.0F), 64.0F);  // black, and so are negatives and NaN
  EXPECT_EQ(logTable.idealCode(0, -1.0F), 64.0F);
  EXPECT_EQ(logTable.idealCode(0, std::nanf("")), 64.0F);
  EXPECT_EQ(logTable.idealCode(0, 1e30F), 4095.0F);
}

TEST(SyntheticCamera, PixelsOutsideTheLensCircleReadTheBlackLevel) {
  SyntheticCamera camera(testing::cameraTruth(160, 128, 3));
  SceneState state;
  state.radiance = [](const glm::dvec3&) { return glm::dvec3(100.0); };
  const vem::RawFrame frame = camera.render(state);
  EXPECT_EQ(frame.at(0, 0, 0), 64);  // a corner: outside the circle
  EXPECT_EQ(frame.at(159, 127, 2), 64);
  EXPECT_GT(frame.at(80, 64, 1), 2000);  // the centre sees 100 cd/m2
  EXPECT_GT(camera.litPixelCount(), 160u * 128u / 2);
  EXPECT_LT(camera.litPixelCount(), 160u * 128u);
}

TEST(SyntheticCamera, SameFrameIndexRepeatsItsNoiseAndAnotherDrawsNew) {
  const calib::CameraCalibration truth = testing::cameraTruth(160, 128, 3);
  SyntheticCameraOptions options;
  options.noise = {2.0, 0.0, 42};
  SyntheticCamera a(truth, options);
  SyntheticCamera b(truth, options);
  const SceneState state = SkyScene().at(5.0);
  EXPECT_EQ(a.render(state, 7).codes, b.render(state, 7).codes);
  EXPECT_NE(a.render(state, 7).codes, a.render(state, 8).codes);
  options.noise.seed = 43;
  EXPECT_NE(SyntheticCamera(truth, options).render(state, 7).codes, a.render(state, 7).codes);
}

TEST(SyntheticCamera, ReadNoiseHasTheRequestedStandardDeviation) {
  const calib::CameraCalibration truth = testing::cameraTruth(160, 128, 1);
  SyntheticCamera noisy(truth, {1, {3.0, 0.0, 5}});
  SceneState state;
  state.radiance = [](const glm::dvec3&) { return glm::dvec3(5.0); };
  const vem::RawFrame a = noisy.render(state, 1);
  const double ideal = calib::codeFromLuminance(*truth.photometric, 0, 5.0, 1000.0, 1.0);
  double sum = 0.0;
  double sumSquares = 0.0;
  double n = 0.0;
  for (const std::uint16_t code : a.codes) {
    if (code < 1000) continue;  // outside the lens circle
    const double d = double(code) - ideal;
    sum += d;
    sumSquares += d * d;
    n += 1.0;
  }
  ASSERT_GT(n, 10000.0);
  EXPECT_NEAR(sum / n, 0.0, 0.05);
  // Rounding adds 1/12 of a code squared.
  EXPECT_NEAR(std::sqrt(sumSquares / n - (sum / n) * (sum / n)), std::sqrt(9.0 + 1.0 / 12.0), 0.05);
}

TEST(SyntheticCamera, SaturatedPixelsReadTheSaturationCodeWithoutNoise) {
  SyntheticCamera camera(testing::cameraTruth(64, 64, 3), {1, {5.0, 0.0, 1}});
  SceneState state;
  state.radiance = [](const glm::dvec3&) { return glm::dvec3(1e9); };
  const vem::RawFrame frame = camera.render(state, 3);
  EXPECT_EQ(frame.at(32, 32, 0), 4095);
  EXPECT_EQ(frame.at(32, 32, 2), 4095);
}

}  // namespace
}  // namespace vem::synth
