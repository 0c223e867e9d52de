// The built-in scenes: the bunny from the shared data standing on the ground, materials per the
// glossy option, the stand-in when the bunny is missing, and what each scene can shadow.
#include "client/scene/default_scene.h"
#include "client/scene/primitives.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <glm/glm.hpp>

#include "scene_test_files.h"

namespace vem::scene {
namespace {

using ::testing::HasSubstr;

const Mesh* findMesh(const Scene& scene, std::string_view name) {
  const auto it = std::ranges::find(scene.meshes, name, &Mesh::name);
  return it == scene.meshes.end() ? nullptr : &*it;
}

Bounds meshBounds(const Mesh& mesh) {
  Scene alone;
  alone.meshes.push_back(mesh);
  return sceneBounds(alone);
}

TEST(DefaultScene, LoadsTheSharedBunnyWithNoNotes) {
  const DefaultScene built = defaultScene();
  EXPECT_THAT(built.notes, ::testing::IsEmpty());
  const Mesh* bunny = findMesh(built.scene, "bunny");
  ASSERT_NE(bunny, nullptr);
  EXPECT_EQ(bunny->triangleCount(), 3674U);
  EXPECT_EQ(firstContractViolation(built.scene), "");
}

TEST(DefaultScene, BunnyStandsOnTheGroundOneUnitTallAtTheOrigin) {
  const DefaultScene built = defaultScene();
  const Mesh* bunny = findMesh(built.scene, "bunny");
  ASSERT_NE(bunny, nullptr);
  const Bounds bounds = meshBounds(*bunny);
  EXPECT_NEAR(bounds.min.y, 0.0F, 1e-5F);
  EXPECT_NEAR(bounds.max.y - bounds.min.y, 1.0F, 1e-5F);
  EXPECT_NEAR(bounds.centre().x, 0.0F, 1e-5F);
  EXPECT_NEAR(bounds.centre().z, 0.0F, 1e-5F);
  EXPECT_EQ(built.scene.materials.at(bunny->material).lobe, Lobe::Lambertian);
  EXPECT_NEAR(sceneBounds(built.scene).min.y, 0.0F, 1e-5F);  // nothing below the ground
}

TEST(DefaultScene, BunnyNormalsPointOutwardNotInward) {
  const DefaultScene built = defaultScene();
  const Mesh* bunny = findMesh(built.scene, "bunny");
  ASSERT_NE(bunny, nullptr);
  glm::vec3 centroid(0.0F);
  for (const glm::vec3& p : bunny->positions) {
    centroid += p / static_cast<float>(bunny->positions.size());
  }
  std::size_t outward = 0;
  for (std::size_t i = 0; i < bunny->positions.size(); ++i) {
    outward += glm::dot(bunny->normals[i], bunny->positions[i] - centroid) > 0.0F ? 1 : 0;
  }
  // Not convex, so not all: 1695 of the 1839 vertices when this was written.
  EXPECT_GT(outward, bunny->positions.size() * 9 / 10);
}

TEST(DefaultScene, IsGlossyIffTheOptionAsksAndNeverMirrorLike) {
  const Scene glossy = defaultScene({.glossy = true}).scene;
  const Scene diffuse = defaultScene({.glossy = false}).scene;
  EXPECT_TRUE(anyGlossy(glossy));
  EXPECT_FALSE(anyGlossy(diffuse));
  EXPECT_FALSE(anyMirrorLike(glossy));
  const Mesh* sphere = findMesh(glossy, "sphere");
  ASSERT_NE(sphere, nullptr);
  EXPECT_EQ(glossy.materials.at(sphere->material).lobe, Lobe::Ggx);
  EXPECT_FLOAT_EQ(glossy.materials.at(sphere->material).roughness, 0.3F);
}

TEST(DefaultScene, CanCastShadows) { EXPECT_TRUE(canCastShadows(defaultScene().scene)); }

TEST(DefaultScene, MissingBunnyGivesAStandInSphereAndANote) {
  test_files::TempDir dir;
  const DefaultScene built = defaultScene({.bunnyPath = dir.path() / "no_bunny.obj"});
  ASSERT_EQ(built.notes.size(), 1U);
  EXPECT_THAT(built.notes[0], HasSubstr("no_bunny.obj does not exist"));
  EXPECT_THAT(built.notes[0], HasSubstr("a sphere stands in its place"));
  EXPECT_NE(findMesh(built.scene, "bunny stand-in"), nullptr);
  EXPECT_EQ(firstContractViolation(built.scene), "");
}

TEST(BuiltinScene, KnowsItsNamesAndNothingElse) {
  for (const std::string_view name : kBuiltinSceneNames) {
    const auto scene = builtinScene(name);
    ASSERT_TRUE(scene) << name;
    EXPECT_EQ(firstContractViolation(*scene), "") << name;
    EXPECT_GT(triangleCount(*scene), 0U) << name;
  }
  EXPECT_FALSE(builtinScene("teapot"));
}

TEST(BuiltinScene, DiffuseIsTheDefaultSceneWithNoGlossyMaterial) {
  const auto diffuse = builtinScene("diffuse");
  ASSERT_TRUE(diffuse);
  EXPECT_FALSE(anyGlossy(*diffuse));
  EXPECT_EQ(triangleCount(*diffuse), triangleCount(defaultScene().scene));
}

TEST(BuiltinScene, LoneSphereCannotCastShadows) {
  const auto sphere = builtinScene("sphere");
  ASSERT_TRUE(sphere);
  EXPECT_FALSE(canCastShadows(*sphere));
}

TEST(BuiltinScene, SphereOnAPlaneCanCastShadows) {
  const auto spheres = builtinScene("spheres");
  ASSERT_TRUE(spheres);
  EXPECT_TRUE(canCastShadows(*spheres));
}

// The shadow maps' view (client/gl/light_clip.h) spans what can cast a shadow: the sphere, not the
// 4-unit ground it stands on (issue 20 part 3: the ground in the view made the sun's shadow
// texels 2.7 times larger and blurred the contact).
TEST(ShadowCasterBounds, LeaveOutTheGroundTheOtherMeshesStandOn) {
  const auto spheres = builtinScene("spheres");
  ASSERT_TRUE(spheres);
  const Bounds casters = shadowCasterBounds(*spheres);
  EXPECT_NEAR(casters.min.y, 0.0F, 1e-3F);
  EXPECT_NEAR(casters.max.y, 1.0F, 1e-3F);
  EXPECT_NEAR(casters.max.x - casters.min.x, 1.0F, 1e-2F);
  EXPECT_NEAR(sceneBounds(*spheres).max.x - sceneBounds(*spheres).min.x, 4.0F, 1e-3F);
}

// A flat mesh with something behind it (a shelf over a box, a plane seen from below) hides that
// from the light on its front side: it stays in the view.
TEST(ShadowCasterBounds, KeepAFlatMeshWithSomethingBehindIt) {
  Scene shelf;
  shelf.materials = {Material{}};
  shelf.meshes.push_back(groundPlane(1.0F, 2.0F));  // a shelf at y = 1, facing up
  shelf.meshes.push_back(boxMesh(glm::vec3(-0.2F, 0.0F, -0.2F), glm::vec3(0.2F, 0.5F, 0.2F)));
  const Bounds casters = shadowCasterBounds(shelf);
  EXPECT_NEAR(casters.max.x - casters.min.x, 2.0F, 1e-3F);
  EXPECT_NEAR(casters.max.y, 1.0F, 1e-3F);
}

// Only grounds (or one plane alone): the whole scene, never empty bounds.
TEST(ShadowCasterBounds, AreTheWholeSceneWhenEveryMeshIsAGround) {
  Scene plane;
  plane.materials = {Material{}};
  plane.meshes.push_back(groundPlane(0.0F, 3.0F));
  const Bounds casters = shadowCasterBounds(plane);
  EXPECT_NEAR(casters.max.x - casters.min.x, 3.0F, 1e-3F);
  EXPECT_NEAR(casters.max.z - casters.min.z, 3.0F, 1e-3F);
}

}  // namespace
}  // namespace vem::scene
