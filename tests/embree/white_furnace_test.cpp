// White furnace: a Lambertian sphere of albedo 0.5 alone under a uniform map of radiance 1 sends
// radiance 0.5 toward every direction (irradiance pi everywhere), in the reference and with the
// lights core generates from the map.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include "client/embree/light_renderer.h"
#include "client/embree/reference_renderer.h"
#include "embree/embree_fixtures.h"

namespace vem::embree {
namespace {

using namespace testing;

struct Furnace {
  EmbreeScene scene =
      built(sphereScene(glm::vec3(0.0F), 1.0F, false, lambertian(0.5F), lambertian(0.5F)));
  scene::OrbitCamera camera = cameraAt(glm::vec3(0.0F), 4.0F, 0.3F);
  EnvMap map = EnvMap::filled(MapLayout::Sphere, 128, 64, glm::vec3(1.0F));
};

// Catches a wrong MIS weight, pdf or cosine in the reference (any gives a grey other than 0.5),
// and self-shadowing from a bad ray offset (dark speckles).
TEST(WhiteFurnace, ReferenceOfHalfAlbedoSphereIsHalfEverywhere) {
  const Furnace f;
  ReferenceOptions
      options;  // balance-heuristic MIS against a uniform map: ~0.38 relative per sample
  options.targetRelativeError = 0.01;
  const ReferenceResult result =
      renderReference(f.scene, f.camera, kWidthPx, kHeightPx, f.map, options);
  const std::vector<std::size_t> covered = coveredPixels(result.image);
  ASSERT_GT(covered.size(), 500U);
  double sum = 0.0;
  std::size_t outliers = 0;
  for (const std::size_t i : covered) {
    const double y = double(result.image.rgb[3 * i + 1]);
    sum += y;
    outliers += std::abs(y - 0.5) > 0.5 * 4.0 * result.relativeError ? 1U : 0U;
  }
  EXPECT_NEAR(sum / double(covered.size()), 0.5, 0.5 * 0.001);
  EXPECT_LE(outliers, covered.size() / 100) << "samples " << result.samplesPerPixel;
  std::printf("white furnace reference: %d samples per pixel, error %.4f\n", result.samplesPerPixel,
              result.relativeError);
  EXPECT_TRUE(result.converged);
  EXPECT_FALSE(result.image.covered[0]);  // corner: background
  EXPECT_NEAR(double(result.image.at(0, 0).y), 1.0, 1e-5);
}

// Catches lights whose rgb is not irradiance (a missing solid angle or 1/N), a missing 1/pi in
// the diffuse BRDF, or a wrong cosine. 256 lights of core's pattern give the irradiance of a
// uniform map to about 3 % per normal (+2.9 % toward +Z, the side this camera sees), 1024 to
// about 0.3 %: the tolerances follow the light count.
TEST(WhiteFurnace, LightsGiveHalfWithinTheirSamplingAccuracy) {
  const Furnace f;
  const render::LightingGeometry geometry = render::makeLightingGeometry();
  for (const auto& [count, meanTolerance, worstTolerance] :
       {std::tuple{256U, 0.025, 0.04}, std::tuple{1024U, 0.005, 0.01}}) {
    const render::ShadingLights lights =
        shadingLightsFor(lightsFrom(f.map, count), geometry, false, 72);
    const render::LinearImage image =
        renderWithLights(f.scene, f.camera, kWidthPx, kHeightPx, lights, geometry, nullptr);
    const std::vector<std::size_t> covered = coveredPixels(image);
    ASSERT_GT(covered.size(), 500U);
    double sum = 0.0;
    double worst = 0.0;
    for (const std::size_t i : covered) {
      const double y = double(image.rgb[3 * i + 1]);
      sum += y;
      worst = std::max(worst, std::abs(y - 0.5));
    }
    EXPECT_NEAR(sum / double(covered.size()), 0.5, 0.5 * meanTolerance) << count << " lights";
    EXPECT_LT(worst, 0.5 * worstTolerance) << count << " lights";
    EXPECT_EQ(image.at(0, 0), glm::vec3(0.0F));  // no cube map: black background
  }
}

}  // namespace
}  // namespace vem::embree
