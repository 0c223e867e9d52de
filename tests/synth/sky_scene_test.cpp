// The `sky` scene: through the example camera and its true calibration, the strongest light points
// at the sun; the sky model, the sun's disc, luminance and path are the documented ones.
#include "synth/sky_scene.h"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "calib/core/camera_orientation.h"
#include "core/color.h"
#include "core/env_map.h"
#include "synth/preetham_sky.h"
#include "synth/synth_pipeline.h"

namespace vem::synth {
namespace {

using testing::angleDeg;

constexpr double kDegToRad = std::numbers::pi / 180.0;

// A unit vector `angleDeg` away from `dir`.
glm::dvec3 tiltedAway(const glm::dvec3& dir, double angle) {
  const glm::dvec3 side = glm::normalize(glm::cross(dir, glm::dvec3(0.0, 1.0, 0.0)));
  return std::cos(angle * kDegToRad) * dir + std::sin(angle * kDegToRad) * side;
}

TEST(SkyScene, StrongestClusterPointsAtTheSunWithinOneDegreeAlongTheArc) {
  const SkyScene scene;
  const calib::CameraCalibration& camera = testing::exampleCamera();
  double worstDeg = 0.0;
  for (const double timeS : {0.0, 25.0, 60.0, 95.0, 125.0}) {  // elevations 22 to 50 to 19 deg
    const SceneState state = scene.at(timeS);
    ASSERT_TRUE(state.sunDirWorld);
    const EnvMap map =
        testing::calibratedMap(camera, testing::exampleSyntheticCamera().render(state));
    const Light strongest = testing::strongestCluster(testing::hemisphereLights(map, 1024), 256);
    const double errorDeg = angleDeg(glm::dvec3(strongest.dir), *state.sunDirWorld);
    EXPECT_LT(errorDeg, 1.0) << "at t = " << timeS << " s";
    worstDeg = std::max(worstDeg, errorDeg);
  }
  std::printf("strongest cluster vs sun: worst %.3f deg over 5 times\n", worstDeg);
}

TEST(SkyScene, SunFollowsTheDocumentedArcAndTurnsBackAtItsEnds) {
  const SunArc arc;  // latitude 40, start 30 deg, 1 deg/s, turning at 20 and 160 deg
  EXPECT_DOUBLE_EQ(sunArcAngleDeg(arc, 0.0), 30.0);
  EXPECT_DOUBLE_EQ(sunArcAngleDeg(arc, 60.0), 90.0);
  EXPECT_DOUBLE_EQ(sunArcAngleDeg(arc, 130.0), 160.0);
  EXPECT_DOUBLE_EQ(sunArcAngleDeg(arc, 140.0), 150.0);  // on its way back
  EXPECT_DOUBLE_EQ(sunArcAngleDeg(arc, -10.0), 20.0);   // and before t = 0
  EXPECT_DOUBLE_EQ(sunArcAngleDeg(arc, -20.0), 30.0);
  // Noon: due south (+Z) at elevation 90 - latitude.
  const glm::dvec3 noon = sunDirection(arc, 60.0);
  EXPECT_NEAR(noon.x, 0.0, 1e-12);
  EXPECT_NEAR(std::asin(noon.y) / kDegToRad, 50.0, 1e-9);
  EXPECT_GT(noon.z, 0.0);
  // Rising in the east (+X): at 30 degrees along the arc.
  const glm::dvec3 morning = sunDirection(arc, 0.0);
  EXPECT_NEAR(morning.x, std::cos(30.0 * kDegToRad), 1e-12);
  EXPECT_NEAR(morning.y, std::sin(30.0 * kDegToRad) * std::cos(40.0 * kDegToRad), 1e-12);
  // One degree of arc per second.
  EXPECT_NEAR(angleDeg(sunDirection(arc, 10.0), sunDirection(arc, 11.0)), 1.0, 1e-9);
}

TEST(SkyScene, SunIsAHundredThousandTimesTheZenith) {
  const SkyScene scene;
  for (const double timeS : {0.0, 60.0}) {
    const SceneState state = scene.at(timeS);
    const double sun = luminance(state.radiance(*state.sunDirWorld));
    const double zenith = luminance(state.radiance(glm::dvec3(0.0, 1.0, 0.0)));
    EXPECT_NEAR(zenith, 1.0, 1e-3);
    // The disc plus the sky right behind it (a few cd/m2).
    EXPECT_NEAR(sun / zenith, 1e5, 100.0);
  }
}

TEST(SkyScene, SunDiscIsHalfADegreeAcross) {
  const SceneState state = SkyScene().at(30.0);
  const glm::dvec3 sun = *state.sunDirWorld;
  EXPECT_GT(luminance(state.radiance(tiltedAway(sun, 0.26))), 1e4);
  EXPECT_LT(luminance(state.radiance(tiltedAway(sun, 0.27))), 100.0);
}

TEST(SkyScene, SunStaysBelowTheExampleCamerasSaturationAndTheSkyAboveItsBlack) {
  const SceneState state = SkyScene().at(60.0);
  const vem::RawFrame frame = testing::exampleSyntheticCamera().render(state);
  const calib::CameraCalibration& camera = testing::exampleCamera();
  const glm::dmat3 cameraFromWorld = glm::transpose(calib::worldFromCamera(camera.orientation));
  const auto codeToward = [&](const glm::dvec3& dir, int channel) {
    const glm::dvec2 p = *camera.lens->sensorFromCamera(cameraFromWorld * dir);
    return frame.at(int(std::lround(p.x)), int(std::lround(p.y)), channel);
  };
  for (int c = 0; c < 3; ++c) {
    EXPECT_GT(codeToward(*state.sunDirWorld, c), 3800) << "channel " << c;
    EXPECT_LT(codeToward(*state.sunDirWorld, c), 4095) << "channel " << c;
    // The blue zenith, luminance 1 cd/m2, reads 0.5 to 3 cd/m2 per channel: far above black.
    EXPECT_GT(codeToward(glm::dvec3(0.0, 1.0, 0.0), c), 1400) << "channel " << c;
    EXPECT_LT(codeToward(glm::dvec3(0.0, 1.0, 0.0), c), 1800) << "channel " << c;
  }
}

TEST(SkyScene, GroundIsTheAlbedoTimesTheIrradianceOverPi) {
  const SkyScene scene;
  const ClearSkyInstant sky = scene.instant(40.0);
  // Horizontal irradiance by a finer midpoint rule than the scene's, plus the sun's disc.
  glm::dvec3 irradiance(0.0);
  constexpr int kRows = 90;
  constexpr int kColumns = 360;
  const double dTheta = 0.5 * std::numbers::pi / kRows;
  const double dPhi = 2.0 * std::numbers::pi / kColumns;
  for (int i = 0; i < kRows; ++i) {
    const double theta = (i + 0.5) * dTheta;
    for (int j = 0; j < kColumns; ++j) {
      irradiance += sky.skyOrGround(directionFromAngles(theta, (j + 0.5) * dPhi)) *
                    std::cos(theta) * std::sin(theta) * dTheta * dPhi;
    }
  }
  irradiance += sky.sunRgb * (2.0 * std::numbers::pi * (1.0 - sky.cosSunRadius)) * sky.sun.sunDir.y;
  const glm::dvec3 expected = scene.params().groundAlbedo * irradiance / std::numbers::pi;
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(sky.groundRgb[c], expected[c], 0.02 * expected[c]);
  EXPECT_EQ(sky.skyOrGround(glm::dvec3(0.0, -1.0, 0.0)), sky.groundRgb);
}

TEST(PreethamSky, TablesMatchTheClosedForm) {
  const PreethamSky model(3.0);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst = 0.0;
  for (int i = 0; i < 2000; ++i) {
    const glm::dvec3 sunDir = directionFromAngles(std::acos(0.05 + 0.95 * unit(random)),
                                                  2.0 * std::numbers::pi * unit(random));
    const glm::dvec3 dir =
        directionFromAngles(std::acos(unit(random)), 2.0 * std::numbers::pi * unit(random));
    const PreethamSky::SunTerms sun = model.sunTerms(sunDir, 1.0);
    const glm::dvec3 fast = model.radiance(sun, dir);
    const glm::dvec3 exact = model.radianceExact(sun, dir);
    worst = std::max(worst, std::abs(luminance(fast) / luminance(exact) - 1.0));
  }
  EXPECT_LT(worst, 1e-3);
}

TEST(PreethamSky, ClearSkyIsBlueAtTheZenithAndBrightestAroundTheSun) {
  const PreethamSky model(3.0);
  const glm::dvec3 sunDir = directionFromAngles(45.0 * kDegToRad, 0.0);
  const PreethamSky::SunTerms sun = model.sunTerms(sunDir, 1.0);
  const glm::dvec3 zenith = model.radiance(sun, glm::dvec3(0.0, 1.0, 0.0));
  EXPECT_NEAR(luminance(zenith), 1.0, 1e-3);
  EXPECT_GT(zenith.b, 1.2 * zenith.r);
  const double nearSun = luminance(model.radiance(sun, tiltedAway(sunDir, 3.0)));
  const double opposite =
      luminance(model.radiance(sun, directionFromAngles(45.0 * kDegToRad, std::numbers::pi)));
  EXPECT_GT(nearSun, 3.0);
  EXPECT_LT(opposite, 1.5);
  EXPECT_GT(nearSun, 3.0 * opposite);
}

}  // namespace
}  // namespace vem::synth
