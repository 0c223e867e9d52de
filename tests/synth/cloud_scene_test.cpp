// The `clouds` scene: clouds really pass over the sun, sunVisibility says so, and the sun's
// pixels darken; the noise field behind them is deterministic and smooth.
#include "synth/cloud_scene.h"

#include <cmath>
#include <optional>

#include <gtest/gtest.h>
#include <glm/mat3x3.hpp>

#include "calib/core/camera_orientation.h"
#include "core/color.h"
#include "synth/synth_pipeline.h"
#include "synth/value_noise.h"

namespace vem::synth {
namespace {

// The example camera's green code toward `dir`.
int greenCodeToward(const vem::RawFrame& frame, const glm::dvec3& dir) {
  const calib::CameraCalibration& camera = testing::exampleCamera();
  const glm::dmat3 cameraFromWorld = glm::transpose(calib::worldFromCamera(camera.orientation));
  const glm::dvec2 p = *camera.lens->sensorFromCamera(cameraFromWorld * dir);
  return frame.at(int(std::lround(p.x)), int(std::lround(p.y)), 1);
}

TEST(CloudScene, CloudsPassOverTheSunAndItsPixelsDarken) {
  const CloudScene scene;
  std::optional<double> covered;
  std::optional<double> clear;
  for (double t = 0.0; t < 20.0 && !(covered && clear); t += 0.05) {
    const double visibility = scene.at(t).sunVisibility;
    if (visibility < 0.3 && !covered) covered = t;
    if (visibility > 0.95 && !clear) clear = t;
  }
  ASSERT_TRUE(covered) << "no cloud covered the sun in 20 s";
  ASSERT_TRUE(clear) << "the sun was never clear in 20 s";

  const SceneState hidden = scene.at(*covered);
  const SceneState shining = scene.at(*clear);
  const int hiddenCode =
      greenCodeToward(testing::exampleSyntheticCamera().render(hidden), *hidden.sunDirWorld);
  const int shiningCode =
      greenCodeToward(testing::exampleSyntheticCamera().render(shining), *shining.sunDirWorld);
  EXPECT_GT(shiningCode, 3900);  // the open sun, 1e5 cd/m2
  // Visibility < 0.3 takes at least ln(1 / 0.3) x 210 = 250 codes off a log sensor's sun.
  EXPECT_LT(hiddenCode, shiningCode - 200);
}

TEST(CloudScene, SunVisibilityIsWhatReachesTheCameraFromTheSun) {
  const CloudScene scene;
  for (double t = 0.0; t < 10.0; t += 0.25) {
    const SceneState state = scene.at(t);
    const double visibility = state.sunVisibility;
    EXPECT_DOUBLE_EQ(visibility, 1.0 - scene.opacity(*state.sunDirWorld, t));
    // The sun's centre: what the cloud lets through of 1e5 cd/m2, plus at most the sky and the
    // cloud's own light (under 20 cd/m2 near the sun).
    const double seen = luminance(state.radiance(*state.sunDirWorld));
    EXPECT_GE(seen, visibility * 1e5 - 1.0) << "t = " << t;
    EXPECT_LE(seen, visibility * 1e5 + 30.0) << "t = " << t;
  }
}

TEST(ValueNoise, SameSeedSameFieldInUnitRangeAndContinuous) {
  const ValueNoise a(3);
  const ValueNoise b(3);
  const ValueNoise other(4);
  int differing = 0;
  for (double x = -40.0; x < 40.0; x += 0.173) {
    const glm::dvec2 p(x, 0.37 * x + 2.0);
    const double v = a.fractal(p, 4);
    EXPECT_EQ(v, b.fractal(p, 4));
    EXPECT_GE(v, 0.0);
    EXPECT_LT(v, 1.0);
    EXPECT_NEAR(a.fractal(p + glm::dvec2(1e-6, 0.0), 4), v, 1e-4);    // no jumps at cell edges
    EXPECT_NEAR(a.at(p), a.at(p + glm::dvec2(256.0, -512.0)), 1e-9);  // the documented period
    differing += other.fractal(p, 4) != v;
  }
  EXPECT_GT(differing, 400);
}

}  // namespace
}  // namespace vem::synth
