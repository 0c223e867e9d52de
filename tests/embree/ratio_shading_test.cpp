// Shading by ratio (light_renderer.h with an EnvironmentLighting, issue 20): unoccluded surfaces
// take the prefiltered environment whatever the lights, a surface no light faces stays finite,
// a black map renders black, and a sun at 1e5 times the sky on a rough and on a mirror sphere
// stays finite and close to the Monte Carlo reference.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include "client/embree/light_renderer.h"
#include "client/embree/reference_renderer.h"
#include "client/render/environment_lighting.h"
#include "client/render/image_metrics.h"
#include "embree/embree_fixtures.h"

namespace vem::embree {
namespace {

using namespace testing;

scene::Material ggx(float roughness, glm::vec3 f0, float diffuse) {
  scene::Material m;
  m.lobe = scene::Lobe::Ggx;
  m.roughness = roughness;
  m.specularAlbedo = f0;
  m.diffuseAlbedo = glm::vec3(diffuse);
  return m;
}

// A gold GGX sphere (no diffuse part, the given GGX alpha) resting on a Lambertian plane, and the
// camera of the glossy tests, close on the sphere.
scene::Scene goldSphereOnPlane(float alpha) {
  return sphereScene(glm::vec3(0, 0.5F, 0), 0.5F, true,
                     ggx(std::sqrt(alpha), glm::vec3(1.0F, 0.78F, 0.34F), 0.0F), lambertian(0.5F));
}
scene::OrbitCamera goldSphereCamera() { return cameraAt(glm::vec3(0, 0.5F, 0), 2.2F, 0.35F); }

struct RatioRender {
  render::LinearImage image;
  bool finite = true;
};

RatioRender renderByRatio(const scene::Scene& s, const scene::OrbitCamera& camera,
                          const EnvMap& map, std::size_t lightCount, bool byRatio = true,
                          bool softShadows = false, int threadCount = 2,
                          double peakFactor = render::EnvironmentLightingOptions{}.peakFactor,
                          render::SpecularModel specularModel =
                              render::SpecularModel::FilteredSampling) {
  const EmbreeScene scene = built(s);
  const CubeMap cube = cubeMapFromEnvMap(map, 64, 7);
  render::EnvironmentLightingOptions environmentOptions;
  environmentOptions.peakFactor = peakFactor;
  environmentOptions.specularModel = specularModel;
  const render::EnvironmentLighting environment =
      render::makeEnvironmentLighting(cube, s.materials, environmentOptions);
  const render::LightingGeometry geometry = render::makeLightingGeometry();
  const render::ShadingLights lights =
      shadingLightsFor(lightsFrom(map, lightCount), geometry, !byRatio, 72);
  LightRenderOptions options;
  options.environment = byRatio ? &environment : nullptr;
  options.softShadows = softShadows;
  options.threadCount = threadCount;
  RatioRender out{
      renderWithLights(scene, camera, kWidthPx, kHeightPx, lights, geometry, &cube, options)};
  for (const float v : out.image.rgb) out.finite = out.finite && std::isfinite(v);
  return out;
}

TEST(RatioShading, UnoccludedPlaneTakesTheEnvironmentWhateverTheLightCount) {
  // Nothing can shadow a lone plane: every ratio is 1, so 4 lights and 256 give the same image,
  // the irradiance cube's. A ratio taken from the lights' unshadowed sum instead of 1 would make
  // 4 lights differ from 256 by the lights' noise (tens of per cent at 4).
  const scene::Scene s = planeScene(lambertian(0.6F), 10.0F);
  const scene::OrbitCamera camera = cameraAt(glm::vec3(0.0F), 3.0F, 0.8F);
  const EnvMap sky = smoothSky(128, 64);
  const RatioRender few = renderByRatio(s, camera, sky, 4);
  const RatioRender many = renderByRatio(s, camera, sky, 256);
  ASSERT_TRUE(few.finite && many.finite);
  const render::ImageError error = render::compareImages(few.image, many.image);
  ASSERT_GT(error.comparedPixels, 1000U);
  EXPECT_LT(error.relativeRms, 1e-5);
}

TEST(RatioShading, BlackMapRendersBlackWithoutNan) {
  const scene::Scene s = sphereScene(glm::vec3(0, 0.5F, 0), 0.5F, true,
                                     ggx(0.5F, glm::vec3(0.9F), 0.2F), lambertian(0.5F));
  const EnvMap black = EnvMap::filled(MapLayout::Sphere, 64, 32, glm::vec3(0.0F));
  const RatioRender r = renderByRatio(s, cameraAt(glm::vec3(0, 0.5F, 0), 3.0F, 0.4F), black, 64);
  ASSERT_TRUE(r.finite);
  for (const float v : r.image.rgb) ASSERT_EQ(v, 0.0F);
}

TEST(RatioShading, SunAtOneHundredThousandTimesTheSkyStaysFiniteAndNearTheReference) {
  // A one-pixel sun at 1e5 over a uniform sky of 1 (the sun carries about 94 % of the power),
  // a rough GGX sphere and a mirror sphere on a plane. The peaks go to the lights exactly; the
  // split sum alone, without the clip, was 0.14 to 2.3 times the exact highlight.
  const EnvMap map = hotPixelMap(128, 64, glm::ivec2(40, 20), 1e5F, 1.0F);
  const scene::OrbitCamera camera = cameraAt(glm::vec3(0, 0.5F, 0), 3.0F, 0.4F);
  for (const scene::Material& sphere :
       {ggx(0.6F, glm::vec3(0.9F, 0.7F, 0.35F), 0.0F), ggx(0.02F, glm::vec3(0.9F), 0.0F)}) {
    const scene::Scene s = sphereScene(glm::vec3(0, 0.5F, 0), 0.5F, true, sphere, lambertian(0.5F));
    const ReferenceOptions referenceOptions = fixedSamples(512);
    const ReferenceResult reference =
        renderReference(built(s), camera, kWidthPx, kHeightPx, map, referenceOptions);
    const RatioRender ratio = renderByRatio(s, camera, map, 256);
    const RatioRender sums = renderByRatio(s, camera, map, 256, false);
    ASSERT_TRUE(ratio.finite) << "roughness " << sphere.roughness;
    const double ratioError = render::compareImages(ratio.image, reference.image).relativeRms;
    const double sumsError = render::compareImages(sums.image, reference.image).relativeRms;
    // Measured: 1.9 % (rough) and 2.7 % (mirror) against 1.6 % and 2.2 % for the sums, which
    // need few lights for a one-texel sun over a uniform sky.
    EXPECT_LT(ratioError, 0.04) << "roughness " << sphere.roughness;
    EXPECT_LT(ratioError, sumsError + 0.015) << "roughness " << sphere.roughness;
  }
}

// Issue 20: "at most 4 % at the frame time of today's N = 256". A rough gold GGX sphere (alpha 0.6)
// on a plane under city's broad light, N = 256, against a 1024-sample reference: the split sum read
// P along R took light from too near the horizon for a lobe that leans toward the normal, and
// stayed 5.8 % off at every N (docs/shading-by-ratio.md); read along the dominant direction
// (render::specularLookupDirection) it is within 4 %.
TEST(RatioShading, RoughGgxUnderBroadLightIsWithinFourPerCentOfTheReference) {
  const EnvMap city = sharedHdri("city");
  const scene::Scene s = goldSphereOnPlane(0.6F);
  const scene::OrbitCamera camera = goldSphereCamera();
  const ReferenceOptions referenceOptions = fixedSamples(1024);
  const ReferenceResult reference =
      renderReference(built(s), camera, kWidthPx, kHeightPx, city, referenceOptions);
  const RatioRender ratio = renderByRatio(s, camera, city, 256);
  ASSERT_TRUE(ratio.finite);
  const double error = render::compareImages(ratio.image, reference.image).relativeRms;
  std::printf("rough GGX under city, N = 256, by ratio: %.2f %% (reference noise %.2f %%)\n",
              100.0 * error, 100.0 * reference.relativeError);
  EXPECT_LT(error, 0.04);
}

// The split sum's plateau: a gold GGX sphere (alpha 0.3) under studio.exr, whose light comes from
// a few softboxes, stayed 3.2-3.4 % off a 1 %-noise reference from N = 256 to 1024 with the peaks
// clipped at a fixed 20 times the mean: more lights did not help, because the split sum kept
// averaging the softboxes over the lobe. With the clip following N (render::peakFactorFor: 5 at
// N = 1024) the lights carry the softboxes exactly, and the error falls with N. Filtered
// importance sampling (the default) averages the lobe as it is, and beats the split sum with the
// same clip (measured: split sum 5.6 % with the fixed clip, 3.0 % with the clip following N;
// filtered sampling 2.1 %, against a reference whose own noise is 1.9 %).
TEST(RatioShading, GlossyUnderCompactSourcesKeepsFallingWithTheLightCount) {
  const EnvMap studio = sharedHdri("studio");
  const scene::Scene s = goldSphereOnPlane(0.3F);
  const scene::OrbitCamera camera = goldSphereCamera();
  const ReferenceResult reference =
      renderReference(built(s), camera, kWidthPx, kHeightPx, studio, fixedSamples(4096));
  const auto errorOf = [&](std::size_t n, double peakFactor, render::SpecularModel model) {
    const RatioRender r = renderByRatio(s, camera, studio, n, true, false, 2, peakFactor, model);
    EXPECT_TRUE(r.finite);
    return render::compareImages(r.image, reference.image).relativeRms;
  };
  const double fixed = errorOf(1024, 20.0, render::SpecularModel::SplitSum);
  const double following = errorOf(1024, render::peakFactorFor(1024), render::SpecularModel::SplitSum);
  const double filtered =
      errorOf(1024, render::peakFactorFor(1024), render::SpecularModel::FilteredSampling);
  std::printf("GGX 0.3 under studio, N = 1024, by ratio, split sum: clip at 20 x mean %.2f %%, at "
              "%.0f x mean %.2f %%; filtered sampling %.2f %% (reference noise %.2f %%)\n",
              100.0 * fixed, render::peakFactorFor(1024), 100.0 * following, 100.0 * filtered,
              100.0 * reference.relativeError);
  EXPECT_LT(following, 0.75 * fixed);
  EXPECT_LT(filtered, following);
}

// Soft shadows (LightRenderOptions::softShadows): at N = 16 each light stands for a large part of
// the sky, and its hard shadow on the plane was a sharp copy of the sphere's outline where the
// reference has a penumbra. A diffuse sphere on a plane under city: the error against the
// reference falls to under 0.6 of the hard shadows' (measured 0.50 with directions drawn from the
// lights' strata; 0.73 with cones around the lights' directions, which this catches, as it does
// cosines taken at the light's direction rather than the drawn one; the bench measures 4.8 % to
// 1.5 % at 160 x 120 against 1 % references; docs/shading-by-ratio.md).
TEST(RatioShading, SoftShadowsCutTheDiffuseErrorAtSixteenLights) {
  const EnvMap city = sharedHdri("city");
  const scene::Scene s =
      sphereScene(glm::vec3(0, 0.5F, 0), 0.5F, true, lambertian(0.8F), lambertian(0.5F));
  const scene::OrbitCamera camera = cameraAt(glm::vec3(0, 0.3F, 0), 3.0F, 0.5F);
  const ReferenceResult reference =
      renderReference(built(s), camera, kWidthPx, kHeightPx, city, fixedSamples(1024));
  const RatioRender hard = renderByRatio(s, camera, city, 16);
  const RatioRender soft = renderByRatio(s, camera, city, 16, true, true);
  ASSERT_TRUE(hard.finite && soft.finite);
  const double hardError = render::compareImages(hard.image, reference.image).relativeRms;
  const double softError = render::compareImages(soft.image, reference.image).relativeRms;
  std::printf("diffuse under city, N = 16, by ratio: hard %.2f %%, soft %.2f %% (reference %.2f %%)\n",
              100.0 * hardError, 100.0 * softError, 100.0 * reference.relativeError);
  EXPECT_LT(softError, 0.6 * hardError);  // measured 0.50
}

// A light as small as a texel (a sun) keeps its hard shadow: when every light is the sun, the soft
// render is the hard one. Catches a cone taken from the light's share of the power alone, which
// blurred a sun's shadow as much as a sky light's.
TEST(RatioShading, SoftShadowsLeaveASunsShadowHard) {
  const EnvMap sun = hotPixelMap(128, 64, glm::ivec2(40, 20), 1e5F, 0.0F);
  const scene::Scene s =
      sphereScene(glm::vec3(0, 0.5F, 0), 0.5F, true, lambertian(0.8F), lambertian(0.5F));
  const scene::OrbitCamera camera = cameraAt(glm::vec3(0, 0.3F, 0), 3.0F, 0.5F);
  const RatioRender hard = renderByRatio(s, camera, sun, 16);
  const RatioRender soft = renderByRatio(s, camera, sun, 16, true, true);
  ASSERT_TRUE(hard.finite && soft.finite);
  ASSERT_EQ(hard.image.rgb.size(), soft.image.rgb.size());
  for (std::size_t i = 0; i < hard.image.rgb.size(); ++i) {
    ASSERT_EQ(hard.image.rgb[i], soft.image.rgb[i]) << "value " << i;
  }
}

// The jitter is a fixed pattern of (pixel, light) and the filter reads only finished rows, so the
// image does not depend on how the rows are shared among threads.
TEST(RatioShading, SoftShadowsDoNotDependOnTheThreadCount) {
  const EnvMap city = sharedHdri("city");
  const scene::Scene s =
      sphereScene(glm::vec3(0, 0.5F, 0), 0.5F, true, lambertian(0.8F), lambertian(0.5F));
  const scene::OrbitCamera camera = cameraAt(glm::vec3(0, 0.3F, 0), 3.0F, 0.5F);
  const RatioRender one = renderByRatio(s, camera, city, 16, true, true, 1);
  const RatioRender two = renderByRatio(s, camera, city, 16, true, true, 2);
  ASSERT_EQ(one.image.rgb, two.image.rgb);
}

}  // namespace
}  // namespace vem::embree
