// Glossy surfaces: the shader's Blinn lobe against render::specularBrdf at the highlight pixel
// (catches a wrong normalisation, half vector or exponent), with and without the glossy L/H pass;
// and with many lights the glossy pass against core's glossyLightsFor() (catches a wrong S_L / S_H
// region lookup, cone test, H weight or the m / k rescaling).
#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include "client/render/shading_model.h"
#include "gl_test_support.h"

namespace vem::gl::test {
namespace {

constexpr int kW = 96;
constexpr int kH = 72;
const glm::vec3 kCentre(0.0F);

struct Reference {
  glm::vec3 diffuse{0.0F};
  glm::vec3 specular{0.0F};
};

// CPU radiance at pixel (x, y): every light diffusely, the glossy lights of glossyLightsFor (or
// every light) through the specular lobe.
std::optional<Reference> cpuRadiance(const scene::OrbitCamera& camera, int x, int y,
                                     const scene::Material& m,
                                     const render::ShadingLights& lights) {
  const auto hit = hitSphere(camera, x, y, kW, kH, kCentre, 1.0F);
  if (!hit || hit->cosView < 0.3F) return std::nullopt;
  Reference out;
  for (const Light& l : lights.diffuse.lights) {
    const float c = std::max(0.0F, glm::dot(hit->normal, l.dir));
    out.diffuse += render::diffuseBrdf(m) * l.rgb * c;
    if (!lights.glossy) out.specular += render::specularBrdf(m, hit->normal, hit->toEye, l.dir) * l.rgb * c;
  }
  if (lights.glossy) {
    const glm::vec3 r = render::reflectedDirection(hit->normal, hit->toEye);
    for (const GlossyShadingLight& g : glossyLightsFor(glm::dvec3(r), *lights.glossy,
                                                        testGeometry().glossyRegions,
                                                        lights.maxConeLights)) {
      const Light& l = lights.glossy->low.lights[g.index];
      const float c = std::max(0.0F, glm::dot(hit->normal, l.dir));
      out.specular += render::specularBrdf(m, hit->normal, hit->toEye, l.dir) * l.rgb * c *
                      float(g.weight);
    }
  }
  return out;
}

void expectHighlightMatches(const render::ShadingLights& lights) {
  const scene::Material m = blinn({0.2F, 0.2F, 0.2F}, {0.6F, 0.6F, 0.6F}, 60.0F);
  const scene::Scene s = sphereScene(m, kCentre, 1.0F);
  auto renderer = makeRenderer(s, kW, kH);
  ASSERT_NE(renderer, nullptr);
  const scene::OrbitCamera camera = scene::framingCamera(scene::sceneBounds(s), 0.6F, 0.3F);
  renderer->render(camera, lights, nullptr);
  const render::LinearImage image = renderer->readLinear();
  float best = 0.0F;
  int bx = 0;
  int by = 0;
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      const auto ref = cpuRadiance(camera, x, y, m, lights);
      if (ref && ref->specular.g > best) { best = ref->specular.g; bx = x; by = y; }
    }
  }
  ASSERT_GT(best, 0.5F);
  const auto ref = cpuRadiance(camera, bx, by, m, lights);
  const float expected = ref->diffuse.g + ref->specular.g;
  EXPECT_NEAR(image.at(bx, by).g, expected, 0.02F * expected) << bx << "," << by;
  EXPECT_GT(ref->specular.g, 2.0F * ref->diffuse.g);  // the highlight dominates: the lobe is tested
}

render::ShadingLights oneLight() {
  Light light;
  light.dir = glm::normalize(glm::vec3(0.2F, 1.0F, 0.9F));
  light.rgb = glm::vec3(4.0F);
  return plainLights({light});
}

TEST(Glossy, BlinnHighlightMatchesTheCpuShadingModelFromTheDiffuseLights) {
  expectHighlightMatches(oneLight());
}

TEST(Glossy, BlinnHighlightMatchesTheCpuShadingModelThroughTheGlossyPass) {
  expectHighlightMatches(withGlossy(oneLight(), 1, 216));
}

TEST(Glossy, GlossyPassMatchesCoreGlossyLightsForWithManyLights) {
  const scene::Material m = blinn({0.1F, 0.1F, 0.1F}, {0.7F, 0.7F, 0.7F}, 30.0F);
  const scene::Scene s = sphereScene(m, kCentre, 1.0F);
  auto renderer = makeRenderer(s, kW, kH);
  ASSERT_NE(renderer, nullptr);
  const render::ShadingLights lights =
      withGlossy(withRegions(plainLights(spreadLights(512, glm::vec3(6.0F)))), 32, 3);
  const scene::OrbitCamera camera = scene::framingCamera(scene::sceneBounds(s), 0.6F, 0.3F);
  renderer->render(camera, lights, nullptr);
  const render::LinearImage image = renderer->readLinear();
  int compared = 0;
  int close = 0;
  double sumGl = 0.0;
  double sumCpu = 0.0;
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      const auto ref = cpuRadiance(camera, x, y, m, lights);
      if (!ref) continue;
      const float expected = ref->diffuse.g + ref->specular.g;
      const float got = image.at(x, y).g;
      ++compared;
      if (std::abs(got - expected) <= 0.02F * expected + 1e-4F) ++close;
      sumGl += double(got);
      sumCpu += double(expected);
    }
  }
  ASSERT_GT(compared, 500);
  EXPECT_GT(close, compared * 9 / 10) << close << " of " << compared;
  EXPECT_NEAR(sumGl, sumCpu, 0.01 * sumCpu);
}

}  // namespace
}  // namespace vem::gl::test
