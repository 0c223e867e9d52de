#include "client/render/cube_map_sampling.h"

#include <gtest/gtest.h>

namespace vem::render {
namespace {

CubeMap constantFaces(int facePx) {
  CubeMap cube;
  CubeMapLevel level;
  level.facePx = facePx;
  for (int f = 0; f < 6; ++f) {
    level.faces[std::size_t(f)].assign(std::size_t(facePx * facePx * 3), 0.0F);
    for (int i = 0; i < facePx * facePx; ++i) {
      level.faces[std::size_t(f)][std::size_t(3 * i + f % 3)] = float(f + 1);
    }
  }
  cube.levels.push_back(level);
  return cube;
}

TEST(CubeMapSampling, EachAxisSeesItsOwnFaceInGlOrder) {
  const CubeMap cube = constantFaces(8);
  const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (int f = 0; f < 6; ++f) {
    const glm::vec3 c = sampleCubeMap(cube, axes[f]);
    EXPECT_FLOAT_EQ(c[f % 3], float(f + 1)) << "face " << f;
  }
}

TEST(CubeMapSampling, TexelCentresReturnTheTexelItselfNotANeighbour) {
  EnvMap map = EnvMap::filled(MapLayout::Sphere, 64, 32, glm::vec3(0.0F));
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 64; ++x) {
      map.set(x, y, glm::vec3(float(x), float(y), 1.0F));
    }
  }
  const CubeMap cube = cubeMapFromEnvMap(map, 16, 1);
  const int f = 16;
  for (int face = 0; face < 6; ++face) {
    for (int row = 1; row < f - 1; row += 3) {
      for (int column = 1; column < f - 1; column += 3) {
        const glm::vec3 dir = cubeTexelDirection(face, f, column + 0.5, row + 0.5);
        const std::size_t i = 3 * std::size_t(row * f + column);
        const auto& texels = cube.levels[0].faces[std::size_t(face)];
        const glm::vec3 expected(texels[i], texels[i + 1], texels[i + 2]);
        const glm::vec3 got = sampleCubeMap(cube, dir);
        EXPECT_NEAR(got.x, expected.x, 1e-3F);
        EXPECT_NEAR(got.y, expected.y, 1e-3F);
      }
    }
  }
}

// The Embree renderer's background of vemd's stream (a hemisphere's cube map): just below the
// horizon it is black, as the map holds nothing there, not the sky that linear filtering blends
// half a texel (0.45 degrees at 128 px) below it: the grey strip atop vemview's default view.
TEST(CubeMapSampling, HemisphereBackgroundLeavesNoGreyStripBelowTheHorizon) {
  const CubeMap cube =
      cubeMapFromEnvMap(EnvMap::filled(MapLayout::Hemisphere, 256, 64, glm::vec3(1.0F)), 128, 1);
  const glm::vec3 justBelow(1.0F, -0.003F, 0.0F);  // 0.17 degrees below the horizon
  EXPECT_GT(sampleCubeMap(cube, justBelow).g, 0.1F) << "the filter blends sky below the horizon";
  EXPECT_EQ(sampleBackground(cube, MapLayout::Hemisphere, justBelow), glm::vec3(0.0F));
  EXPECT_EQ(sampleBackground(cube, MapLayout::Sphere, justBelow), sampleCubeMap(cube, justBelow));
  EXPECT_NEAR(sampleBackground(cube, MapLayout::Hemisphere, {1.0F, 0.2F, 0.0F}).g, 1.0F, 1e-5F);
}

}  // namespace
}  // namespace vem::render
