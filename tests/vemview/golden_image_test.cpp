// Golden images: the default scene under a real HDRI, rendered by the OpenGL renderer (headless,
// llvmpipe) and by the Embree renderer with the same lights, tone-mapped, against the pictures in
// tests/vemview/golden/ (tolerances and the update mode: golden_compare.h).
#include <gtest/gtest.h>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "client/render/image_files.h"
#include "client/render/tone_mapping.h"
#include "vemview/golden_compare.h"
#include "vemview/render_rig.h"

namespace vem::testing {
namespace {

std::vector<std::uint8_t> toneMapped(const render::LinearImage& image) {
  const render::ToneParams tone =
      render::ToneSmoother().update(render::measureLuminance(image), 0.0);
  return render::toneMappedSrgb8(image, tone);
}

void compareWithGolden(const render::LinearImage& image, const std::string& name) {
  compareSrgb8WithGolden(toneMapped(image), image.widthPx, image.heightPx, name);
}

RigOptions goldenRig() {
  RigOptions options;
  options.sceneName = "default";
  options.mapName = "park";
  options.widthPx = 160;
  options.heightPx = 120;
  options.shadowMapPx = 256;
  return options;
}

TEST(GoldenImage, OpenGlDefaultSceneUnderParkLooksAsItDid) {
  RenderRig rig(goldenRig());
  compareWithGolden(rig.gl(rig.lights(128, 64)), "default-park-gl.png");
}

TEST(GoldenImage, EmbreeDefaultSceneUnderParkLooksAsItDid) {
  RenderRig rig(goldenRig());
  compareWithGolden(rig.embree(rig.lights(128, 64)), "default-park-embree.png");
}

TEST(GoldenImage, OpenGlDefaultSceneUnderTheSunLooksAsItDid) {
  RigOptions options = goldenRig();
  options.mapName = "sky";
  RenderRig rig(options);
  compareWithGolden(rig.gl(rig.lights(128, 64)), "default-sky-gl.png");
}

// Issue 20 part 3: a sphere standing on a plane under the sun, the contact and the sun's shadow
// close up; rendered with the maps' view spanning the whole scene, the contact came out as a dark
// blurred halo (this picture then differs by more than the tolerance).
TEST(GoldenImage, OpenGlSphereOnAPlaneUnderTheSunHasASharpContactShadow) {
  RenderRig rig(sphereOnAPlaneUnderTheSun());
  compareWithGolden(rig.gl(rig.lights(256, 256)), "spheres-sky-gl.png");
}

}  // namespace
}  // namespace vem::testing
