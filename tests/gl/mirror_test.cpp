// A mirror's reflection in the OpenGL renderer (client/gl/mirror_occlusion.h): black where the
// scene blocks the reflected ray, as Embree's renderer and the Monte Carlo reference (direct light
// only) show it, and the cube map elsewhere. Without the occlusion a mirror sphere reflected the
// sky where the plane under it is, 7.4 % off the reference under sky.exr.
#include <cmath>

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include "client/render/shading_model.h"
#include "core/cube_map.h"
#include "gl_test_support.h"

namespace vem::gl::test {
namespace {

constexpr int kW = 96;
constexpr int kH = 72;

// Whether the ray p + t r (t > 0) crosses the 6 x 6 ground at y = 0, and how far inside its edge.
std::optional<float> groundMarginOf(glm::vec3 p, glm::vec3 r) {
  if (r.y >= -1e-3F) return std::nullopt;
  const glm::vec3 q = p - (p.y / r.y) * r;
  return 3.0F - std::max(std::abs(q.x), std::abs(q.z));
}

TEST(Mirror, ReflectionIsBlackWhereTheGroundBlocksItAndTheCubeMapElsewhere) {
  if (headlessContext() == nullptr) GTEST_SKIP() << "no EGL context";
  scene::Material mirror;
  mirror.lobe = scene::Lobe::Ggx;
  mirror.roughness = 0.02F;
  mirror.specularAlbedo = glm::vec3(0.9F);
  mirror.diffuseAlbedo = glm::vec3(0.0F);
  ASSERT_TRUE(mirror.mirrorLike());
  scene::Scene s = sphereOverPlane();
  s.materials.push_back(mirror);
  s.meshes[0].material = 1;
  const auto renderer = makeRenderer(s, kW, kH);
  ASSERT_NE(renderer, nullptr);
  scene::OrbitCamera camera;
  camera.targetWorld = {0.0F, 1.0F, 0.0F};
  camera.distance = 2.5F;
  camera.elevationRad = 0.15F;
  camera.verticalFovRad = 0.7F;
  const CubeMap cube =
      cubeMapFromEnvMap(EnvMap::filled(MapLayout::Sphere, 128, 64, glm::vec3(1.0F)), 32, 1);
  renderer->render(camera, plainLights({}), &cube, 1);
  const render::LinearImage image = renderer->readLinear();
  int blocked = 0;
  int open = 0;
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      const auto hit = hitSphere(camera, x, y, kW, kH, {0.0F, 1.0F, 0.0F}, 0.5F);
      // Away from the silhouette (interpolated normals) and from the ground's edge in reflection.
      if (!hit || hit->cosView < 0.3F) continue;
      const glm::vec3 r = render::reflectedDirection(hit->normal, hit->toEye);
      const std::optional<float> margin = groundMarginOf(hit->pointWorld, r);
      const float green = image.at(x, y).y;
      if (margin && *margin > 0.3F) {
        EXPECT_LT(green, 1e-4F) << "pixel " << x << ", " << y << " reflects the ground";
        ++blocked;
      } else if (!margin && r.y > 0.05F) {
        const float expected = render::mirrorReflectance(mirror, hit->normal, hit->toEye).y;
        EXPECT_NEAR(green, expected, 0.03F * expected) << "pixel " << x << ", " << y;
        ++open;
      }
    }
  }
  EXPECT_GT(blocked, 100);
  EXPECT_GT(open, 100);
}

}  // namespace
}  // namespace vem::gl::test
