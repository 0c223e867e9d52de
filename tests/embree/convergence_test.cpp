// The reference converges as 1 / sqrt(n), stops at its target, and is deterministic; the light
// renderer is deterministic and independent of its thread count.
#include <cmath>

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include "client/embree/light_renderer.h"
#include "client/embree/reference_renderer.h"
#include "embree/embree_fixtures.h"

namespace vem::embree {
namespace {

using namespace testing;

struct SkyScene {
  EmbreeScene scene = built(sphereScene(glm::vec3(0.0F, 1.0F, 0.0F), 0.5F, true,
                                        phong(0.4F, 0.3F, 30.0F), lambertian(0.6F)));
  scene::OrbitCamera camera = cameraAt(glm::vec3(0.0F, 0.5F, 0.0F), 3.5F, 0.5F);
  EnvMap map = smoothSky(128, 64);
};

ReferenceResult fixedCount(const SkyScene& s, int samples, std::uint64_t seed, int threads = 2) {
  ReferenceOptions options;
  options.targetRelativeError = 0.0;  // never converged: exactly `samples`
  options.maxSamples = samples;
  options.seed = seed;
  options.threadCount = threads;
  return renderReference(s.scene, s.camera, 48, 36, s.map, options);
}

// Catches a variance estimate that is not per sample (it would not fall as 1 / sqrt(n)) and
// correlated samples (the same numbers in every pass: the true error would stall).
TEST(ReferenceConvergence, ErrorFallsAsOneOverSqrtSamples) {
  const SkyScene s;
  const ReferenceResult coarse = fixedCount(s, 32, 1);
  const ReferenceResult fine = fixedCount(s, 128, 1);
  const ReferenceResult truth = fixedCount(s, 1024, 99);
  EXPECT_EQ(coarse.samplesPerPixel, 32);
  EXPECT_EQ(fine.samplesPerPixel, 128);
  EXPECT_FALSE(fine.converged);
  EXPECT_NEAR(coarse.relativeError / fine.relativeError, 2.0, 0.4);
  const std::vector<std::size_t> covered = coveredPixels(truth.image);
  const double coarseTrue = relativeRmsOver(coarse.image, truth.image, covered);
  const double fineTrue = relativeRmsOver(fine.image, truth.image, covered);
  EXPECT_GT(coarseTrue / fineTrue, 1.5) << coarseTrue << " " << fineTrue;
  EXPECT_LT(fineTrue, 0.05);
}

// Catches a loop that ignores its target (always maxSamples) or stops before it.
TEST(ReferenceConvergence, StopsOnceTheTargetErrorIsReached) {
  const SkyScene s;
  ReferenceOptions options;
  options.targetRelativeError = 0.03;
  options.samplesPerPass = 16;
  const ReferenceResult result = renderReference(s.scene, s.camera, 48, 36, s.map, options);
  EXPECT_TRUE(result.converged);
  EXPECT_LT(result.relativeError, 0.03);
  EXPECT_LT(result.samplesPerPixel, options.maxSamples);
  EXPECT_EQ(result.samplesPerPixel % 16, 0);
  const ReferenceResult previous = fixedCount(s, result.samplesPerPixel - 16, options.seed);
  EXPECT_GE(previous.relativeError, 0.03);  // one pass fewer had not converged
}

// Catches shared RNG state between threads or pixels (results would depend on scheduling).
TEST(Determinism, ReferenceIsTheSameTwiceAndWithAnyThreadCount) {
  const SkyScene s;
  const ReferenceResult a = fixedCount(s, 32, 5, 2);
  const ReferenceResult b = fixedCount(s, 32, 5, 2);
  const ReferenceResult c = fixedCount(s, 32, 5, 1);
  EXPECT_EQ(a.image.rgb, b.image.rgb);
  EXPECT_EQ(a.image.rgb, c.image.rgb);
  EXPECT_EQ(a.image.covered, c.image.covered);
  const ReferenceResult other = fixedCount(s, 32, 6, 2);
  EXPECT_NE(a.image.rgb, other.image.rgb);  // the seed matters
}

TEST(Determinism, LightRendererIsTheSameTwiceAndWithAnyThreadCount) {
  const SkyScene s;
  const render::LightingGeometry geometry = render::makeLightingGeometry();
  const render::ShadingLights lights = shadingLightsFor(lightsFrom(s.map, 256), geometry, true, 64);
  LightRenderOptions one;
  one.threadCount = 1;
  const render::LinearImage a =
      renderWithLights(s.scene, s.camera, 48, 36, lights, geometry, nullptr);
  const render::LinearImage b =
      renderWithLights(s.scene, s.camera, 48, 36, lights, geometry, nullptr);
  const render::LinearImage c =
      renderWithLights(s.scene, s.camera, 48, 36, lights, geometry, nullptr, one);
  EXPECT_EQ(a.rgb, b.rgb);
  EXPECT_EQ(a.rgb, c.rgb);
  EXPECT_EQ(a.covered, c.covered);
}

}  // namespace
}  // namespace vem::embree
