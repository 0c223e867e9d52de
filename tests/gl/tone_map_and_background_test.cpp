// The display pass and the background: the tone-mapping shader must equal render::toneMappedSrgb8
// of the linear image (catches a different luminance, white point, sRGB curve or a flipped
// read-back), and the background must show each cube-map face where the view looks at it
// (catches a wrong face order, a mirrored face or an inverted view reconstruction), and nothing
// below the horizon of a hemisphere's cube map (catches the grey strip at the top of vemview's
// default view of vemd's stream).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <numbers>

#include "client/render/tone_mapping.h"
#include "gl_test_support.h"

namespace vem::gl::test {
namespace {

const std::array<glm::vec3, 6> kFaceColours = {
    glm::vec3(1.0F, 0.0F, 0.0F), glm::vec3(0.0F, 1.0F, 0.0F), glm::vec3(0.0F, 0.0F, 1.0F),
    glm::vec3(1.0F, 1.0F, 0.0F), glm::vec3(0.0F, 1.0F, 1.0F), glm::vec3(1.0F, 0.0F, 1.0F)};

CubeMap constantFaces() {
  CubeMap cube;
  CubeMapLevel level;
  level.facePx = 4;
  for (std::size_t f = 0; f < 6; ++f) {
    for (int t = 0; t < 16; ++t) {
      for (int c = 0; c < 3; ++c) level.faces[f].push_back(kFaceColours[f][c] * 2.0F);
    }
  }
  cube.levels.push_back(level);
  return cube;
}

TEST(ToneMapPass, DisplayImageEqualsTheCpuToneMappingOfTheLinearImage) {
  constexpr int kW = 80;
  constexpr int kH = 60;
  const scene::Scene s = sphereOverPlane();
  auto renderer = makeRenderer(s, kW, kH);
  ASSERT_NE(renderer, nullptr);
  std::vector<Light> lights = spreadLights(16, glm::vec3(2.0F, 1.5F, 1.0F));
  lights[0].rgb = glm::vec3(40.0F, 30.0F, 20.0F);  // a sun: values well past white
  const CubeMap cube = constantFaces();
  renderer->render(scene::framingCamera(scene::sceneBounds(s)), plainLights(lights), &cube, 1);
  const render::LinearImage linear = renderer->readLinear();
  const render::ToneParams params{0.4, 0.18, 2.5};
  renderer->presentToneMapped(params);
  const std::vector<std::uint8_t> gl = renderer->readDisplaySrgb8();
  const std::vector<std::uint8_t> cpu = render::toneMappedSrgb8(linear, params);
  ASSERT_EQ(gl.size(), cpu.size());
  int worst = 0;
  int distinct = 0;
  for (std::size_t i = 0; i < gl.size(); ++i) {
    worst = std::max(worst, std::abs(int(gl[i]) - int(cpu[i])));
    if (cpu[i] != cpu[0]) ++distinct;
  }
  EXPECT_LE(worst, 1);
  EXPECT_GT(distinct, int(gl.size()) / 4);  // a real picture, not a flat one
}

TEST(Background, EachCubeFaceShowsWhereTheViewLooksAtIt) {
  constexpr int kW = 32;
  constexpr int kH = 24;
  auto renderer = makeRenderer(sphereScene(lambertian(glm::vec3(0.5F)), {0.0F, 0.0F, 0.0F}, 0.01F),
                               kW, kH);
  ASSERT_NE(renderer, nullptr);
  const CubeMap cube = constantFaces();
  // The view direction is -(cos e cos a, sin e, cos e sin a) (scene/orbit_camera.h).
  struct View { float azimuthRad; float elevationRad; int face; };
  const float pi = 3.14159265F;
  for (const View view : {View{pi, 0.0F, 0}, View{0.0F, 0.0F, 1}, View{0.0F, -1.5F, 2},
                          View{0.0F, 1.5F, 3}, View{-pi / 2, 0.0F, 4}, View{pi / 2, 0.0F, 5}}) {
    scene::OrbitCamera camera;
    camera.distance = 5.0F;
    camera.azimuthRad = view.azimuthRad;
    camera.elevationRad = view.elevationRad;
    camera.verticalFovRad = 0.3F;
    renderer->render(camera, plainLights({}), &cube, 1);
    const render::LinearImage image = renderer->readLinear();
    // A corner pixel: away from the tiny sphere at the centre.
    const glm::vec3 got = image.at(kW / 4, kH / 4);
    EXPECT_NEAR(got.r, 2.0F * kFaceColours[std::size_t(view.face)].r, 1e-4F) << view.face;
    EXPECT_NEAR(got.g, 2.0F * kFaceColours[std::size_t(view.face)].g, 1e-4F) << view.face;
    EXPECT_NEAR(got.b, 2.0F * kFaceColours[std::size_t(view.face)].b, 1e-4F) << view.face;
    EXPECT_EQ(image.covered[std::size_t((kH / 4) * kW + kW / 4)], 0);
  }
}

TEST(Background, IsUploadedOnlyWhenTheVersionChanges) {
  auto renderer = makeRenderer(sphereOverPlane(), 32, 24);
  ASSERT_NE(renderer, nullptr);
  const CubeMap cube = constantFaces();
  const scene::OrbitCamera camera = scene::framingCamera(scene::sceneBounds(sphereOverPlane()));
  EXPECT_TRUE(renderer->render(camera, plainLights({}), &cube, 1).backgroundUploaded);
  EXPECT_FALSE(renderer->render(camera, plainLights({}), &cube, 1).backgroundUploaded);
  EXPECT_TRUE(renderer->render(camera, plainLights({}), &cube, 2).backgroundUploaded);
}

// vemd streams the cube map of its hemisphere polar map (core/cube_map.h: black below the
// horizon). vemview's default view (elevation 20 degrees, vertical field 0.7 rad) puts the horizon
// at the top edge, so every row below it must look like the rows under it: black. Linear filtering
// used to blend the first sky texels half a texel (0.45 degrees) below the horizon: a grey band
// over the top 3 rows at 240 px, 6 at 480.
TEST(Background, HemisphereCubeMapLeavesNoGreyStripAtTheTopOfTheDefaultView) {
  constexpr int kW = 320;
  constexpr int kH = 240;
  const scene::Scene s = sphereOverPlane();
  auto renderer = makeRenderer(s, kW, kH, 256, MapLayout::Hemisphere);
  ASSERT_NE(renderer, nullptr);
  const CubeMap cube =
      cubeMapFromEnvMap(EnvMap::filled(MapLayout::Hemisphere, 256, 64, glm::vec3(1.0F)), 128, 8);
  constexpr float kDeg = std::numbers::pi_v<float> / 180.0F;
  const scene::OrbitCamera camera = scene::viewingCamera(s, 35.0F * kDeg, 20.0F * kDeg);
  renderer->render(camera, plainLights({}), &cube, 1);
  const render::LinearImage image = renderer->readLinear();
  // Mean luminance of each row's background pixels whose ray points below the horizon.
  std::vector<double> rowMean;
  for (int y = 0; y < 24; ++y) {
    double sum = 0.0;
    int count = 0;
    for (int x = 0; x < kW; ++x) {
      const bool covered = image.covered[std::size_t(y * kW + x)] != 0;
      if (covered || camera.primaryRay(float(x) + 0.5F, float(y) + 0.5F, kW, kH).dirWorld.y >= 0) {
        continue;
      }
      sum += double(image.at(x, y).g);  // a white sky: r = g = b
      ++count;
    }
    if (count > kW / 2) rowMean.push_back(sum / count);
  }
  ASSERT_GE(rowMean.size(), 20U) << "the view's top rows look below the horizon";
  double below = 0.0;
  for (std::size_t y = 6; y < rowMean.size(); ++y) below += rowMean[y];
  below /= double(rowMean.size() - 6);
  for (std::size_t y = 0; y < 6; ++y) {
    EXPECT_NEAR(rowMean[y], below, 1e-3) << "row " << y << " is a band unlike the rows below";
  }
  // The cube is there: looking level, a quarter of the way down is sky.
  const scene::OrbitCamera level = scene::viewingCamera(s, 35.0F * kDeg, 0.0F);
  renderer->render(level, plainLights({}), &cube, 1);
  const render::LinearImage sky = renderer->readLinear();
  EXPECT_EQ(sky.covered[std::size_t((kH / 4) * kW + 4)], 0);
  EXPECT_NEAR(sky.at(4, kH / 4).g, 1.0F, 0.05F);
}

}  // namespace
}  // namespace vem::gl::test
