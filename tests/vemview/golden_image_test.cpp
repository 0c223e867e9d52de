// Golden images: the default scene under a real HDRI, rendered by the OpenGL renderer (headless,
// llvmpipe) and by the Embree renderer with the same lights, tone-mapped, against the pictures in
// tests/vemview/golden/. Tolerance: the mean absolute difference of the 8-bit sRGB values below
// kMeanTolerance and at most kOutlierFraction of the values off by more than kOutlierLevels
// (rasteriser and driver differences move a few silhouette and shadow-edge pixels).
// Update mode: VEM_UPDATE_GOLDEN=1 rewrites the golden pictures from this build (then review them
// and commit), and the tests report that they updated rather than compared.
#include <gtest/gtest.h>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "client/render/image_files.h"
#include "client/render/tone_mapping.h"
#include "vemview/render_rig.h"

namespace vem::testing {
namespace {

constexpr double kMeanTolerance = 1.5;
constexpr double kOutlierFraction = 0.01;
constexpr int kOutlierLevels = 24;

std::filesystem::path goldenPath(const std::string& name) {
  return std::filesystem::path(VEM_SOURCE_DIR) / "tests" / "vemview" / "golden" / name;
}

std::vector<std::uint8_t> toneMapped(const render::LinearImage& image) {
  const render::ToneParams tone =
      render::ToneSmoother().update(render::measureLuminance(image), 0.0);
  return render::toneMappedSrgb8(image, tone);
}

void compareWithGolden(const render::LinearImage& image, const std::string& name) {
  const std::vector<std::uint8_t> rendered = toneMapped(image);
  const auto path = goldenPath(name);
  if (std::getenv("VEM_UPDATE_GOLDEN") != nullptr) {
    ASSERT_TRUE(render::saveSrgbPng(rendered, image.widthPx, image.heightPx, path).has_value());
    std::printf("updated %s\n", path.c_str());
    return;
  }
  const auto golden = render::loadSrgb8(path);
  ASSERT_TRUE(golden.has_value()) << golden.error() << " (VEM_UPDATE_GOLDEN=1 makes it)";
  ASSERT_EQ(golden->widthPx, image.widthPx);
  ASSERT_EQ(golden->heightPx, image.heightPx);
  double sum = 0.0;
  std::size_t outliers = 0;
  for (std::size_t i = 0; i < rendered.size(); ++i) {
    const int d = std::abs(int(rendered[i]) - int(golden->rgb[i]));
    sum += d;
    outliers += d > kOutlierLevels ? 1 : 0;
  }
  const double mean = sum / double(rendered.size());
  const double fraction = double(outliers) / double(rendered.size());
  std::printf("%s: mean |difference| %.3f levels, %.4f %% beyond %d levels\n", name.c_str(), mean,
              100.0 * fraction, kOutlierLevels);
  EXPECT_LT(mean, kMeanTolerance) << name;
  EXPECT_LT(fraction, kOutlierFraction) << name;
  if (::testing::Test::HasFailure()) {
    const auto failed = std::filesystem::temp_directory_path() / ("failed-" + name);
    (void)render::saveSrgbPng(rendered, image.widthPx, image.heightPx, failed);
    std::printf("the rendered picture is in %s\n", failed.c_str());
  }
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
