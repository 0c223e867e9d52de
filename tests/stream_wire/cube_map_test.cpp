// cubeMapFromEnvMap: face orientation against the OpenGL specification's table (written out here
// independently of the code), constant maps, the hemisphere's black lower half, the box mip chain.
#include "core/cube_map.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <string>

#include <glm/geometric.hpp>

#include "core/env_map.h"
#include "proto/stream_protocol.h"

namespace vem {
namespace {

// OpenGL 4.6, section 8.13, table 8.19, inverted: the direction through (s, t) of a face.
glm::dvec3 glDirection(int face, double s, double t) {
  const double sc = 2 * s - 1;
  const double tc = 2 * t - 1;
  switch (face) {
    case 0: return glm::normalize(glm::dvec3{1, -tc, -sc});    // +X: sc = -rz, tc = -ry
    case 1: return glm::normalize(glm::dvec3{-1, -tc, sc});    // -X: sc = +rz, tc = -ry
    case 2: return glm::normalize(glm::dvec3{sc, 1, tc});      // +Y: sc = +rx, tc = +rz
    case 3: return glm::normalize(glm::dvec3{sc, -1, -tc});    // -Y: sc = +rx, tc = -rz
    case 4: return glm::normalize(glm::dvec3{sc, -tc, 1});     // +Z: sc = +rx, tc = -ry
    default: return glm::normalize(glm::dvec3{-sc, -tc, -1});  // -Z: sc = -rx, tc = -ry
  }
}

struct Texel {
  int face = -1;
  int row = -1;
  int column = -1;
  float value = -1.0F;
};

Texel brightestTexel(const CubeMapLevel& level) {
  Texel best;
  for (int face = 0; face < 6; ++face) {
    const std::vector<float>& texels = level.faces[std::size_t(face)];
    for (int i = 0; i < level.facePx * level.facePx; ++i) {
      const float red = texels[3 * std::size_t(i)];
      if (red > best.value) best = {face, i / level.facePx, i % level.facePx, red};
    }
  }
  return best;
}

// Background 1, and within `radiusRad` of `dir` a cone peaking at 1001 in direction `dir`.
EnvMap spotMap(MapLayout layout, int width, int height, glm::dvec3 dir, double radiusRad) {
  EnvMap map = EnvMap::filled(layout, width, height, glm::vec3(1.0F));
  const double cosRadius = std::cos(radiusRad);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const double c = glm::dot(pixelCentreDirection(map, x, y), dir);
      if (c >= cosRadius)
        map.set(x, y, glm::vec3(float(1.0 + 1000.0 * (c - cosRadius) / (1.0 - cosRadius))));
    }
  }
  return map;
}

// A texel (s, t) off every axis of symmetry of its face, so a flipped s or t or a swapped face
// moves the brightest texel far away.
constexpr double kSpotS = 0.28;
constexpr double kSpotT = 0.78;

void expectSpotAt(MapLayout layout, int face, double s, double t) {
  constexpr int kFacePx = 32;
  const glm::dvec3 dir = glDirection(face, s, t);
  const int height = layout == MapLayout::Sphere ? 512 : 256;
  const CubeMap cube = cubeMapFromEnvMap(spotMap(layout, 1024, height, dir, 0.08), kFacePx, 1);
  const Texel best = brightestTexel(cube.levels[0]);
  SCOPED_TRACE("face " + std::to_string(face) + " layout " + layoutName(layout));
  EXPECT_EQ(best.face, face);
  EXPECT_NEAR(best.column, int(s * kFacePx), 1);
  EXPECT_NEAR(best.row, int(t * kFacePx), 1);
  EXPECT_GT(best.value, 100.0F);
}

TEST(CubeMap, BrightSpotLandsOnItsDirectionsTexelOnEveryFace) {
  for (int face = 0; face < 6; ++face) expectSpotAt(MapLayout::Sphere, face, kSpotS, kSpotT);
}

TEST(CubeMap, BrightSpotOfAHemisphereMapLandsOnItsDirectionsTexel) {
  // The upper half of the side faces (y > 0 there is t < 0.5) and the +Y face: catches a
  // hemisphere azimuth taken as the sphere's (phi = psi - pi).
  for (const int face : {0, 1, 4, 5}) {
    expectSpotAt(MapLayout::Hemisphere, face, kSpotS, 1.0 - kSpotT);
  }
  expectSpotAt(MapLayout::Hemisphere, 2, kSpotS, kSpotT);
}

TEST(CubeMap, CubeTexelDirectionFollowsTheOpenGlTable) {
  for (int face = 0; face < 6; ++face) {
    for (const double u : {0.0, 3.5, 10.0, 16.0}) {
      for (const double v : {0.0, 1.5, 12.25, 16.0}) {
        const glm::dvec3 expected = glDirection(face, u / 16.0, v / 16.0);
        const glm::dvec3 got(cubeTexelDirection(face, 16, u, v));
        EXPECT_LT(glm::length(got - expected), 1e-6) << "face " << face << " u " << u << " v " << v;
      }
    }
  }
}

TEST(CubeMap, SmoothMapIsReproducedAtEveryTexelDirection) {
  // rgb = 2 + direction: any orientation, seam or row error shows as a wrong value.
  EnvMap map = EnvMap::filled(MapLayout::Sphere, 1024, 512, glm::vec3(0.0F));
  for (int y = 0; y < map.height; ++y) {
    for (int x = 0; x < map.width; ++x) {
      map.set(x, y, glm::vec3(2.0) + glm::vec3(pixelCentreDirection(map, x, y)));
    }
  }
  constexpr int kFacePx = 16;
  const CubeMap cube = cubeMapFromEnvMap(map, kFacePx, 1);
  double worst = 0.0;
  for (int face = 0; face < 6; ++face) {
    for (int row = 0; row < kFacePx; ++row) {
      for (int column = 0; column < kFacePx; ++column) {
        const glm::dvec3 dir = glDirection(face, (column + 0.5) / kFacePx, (row + 0.5) / kFacePx);
        const std::size_t i = 3 * std::size_t(row * kFacePx + column);
        const std::vector<float>& texels = cube.levels[0].faces[std::size_t(face)];
        const glm::dvec3 got{texels[i], texels[i + 1], texels[i + 2]};
        worst = std::max(worst, glm::length(got - (glm::dvec3(2.0) + dir)));
      }
    }
  }
  EXPECT_LT(worst, 0.01);
}

TEST(CubeMap, ConstantMapGivesAConstantCubeMapAtEveryLevel) {
  const glm::vec3 value{3.0F, 2.0F, 0.5F};
  const CubeMap cube = cubeMapFromEnvMap(EnvMap::filled(MapLayout::Sphere, 64, 32, value), 16, 5);
  ASSERT_EQ(cube.levels.size(), 5U);
  for (std::size_t k = 0; k < cube.levels.size(); ++k) {
    const CubeMapLevel& level = cube.levels[k];
    EXPECT_EQ(level.facePx, 16 >> k);
    for (const std::vector<float>& face : level.faces) {
      ASSERT_EQ(face.size(), 3 * std::size_t(level.facePx * level.facePx));
      for (std::size_t i = 0; i < face.size(); ++i) {
        ASSERT_NEAR(face[i], value[int(i % 3)], 1e-5) << "level " << k << " value " << i;
      }
    }
  }
}

TEST(CubeMap, HemisphereLowerHalfIsBlackAndUpperHalfKeepsTheMap) {
  constexpr int kFacePx = 16;
  const CubeMap cube = cubeMapFromEnvMap(
      EnvMap::filled(MapLayout::Hemisphere, 128, 32, glm::vec3(5.0F)), kFacePx, 1);
  for (int face = 0; face < 6; ++face) {
    for (int row = 0; row < kFacePx; ++row) {
      for (int column = 0; column < kFacePx; ++column) {
        const double y = glDirection(face, (column + 0.5) / kFacePx, (row + 0.5) / kFacePx).y;
        const float red =
            cube.levels[0].faces[std::size_t(face)][3 * std::size_t(row * kFacePx + column)];
        ASSERT_FLOAT_EQ(red, y < 0.0 ? 0.0F : 5.0F) << "face " << face << " row " << row;
      }
    }
  }
}

TEST(CubeMap, MipLevelIsTheBoxAverageOfTheLevelAbove) {
  EnvMap map = EnvMap::filled(MapLayout::Sphere, 256, 128, glm::vec3(0.0F));
  for (int y = 0; y < map.height; ++y) {
    for (int x = 0; x < map.width; ++x) {
      const float v = float((x * 7919 + y * 104729) % 1000);
      map.set(x, y, glm::vec3(v, 1000.0F - v, 0.5F * v));
    }
  }
  const CubeMap cube = cubeMapFromEnvMap(map, 32, 4);
  ASSERT_EQ(cube.levels.size(), 4U);
  for (std::size_t k = 1; k < cube.levels.size(); ++k) {
    const CubeMapLevel& above = cube.levels[k - 1];
    const CubeMapLevel& level = cube.levels[k];
    ASSERT_EQ(level.facePx * 2, above.facePx);
    for (std::size_t face = 0; face < 6; ++face) {
      const auto at = [&](int row, int column, int c) {
        return double(
            above.faces[face][3 * std::size_t(row * above.facePx + column) + std::size_t(c)]);
      };
      for (int row = 0; row < level.facePx; ++row) {
        for (int column = 0; column < level.facePx; ++column) {
          for (int c = 0; c < 3; ++c) {
            const double mean =
                0.25 * (at(2 * row, 2 * column, c) + at(2 * row, 2 * column + 1, c) +
                        at(2 * row + 1, 2 * column, c) + at(2 * row + 1, 2 * column + 1, c));
            const double got =
                level.faces[face][3 * std::size_t(row * level.facePx + column) + std::size_t(c)];
            ASSERT_NEAR(got, mean, 1e-3) << "level " << k << " face " << face;
          }
        }
      }
    }
  }
}

TEST(CubeMap, MipChainStopsAtTheFirstOddFaceSizeAsTheProtocolSays) {
  const EnvMap map = EnvMap::filled(MapLayout::Sphere, 64, 32, glm::vec3(1.0F));
  for (const int facePx : {8, 12, 64, 40}) {
    const CubeMap cube = cubeMapFromEnvMap(map, facePx, stream::kMaxCubeLevels);
    EXPECT_EQ(int(cube.levels.size()), stream::usableCubeLevels(facePx, stream::kMaxCubeLevels))
        << facePx;
    EXPECT_TRUE(cube.levels.back().facePx % 2 == 1 ||
                int(cube.levels.size()) == stream::kMaxCubeLevels)
        << facePx;
  }
  EXPECT_EQ(cubeMapFromEnvMap(map, 12, 8).levels.size(), 3U);  // 12, 6, 3
}

TEST(CubeMap, NegativeAndNanPixelsAreBlackAsTheLightsReadThem) {
  // sky.exr holds 11 negative pixels beside its sun (down to -3394): read raw, they took 12 % of
  // the map's light out of its cube maps while the lights and the reference clamp them to black.
  EnvMap map = EnvMap::filled(MapLayout::Sphere, 64, 32, glm::vec3(1.0F));
  for (int x = 0; x < map.width; ++x) {
    for (int y = 0; y < map.height; y += 2) {
      const std::size_t i = 3 * (std::size_t(y) * std::size_t(map.width) + std::size_t(x));
      map.rgb[i] = x % 2 == 0 ? -50.0F : std::nanf("");
    }
  }
  const CubeMap cube = cubeMapFromEnvMap(map, 16, 1);
  for (const std::vector<float>& face : cube.levels[0].faces) {
    for (const float v : face) {
      ASSERT_TRUE(std::isfinite(v));
      ASSERT_GE(v, 0.0F);
      ASSERT_LE(v, 1.0F);
    }
  }
}

}  // namespace
}  // namespace vem
