// The lighting shader's diffuse term against the CPU shading model (render/shading_model.h) at
// pixel centres of an unshadowed Lambertian sphere: catches wrong BRDF normalisation, light
// packing (dir/rgb swapped), missed lights, flipped images (row 0 must be the top).
#include <gtest/gtest.h>

#include <algorithm>

#include <glm/glm.hpp>

#include "client/render/shading_model.h"
#include "gl_test_support.h"

namespace vem::gl::test {
namespace {

constexpr int kW = 96;
constexpr int kH = 72;

TEST(LambertianSphere, MatchesTheCpuShadingModelAtPixelCentres) {
  const glm::vec3 centre(0.0F, 0.2F, 0.0F);
  const scene::Scene sphere = sphereScene(lambertian({0.8F, 0.6F, 0.4F}), centre, 1.0F);
  auto renderer = makeRenderer(sphere, kW, kH);
  ASSERT_NE(renderer, nullptr);
  std::vector<Light> lights(3);
  lights[0].dir = glm::normalize(glm::vec3(0.3F, 1.0F, 0.2F));
  lights[0].rgb = {3.0F, 2.5F, 2.0F};
  lights[1].dir = glm::normalize(glm::vec3(-1.0F, 0.2F, 0.6F));
  lights[1].rgb = {0.2F, 0.5F, 1.5F};
  lights[2].dir = glm::normalize(glm::vec3(0.7F, -0.1F, 1.0F));  // low, from the camera side
  lights[2].rgb = {1.0F, 0.1F, 0.1F};
  const scene::OrbitCamera camera = scene::framingCamera(scene::sceneBounds(sphere), 0.6F, 0.5F);
  renderer->render(camera, plainLights(lights), nullptr);
  const render::LinearImage image = renderer->readLinear();

  const glm::vec3 f = render::diffuseBrdf(sphere.materials[0]);
  int compared = 0;
  int coveredMismatch = 0;
  float worstRelative = 0.0F;
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      const auto hit = hitSphere(camera, x, y, kW, kH, centre, 1.0F);
      if (!hit || hit->cosView < 0.3F) {
        if (!hit && image.covered[std::size_t(y * kW + x)] != 0) ++coveredMismatch;
        continue;
      }
      EXPECT_EQ(image.covered[std::size_t(y * kW + x)], 1) << x << "," << y;
      glm::vec3 expected(0.0F);
      for (const Light& l : lights) {
        expected += f * l.rgb * std::max(0.0F, glm::dot(hit->normal, l.dir));
      }
      const glm::vec3 got = image.at(x, y);
      for (int c = 0; c < 3; ++c) {
        const float scale = std::max(expected[c], 0.1F);
        worstRelative = std::max(worstRelative, std::abs(got[c] - expected[c]) / scale);
      }
      ++compared;
    }
  }
  EXPECT_GT(compared, kW * kH / 10);
  EXPECT_LT(coveredMismatch, kW);  // only silhouette pixels may differ
  EXPECT_LT(worstRelative, 0.01F);
}

}  // namespace
}  // namespace vem::gl::test
