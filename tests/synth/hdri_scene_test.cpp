// The `hdri:FILE` scene turns the map about the vertical by the documented angle: in the scene and
// through the camera and its calibration.
#include "synth/hdri_scene.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "calib/core/camera_simulator.h"
#include "core/color.h"
#include "mapio/map_file.h"
#include "synth/synth_pipeline.h"

namespace vem::synth {
namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;

EnvMap sharedHdri(const char* name) {
  auto map = mapio::loadMap(std::string(VEM_SHARED_DATA_DIR) + "/hdri/" + name);
  if (!map) ADD_FAILURE() << map.error().message;
  return map ? *map : EnvMap::filled(MapLayout::Sphere, 8, 4, glm::vec3(1.0F));
}

// Mean |ln| of the ratio of two maps' luminances (plus a floor), map `b` read `shift` columns
// further along the azimuth.
double meanLogDifference(const EnvMap& a, const EnvMap& b, int shift) {
  double sum = 0.0;
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      const double la = luminance(a.at(x, y)) + 0.01;
      const double lb = luminance(b.at((x + shift + b.width) % b.width, y)) + 0.01;
      sum += std::abs(std::log(la / lb));
    }
  }
  return sum / double(a.pixelCount());
}

TEST(HdriScene, RadianceAtTIsTheMapTurnedByPanSpeedTimesT) {
  const EnvMap map = sharedHdri("park.exr");
  const HdriScene scene(map, "park.exr", {2.0, 10.0});
  EXPECT_EQ(scene.name(), "hdri:park.exr");
  // radianceFromMap zeroes negative interpolated values; MapRadiance zeroes negative pixels first
  // (the shared HDRIs have a few small negatives): compare on the map they agree on.
  EnvMap clean = map;
  for (float& value : clean.rgb) value = std::max(value, 0.0F);
  const calib::RadianceFunction original = calib::radianceFromMap(clean);
  const SceneState later = scene.at(3.0);  // turned by 30 degrees
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 500; ++i) {
    const double theta = std::acos(2.0 * unit(random) - 1.0);
    const double phi = 2.0 * std::numbers::pi * unit(random);
    const glm::dvec3 seen = later.radiance(directionFromAngles(theta, phi + 30.0 * kDegToRad));
    const glm::dvec3 source = 2.0 * original(directionFromAngles(theta, phi));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(seen[c], source[c], 1e-3 * (1.0 + source[c]));
  }
}

TEST(HdriScene, CalibratedMapsTurnByThePanAngleNotTheOtherWay) {
  const HdriScene scene(sharedHdri("park.exr"), "park.exr", {1.0, 10.0});
  const calib::CameraCalibration& camera = testing::exampleCamera();
  // 32 columns of the 1024-column polar map: 11.25 degrees, 1.125 s at 10 degrees per second.
  const EnvMap before =
      testing::calibratedMap(camera, testing::exampleSyntheticCamera().render(scene.at(0.0)));
  const EnvMap after =
      testing::calibratedMap(camera, testing::exampleSyntheticCamera().render(scene.at(1.125)));
  const double turned = meanLogDifference(before, after, 32);  // after(x + 32) = before(x)
  const double wrongWay = meanLogDifference(before, after, -32);
  const double unturned = meanLogDifference(before, after, 0);
  EXPECT_LT(turned, 0.05);
  EXPECT_GT(wrongWay, 4.0 * turned);
  EXPECT_GT(unturned, 4.0 * turned);
}

}  // namespace
}  // namespace vem::synth
