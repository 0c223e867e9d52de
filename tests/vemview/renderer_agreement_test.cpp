// The OpenGL renderer against the Embree renderer and the Monte Carlo reference, on the default
// scene under a real HDRI: with the same lights the two renderers agree up to shadow-map
// resolution, and the OpenGL image approaches the reference as the light count grows.
#include <cstdio>
#include <gtest/gtest.h>

#include "client/render/image_metrics.h"
#include "vemview/render_rig.h"

namespace vem::testing {
namespace {

TEST(RendererAgreement, OpenGlAndEmbreeAgreeWithTheSameLightsOnTheDiffuseScene) {
  RenderRig rig(RigOptions{});
  const render::ShadingLights lights = rig.lights(64, 64);
  const render::ImageError e = render::compareImages(rig.gl(lights), rig.embree(lights));
  std::printf("diffuse scene, N = 64, S = 64: relative RMS %.4f, mean |dY| %.4f, >10%%: %.4f\n",
              e.relativeRms, e.meanAbsoluteRelative, e.fractionAbove(0.1));
  EXPECT_LT(e.relativeRms, 0.05);
  EXPECT_LT(e.fractionAbove(0.1), 0.03);  // shadow-map edges
  EXPECT_LT(e.coverageMismatch, 40U);     // silhouettes
}

}  // namespace
}  // namespace vem::testing

namespace vem::testing {
namespace {

TEST(RendererAgreement, OpenGlAndEmbreeAgreeWithTheSameLightsOnTheGlossyDefaultScene) {
  RigOptions options;
  options.sceneName = "default";
  RenderRig rig(options);
  const render::ShadingLights lights = rig.lights(256, 64);
  const render::ImageError e = render::compareImages(rig.gl(lights), rig.embree(lights));
  std::printf("default scene, N = 256, S = 64: relative RMS %.4f, mean |dY| %.4f, >10%%: %.4f\n",
              e.relativeRms, e.meanAbsoluteRelative, e.fractionAbove(0.1));
  EXPECT_LT(e.relativeRms, 0.08);
  EXPECT_LT(e.fractionAbove(0.1), 0.05);
}

}  // namespace
}  // namespace vem::testing
