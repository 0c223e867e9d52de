// The L/H estimator for glossy surfaces (paper 004 section 4.2) approaches the Monte Carlo
// reference as N grows, on the specular highlight, and mirror-like materials reflect the cube map.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include "client/embree/light_renderer.h"
#include "client/embree/reference_renderer.h"
#include "client/render/shading_model.h"
#include "core/cube_map.h"
#include "embree/embree_fixtures.h"

namespace vem::embree {
namespace {

using namespace testing;

// The brightest tenth of the covered pixels of the reference: the highlight.
std::vector<std::size_t> highlightPixels(const render::LinearImage& reference) {
  std::vector<std::size_t> covered = coveredPixels(reference);
  std::ranges::sort(covered, [&](std::size_t a, std::size_t b) {
    return luminanceAt(reference, a) > luminanceAt(reference, b);
  });
  covered.resize(std::max<std::size_t>(covered.size() / 10, 1));
  return covered;
}

// Catches L/H weights that do not add up (the error would not fall with N), lights of H counted
// inside the cone too, and the specular lobe shaded with the wrong direction.
TEST(GlossyLights, LowHighEstimatorApproachesReferenceAsLightsGrow) {
  const EmbreeScene scene =
      built(sphereScene(glm::vec3(0.0F), 1.0F, false, phong(0.2F, 0.6F, 200.0F), lambertian(0.5F)));
  const scene::OrbitCamera camera = cameraAt(glm::vec3(0.0F), 4.0F, 0.25F);
  const EnvMap map = smoothSky(256, 128);
  ReferenceOptions options;
  options.targetRelativeError = 0.004;
  const ReferenceResult reference = renderReference(scene, camera, 48, 36, map, options);
  const std::vector<std::size_t> highlight = highlightPixels(reference.image);
  const render::LightingGeometry geometry = render::makeLightingGeometry();
  LightRenderOptions noShadows;  // a lone convex sphere: nothing to shadow
  noShadows.shadows = false;
  std::vector<double> errors;
  for (const std::size_t n : {256U, 4096U}) {
    const render::ShadingLights lights =
        shadingLightsFor(lightsFrom(map, n), geometry, true, n / 4);
    const render::LinearImage image =
        renderWithLights(scene, camera, 48, 36, lights, geometry, nullptr, noShadows);
    errors.push_back(relativeRmsOver(image, reference.image, highlight));
  }
  std::printf(
      "L/H highlight error vs reference (%d samples, error %.4f): N=256 %.4f, N=4096 %.4f\n",
      reference.samplesPerPixel, reference.relativeError, errors[0], errors[1]);
  EXPECT_LT(errors[1], 0.6 * errors[0]) << errors[0] << " -> " << errors[1];
  EXPECT_LT(errors[1], 0.05) << "reference error " << reference.relativeError;
}

// Catches a mirror that reflects the lights or the background direction instead of R.
TEST(GlossyLights, MirrorReflectsTheCubeMapAlongTheReflectedDirection) {
  scene::Material mirror = phong(0.0F, 0.9F, 5000.0F);
  const EmbreeScene scene = built(sphereScene(glm::vec3(0.0F), 1.0F, false, mirror, mirror));
  const scene::OrbitCamera camera = cameraAt(glm::vec3(0.0F), 4.0F, 0.25F);
  const EnvMap map = smoothSky(128, 64);
  const CubeMap cube = cubeMapFromEnvMap(map, 32, 1);
  const render::LightingGeometry geometry = render::makeLightingGeometry();
  const render::ShadingLights lights = shadingLightsFor(lightsFrom(map, 64), geometry, true, 16);
  const render::LinearImage image =
      renderWithLights(scene, camera, 48, 36, lights, geometry, &cube);
  const scene::Ray ray = camera.primaryRay(24.5F, 18.5F, 48, 36);
  const auto hit = scene.intersect(ray);
  ASSERT_TRUE(hit);
  const glm::vec3 r = render::reflectedDirection(hit->shadingNormal, -ray.dirWorld);
  const glm::vec3 expected = 0.9F * sampleEnvMapBilinear(map, glm::dvec3(r));
  EXPECT_NEAR(double(image.at(24, 18).y), double(expected.y), 0.03 * double(expected.y));
  const ReferenceResult reference = renderReference(scene, camera, 48, 36, map);
  EXPECT_NEAR(double(reference.image.at(24, 18).y), double(expected.y), 1e-3 * double(expected.y));
}

}  // namespace
}  // namespace vem::embree
