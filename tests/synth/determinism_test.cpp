// Every scene is a function of time: the same time gives the same frame, from a fresh scene and a
// fresh camera too; moving scenes give different frames at different times.
#include <memory>

#include <gtest/gtest.h>

#include "support/test_cameras.h"
#include "synth/scene_factory.h"
#include "synth/synthetic_camera.h"

namespace vem::synth {
namespace {

SceneOptions optionsWithMap() {
  SceneOptions options;
  EnvMap map = EnvMap::filled(MapLayout::Sphere, 64, 32, glm::vec3(1.0F));
  for (int x = 0; x < 64; ++x) map.set(x, 10, glm::vec3(50.0F + float(x)));  // something to turn
  options.hdri = std::make_shared<const EnvMap>(map);
  return options;
}

TEST(SceneDeterminism, SameTimeGivesTheSameFrameFromFreshScenesAndCameras) {
  const calib::CameraCalibration camera = testing::cameraTruth(160, 128, 3);
  for (const char* name : {"sky", "clouds", "hdri:map", "fluorescent", "exposure-jump"}) {
    const auto first = makeScene(name, optionsWithMap());
    const auto second = makeScene(name, optionsWithMap());
    ASSERT_TRUE(first && second);
    SyntheticCamera a(camera, {1, {1.5, 0.0, 9}});
    SyntheticCamera b(camera, {1, {1.5, 0.0, 9}});
    EXPECT_EQ(a.render((*first)->at(1.7), 4).codes, b.render((*second)->at(1.7), 4).codes) << name;
    EXPECT_EQ(a.render((*first)->at(1.7), 4).codes, a.render((*first)->at(1.7), 4).codes) << name;
  }
}

TEST(SceneDeterminism, MovingScenesChangeOverTime) {
  const calib::CameraCalibration camera = testing::cameraTruth(160, 128, 3);
  SyntheticCamera synthetic(camera);
  for (const char* name : {"sky", "clouds", "hdri:map", "fluorescent"}) {
    const auto scene = makeScene(name, optionsWithMap());
    EXPECT_NE(synthetic.render((*scene)->at(0.0)).codes,
              synthetic.render((*scene)->at(1.0 / 30.0)).codes)
        << name;
  }
}

}  // namespace
}  // namespace vem::synth
