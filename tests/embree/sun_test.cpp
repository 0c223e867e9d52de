// A single hot pixel (a sun) over a plane: the closed form E albedo / pi, and shadows under a
// sphere that move with the sun, in both renderers.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include "client/embree/light_renderer.h"
#include "client/embree/reference_renderer.h"
#include "embree/embree_fixtures.h"

namespace vem::embree {
namespace {

using namespace testing;

constexpr int kMapW = 128;
constexpr int kMapH = 64;
constexpr float kSun = 5000.0F;

// Irradiance on a +Y plane from pixel (x, y) of radiance L: L (2 pi / W) (sin^2 t1 - sin^2 t0) / 2.
double hotPixelIrradiance(int y, double radiance) {
  const double t0 = std::numbers::pi * y / kMapH;
  const double t1 = std::numbers::pi * (y + 1) / kMapH;
  const double s0 = std::sin(t0);
  const double s1 = std::sin(t1);
  return radiance * (2.0 * std::numbers::pi / kMapW) * 0.5 * (s1 * s1 - s0 * s0);
}

// Catches env radiance looked up at the wrong pixel or with the bilinear value (the sun spreads),
// a pdf not matching the sampler, and a wrong albedo / pi. Per pixel the estimate has rare
// events (a BRDF sample that finds the sun adds 1/n, an environment sample that lands in the
// floor's share loses 1/n), so most pixels, not all, are held to 0.6 %.
TEST(SunOnPlane, ReferenceMatchesClosedFormIrradianceTimesAlbedoOverPi) {
  const glm::ivec2 sun(40, 20);
  const EnvMap map = hotPixelMap(kMapW, kMapH, sun, kSun, 0.0F);
  const EmbreeScene scene = built(planeScene(lambertian(0.5F), 20.0F));
  ReferenceOptions options;
  options.minSamples = 256;
  options.maxSamples = 256;
  const ReferenceResult result = renderReference(scene, cameraAt(glm::vec3(0.0F), 3.0F, 0.8F),
                                                 kWidthPx, kHeightPx, map, options);
  const double expected = 0.5 / std::numbers::pi * hotPixelIrradiance(sun.y, kSun);
  const std::vector<std::size_t> covered = coveredPixels(result.image);
  ASSERT_GT(covered.size(), 1000U);
  double sum = 0.0;
  std::size_t outliers = 0;
  for (const std::size_t i : covered) {
    const double value = double(result.image.rgb[3 * i]);
    sum += value;
    outliers += std::abs(value - expected) > 0.006 * expected ? 1U : 0U;
    ASSERT_NEAR(value, expected, 0.02 * expected) << "pixel " << i;
  }
  EXPECT_NEAR(sum / double(covered.size()), expected, 0.002 * expected);
  EXPECT_LE(outliers, covered.size() / 200);
}

TEST(SunOnPlane, LightsMatchClosedFormIrradianceTimesAlbedoOverPi) {
  const glm::ivec2 sun(40, 20);
  const EnvMap map = hotPixelMap(kMapW, kMapH, sun, kSun, 0.0F);
  const EmbreeScene scene = built(planeScene(lambertian(0.5F), 20.0F));
  const render::LightingGeometry geometry = render::makeLightingGeometry();
  const render::ShadingLights lights = shadingLightsFor(lightsFrom(map, 64), geometry, false, 16);
  const render::LinearImage image = renderWithLights(
      scene, cameraAt(glm::vec3(0.0F), 3.0F, 0.8F), kWidthPx, kHeightPx, lights, geometry, nullptr);
  const double expected = 0.5 / std::numbers::pi * hotPixelIrradiance(sun.y, kSun);
  for (const std::size_t i : coveredPixels(image)) {
    ASSERT_NEAR(double(image.rgb[3 * i]), expected, 0.01 * expected) << "pixel " << i;
  }
}

struct ShadowCase {
  glm::vec3 sphereCentre{0.0F, 1.0F, 0.0F};
  scene::OrbitCamera camera = cameraAt(glm::vec3(0.0F, 0.3F, 0.3F), 4.0F, 0.9F);
  EmbreeScene scene =
      built(sphereScene(sphereCentre, 0.5F, true, lambertian(0.5F), lambertian(0.5F)));
};

// Where the sphere's centre projects onto the plane along the sun's direction.
glm::vec3 shadowCentre(glm::vec3 sphereCentre, glm::vec3 sunDir) {
  return sphereCentre - sunDir * (sphereCentre.y / sunDir.y);
}

struct SunImages {
  render::LinearImage reference;
  render::LinearImage lights;
  glm::vec3 shadow{0.0F};
};

SunImages renderUnderSun(const ShadowCase& c, glm::vec3 wantedDir) {
  EnvMap map = hotPixelMap(kMapW, kMapH, glm::ivec2(0), 0.0F, 0.05F);
  const glm::ivec2 sun = pixelOfDirection(map, glm::normalize(wantedDir));
  map.set(sun.x, sun.y, glm::vec3(kSun));
  const glm::vec3 sunDir(pixelCentreDirection(map, sun.x, sun.y));
  ReferenceOptions options;
  options.targetRelativeError = 0.02;
  options.maxSamples = 128;
  SunImages out;
  out.reference = renderReference(c.scene, c.camera, kWidthPx, kHeightPx, map, options).image;
  const render::LightingGeometry geometry = render::makeLightingGeometry();
  const render::ShadingLights lights = shadingLightsFor(lightsFrom(map, 64), geometry, false, 16);
  out.lights = renderWithLights(c.scene, c.camera, kWidthPx, kHeightPx, lights, geometry, nullptr);
  out.shadow = shadowCentre(c.sphereCentre, sunDir);
  return out;
}

// Catches occlusion rays that never hit (no shadows), shadow rays cast away from the light
// (shadow on the wrong side), and a shadow test that ignores the light's direction.
TEST(SunShadow, ShadowUnderSphereIsDarkAndFollowsTheSun) {
  const ShadowCase c;
  const SunImages left = renderUnderSun(c, glm::vec3(-0.35F, 0.87F, -0.35F));
  const SunImages right = renderUnderSun(c, glm::vec3(0.35F, 0.87F, -0.35F));
  const auto leftPx = pixelOf(c.camera, left.shadow, kWidthPx, kHeightPx);
  const auto rightPx = pixelOf(c.camera, right.shadow, kWidthPx, kHeightPx);
  ASSERT_TRUE(leftPx && rightPx);
  ASSERT_GT(std::abs(leftPx->x - rightPx->x), 6);
  for (const render::LinearImage* image : {&left.reference, &left.lights}) {
    EXPECT_LT(neighbourhoodMean(*image, *leftPx), 0.2 * neighbourhoodMean(*image, *rightPx));
  }
  for (const render::LinearImage* image : {&right.reference, &right.lights}) {
    EXPECT_LT(neighbourhoodMean(*image, *rightPx), 0.2 * neighbourhoodMean(*image, *leftPx));
  }
}

// The shadows option: with V = 1 the plane under the sphere is as bright as elsewhere.
TEST(SunShadow, ShadowsOffLeavesNoShadow) {
  const ShadowCase c;
  EnvMap map = hotPixelMap(kMapW, kMapH, glm::ivec2(0), 0.0F, 0.05F);
  const glm::ivec2 sun = pixelOfDirection(map, glm::normalize(glm::vec3(-0.35F, 0.87F, -0.35F)));
  map.set(sun.x, sun.y, glm::vec3(kSun));
  const glm::vec3 shadow =
      shadowCentre(c.sphereCentre, glm::vec3(pixelCentreDirection(map, sun.x, sun.y)));
  const render::LightingGeometry geometry = render::makeLightingGeometry();
  const render::ShadingLights lights = shadingLightsFor(lightsFrom(map, 64), geometry, false, 16);
  LightRenderOptions options;
  options.shadows = false;
  const render::LinearImage image =
      renderWithLights(c.scene, c.camera, kWidthPx, kHeightPx, lights, geometry, nullptr, options);
  const auto px = pixelOf(c.camera, shadow, kWidthPx, kHeightPx);
  ASSERT_TRUE(px);
  const double lit = 0.5 / std::numbers::pi * hotPixelIrradiance(sun.y, kSun);
  EXPECT_GT(neighbourhoodMean(image, *px), 0.9 * lit);
}

}  // namespace
}  // namespace vem::embree
