// EmbreeScene: hits, normals, mesh and material indices, occlusion, and errors as values.
#include "client/embree/embree_scene.h"

#include <cmath>

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include "client/embree/shading_point.h"
#include "client/scene/primitives.h"
#include "embree/embree_fixtures.h"

namespace vem::embree {
namespace {

using testing::built;
using testing::lambertian;

scene::Scene twoMeshScene() {
  scene::Scene s;
  s.name = "two";
  s.materials = {lambertian(0.2F), lambertian(0.7F)};
  s.meshes.push_back(scene::groundPlane(0.0F, 4.0F, 0.0F, 0.0F, 1));
  s.meshes.push_back(scene::sphereMesh(glm::vec3(0.0F, 1.0F, 0.0F), 0.5F, 32, 64, 0));
  return s;
}

TEST(EmbreeScene, HitReportsTheMeshItStruckNotTheFirstMesh) {
  const EmbreeScene scene = built(twoMeshScene());
  const auto sphere = scene.intersect({glm::vec3(0.0F, 5.0F, 0.0F), glm::vec3(0.0F, -1.0F, 0.0F)});
  ASSERT_TRUE(sphere.has_value());
  EXPECT_EQ(sphere->meshIndex, 1U);
  EXPECT_EQ(sphere->materialIndex, 0U);
  EXPECT_NEAR(double(sphere->distance), 3.5, 1e-3);
  const auto plane = scene.intersect({glm::vec3(1.5F, 5.0F, 0.0F), glm::vec3(0.0F, -1.0F, 0.0F)});
  ASSERT_TRUE(plane.has_value());
  EXPECT_EQ(plane->meshIndex, 0U);
  EXPECT_EQ(plane->materialIndex, 1U);
  EXPECT_NEAR(double(plane->positionWorld.y), 0.0, 1e-5);
}

TEST(EmbreeScene, NormalsFaceTheFrontSideAndInterpolate) {
  const EmbreeScene scene = built(twoMeshScene());
  const glm::vec3 dir = glm::normalize(glm::vec3(-1.0F, -0.2F, 0.1F));
  const auto hit = scene.intersect({glm::vec3(3.0F, 1.6F, -0.3F), dir});
  ASSERT_TRUE(hit.has_value());
  const glm::vec3 radial = glm::normalize(hit->positionWorld - glm::vec3(0.0F, 1.0F, 0.0F));
  EXPECT_GT(glm::dot(hit->geometricNormal, radial), 0.99F);  // outward: the winding's front
  EXPECT_GT(glm::dot(hit->shadingNormal, radial), 0.9999F);  // smooth, closer than the facet
  EXPECT_NEAR(double(glm::length(hit->shadingNormal)), 1.0, 1e-5);
  const auto below = scene.intersect({glm::vec3(1.5F, -1.0F, 0.0F), glm::vec3(0.0F, 1.0F, 0.0F)});
  ASSERT_TRUE(below.has_value());
  EXPECT_GT(below->geometricNormal.y, 0.99F);  // not turned toward the ray
  const auto point =
      shadingPointOf(scene, {glm::vec3(1.5F, -1.0F, 0.0F), glm::vec3(0.0F, 1.0F, 0.0F)});
  ASSERT_TRUE(point.has_value());
  EXPECT_LT(point->normal.y, -0.99F);  // two-sided: turned toward the eye
}

TEST(EmbreeScene, OcclusionSeesBlockersOnlyWithinTheSegment) {
  const EmbreeScene scene = built(twoMeshScene());
  const glm::vec3 up(0.0F, 1.0F, 0.0F);
  EXPECT_TRUE(scene.occluded(glm::vec3(0.0F, 0.01F, 0.0F), up));
  EXPECT_FALSE(scene.occluded(glm::vec3(0.0F, 0.01F, 0.0F), up, 0.0F, 0.4F));
  EXPECT_FALSE(scene.occluded(glm::vec3(1.5F, 0.01F, 0.0F), up));
}

TEST(EmbreeScene, MissReturnsNothing) {
  const EmbreeScene scene = built(twoMeshScene());
  EXPECT_FALSE(scene.intersect({glm::vec3(0.0F, 5.0F, 0.0F), glm::vec3(0.0F, 1.0F, 0.0F)}));
}

TEST(EmbreeScene, BrokenSceneIsAnErrorNotACrash) {
  scene::Scene s = twoMeshScene();
  s.meshes[1].indices.back() = 1000000U;
  const auto result = EmbreeScene::build(s);
  ASSERT_FALSE(result.has_value());
  EXPECT_NE(result.error().find("two"), std::string::npos) << result.error();
}

TEST(EmbreeScene, EmptyMeshKeepsLaterMeshIndices) {
  scene::Scene s = twoMeshScene();
  s.meshes.insert(s.meshes.begin(), scene::Mesh{});
  const EmbreeScene scene = built(s);
  const auto sphere = scene.intersect({glm::vec3(0.0F, 5.0F, 0.0F), glm::vec3(0.0F, -1.0F, 0.0F)});
  ASSERT_TRUE(sphere.has_value());
  EXPECT_EQ(sphere->meshIndex, 2U);
}

}  // namespace
}  // namespace vem::embree
