// Angular-region culling (paper 004 section 4.1) must not change the image: the list of the
// normal's region holds every light with n . dir > 0, in light order, so walking it sums the same
// terms in the same order as walking all lights. Catches a wrong cube-map face order or
// orientation, wrong offsets, or lists read with the wrong stride.
#include <gtest/gtest.h>

#include <algorithm>

#include "client/scene/primitives.h"
#include "gl_test_support.h"

namespace vem::gl::test {
namespace {

constexpr int kW = 120;
constexpr int kH = 90;

TEST(AngularRegions, RegionsOnAndOffGiveTheSameImage) {
  scene::Scene s = sphereOverPlane();
  s.meshes.push_back(scene::boxMesh({0.8F, 0.0F, -0.6F}, {1.4F, 0.7F, 0.1F}, 0));
  auto renderer = makeRenderer(s, kW, kH);
  ASSERT_NE(renderer, nullptr);
  // Lights over the whole sphere (below the horizon too), strong enough to matter one by one.
  std::vector<Light> lights = spreadLights(200, glm::vec3(40.0F));
  for (std::size_t i = 0; i < lights.size(); i += 2) lights[i].dir.y = -lights[i].dir.y;
  for (std::size_t i = 0; i < lights.size(); ++i) lights[i].rgb *= 1.0F + float(i % 7);
  const scene::OrbitCamera camera = scene::framingCamera(scene::sceneBounds(s), 0.9F, 0.45F);

  renderer->render(camera, plainLights(lights), nullptr);
  const render::LinearImage off = renderer->readLinear();
  const render::ShadingLights regionLights = withRegions(plainLights(lights));
  ASSERT_FALSE(regionLights.diffuseLists.offsets.empty());
  ASSERT_LT(regionLights.diffuseLists.meanFraction(lights.size()), 0.9);  // regions do cull
  renderer->render(camera, regionLights, nullptr);
  const render::LinearImage on = renderer->readLinear();

  float maxValue = 0.0F;
  float maxDiff = 0.0F;
  for (std::size_t i = 0; i < off.rgb.size(); ++i) {
    maxValue = std::max(maxValue, off.rgb[i]);
    maxDiff = std::max(maxDiff, std::abs(off.rgb[i] - on.rgb[i]));
  }
  EXPECT_GT(maxValue, 0.5F);
  EXPECT_LE(maxDiff, 1e-5F * maxValue);
  EXPECT_EQ(off.covered, on.covered);
}

}  // namespace
}  // namespace vem::gl::test
