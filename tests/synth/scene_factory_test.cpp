// Scenes by name and the built-in camera: what `vemtool synth --scene` and vemd accept.
#include "synth/scene_factory.h"

#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "calib/io/camera_file.h"
#include "synth/default_camera.h"

namespace vem::synth {
namespace {

TEST(SceneFactory, EveryDocumentedNameMakesItsScene) {
  SceneOptions options;
  options.hdri =
      std::make_shared<const EnvMap>(EnvMap::filled(MapLayout::Sphere, 16, 8, glm::vec3(2.0F)));
  for (const std::string name :
       {"sky", "clouds", "fluorescent", "exposure-jump", "hdri:some/where/park.exr"}) {
    auto scene = makeScene(name, options);
    ASSERT_TRUE(scene) << scene.error();
    EXPECT_EQ((*scene)->name(), name);
    EXPECT_TRUE((*scene)->at(0.5).radiance) << name;
  }
}

TEST(SceneFactory, EveryDocumentedNameHasANaturalRateAndFluorescentsIsThe30HzItsAliasingNeeds) {
  for (const std::string name :
       {"sky", "clouds", "fluorescent", "exposure-jump", "hdri:some/where/park.exr"}) {
    EXPECT_EQ(naturalRateHz(name), 30.0) << name;
  }
  EXPECT_FALSE(naturalRateHz("skies"));
  EXPECT_FALSE(naturalRateHz("hdri:"));
}

TEST(SceneFactory, UnknownNameIsRefusedInOneSentenceListingTheNames) {
  const auto scene = makeScene("skies", {});
  ASSERT_FALSE(scene);
  EXPECT_EQ(scene.error(),
            "unknown scene 'skies' (expected one of sky, clouds, hdri:FILE, fluorescent, "
            "exposure-jump)");
}

TEST(SceneFactory, HdriNeedsItsMapAndAFileName) {
  EXPECT_EQ(hdriFileOf("hdri:a/b.exr"), "a/b.exr");
  EXPECT_FALSE(hdriFileOf("hdri:"));
  EXPECT_FALSE(hdriFileOf("sky"));
  const auto noMap = makeScene("hdri:park.exr", {});
  ASSERT_FALSE(noMap);
  EXPECT_NE(noMap.error().find("needs its map loaded"), std::string::npos) << noMap.error();
  const auto noFile = makeScene("hdri:", {});
  ASSERT_FALSE(noFile);
  EXPECT_NE(noFile.error().find("names no file"), std::string::npos) << noFile.error();
}

TEST(SceneFactory, CloudSeedChangesTheClouds) {
  SceneOptions a;
  SceneOptions b;
  b.seed = 2;
  const glm::dvec3 dir(0.2, 0.9, 0.38);
  int differing = 0;
  for (double t = 0.0; t < 5.0; t += 0.5) {
    differing += (*makeScene("clouds", a))->at(t).radiance(dir) !=
                 (*makeScene("clouds", b))->at(t).radiance(dir);
  }
  EXPECT_GT(differing, 5);
}

TEST(DefaultCamera, BuiltInCameraIsConfigCameraExampleByteForByte) {
  std::ifstream file(std::string(VEM_SOURCE_DIR) + "/config/camera-example.toml");
  ASSERT_TRUE(file);
  std::stringstream text;
  text << file.rdbuf();
  EXPECT_EQ(exampleCameraToml(), text.str());
  const auto builtIn = calib::io::parseCameraFile(std::string(exampleCameraToml()), "built in");
  const auto loaded =
      calib::io::loadCameraFile(std::string(VEM_SOURCE_DIR) + "/config/camera-example.toml");
  ASSERT_TRUE(builtIn && loaded);
  EXPECT_EQ(calib::io::formatCameraFile(*builtIn), calib::io::formatCameraFile(*loaded));
  EXPECT_TRUE(builtIn->photometric && builtIn->lens);
}

}  // namespace
}  // namespace vem::synth
