// The prefiltered environment (render/environment_lighting.h) against closed forms: irradiance of
// a uniform sphere and of a uniform sky above a black ground, a small sun at 1e5 times the sky,
// prefiltering that keeps a constant, directional albedo against a brute-force hemisphere
// integral of the same BRDF, and black or NaN texels.
#include "client/render/environment_lighting.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <utility>

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include "client/render/shading_model.h"

namespace vem::render {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

CubeMap cubeFrom(int facePx, const std::function<glm::vec3(glm::vec3)>& radiance) {
  CubeMap cube;
  CubeMapLevel& level = cube.levels.emplace_back();
  level.facePx = facePx;
  for (int face = 0; face < 6; ++face) {
    std::vector<float>& texels = level.faces[std::size_t(face)];
    texels.resize(std::size_t(3 * facePx * facePx));
    for (int row = 0; row < facePx; ++row) {
      for (int column = 0; column < facePx; ++column) {
        const glm::vec3 v = radiance(cubeTexelDirection(face, facePx, column + 0.5, row + 0.5));
        const std::size_t i = 3 * (std::size_t(row) * std::size_t(facePx) + std::size_t(column));
        texels[i] = v.x;
        texels[i + 1] = v.y;
        texels[i + 2] = v.z;
      }
    }
  }
  return cube;
}

scene::Material ggx(float roughness) {
  scene::Material m;
  m.lobe = scene::Lobe::Ggx;
  m.roughness = roughness;
  m.specularAlbedo = glm::vec3(0.9F, 0.7F, 0.35F);
  m.diffuseAlbedo = glm::vec3(0.0F);
  return m;
}

scene::Material lobe(scene::Lobe kind, float exponent) {
  scene::Material m;
  m.lobe = kind;
  m.exponent = exponent;
  m.specularAlbedo = glm::vec3(0.5F);
  m.diffuseAlbedo = glm::vec3(0.3F);
  return m;
}

const std::vector<glm::vec3> kNormals{
    glm::normalize(glm::vec3(0, 1, 0)), glm::normalize(glm::vec3(1, 1, 0)),
    glm::normalize(glm::vec3(0.3F, 0.2F, -1)), glm::normalize(glm::vec3(1, 0, 0)),
    glm::normalize(glm::vec3(-0.2F, -1, 0.4F))};

// The split sum's P is read toward the lobe's dominant direction: R for Phong (its lobe is centred
// on R) and for a sharp lobe, leaning toward n as GGX or Blinn get rougher; at normal incidence
// n = R, so every blend reads n.
TEST(EnvironmentLighting, SpecularLookupLeansTowardTheNormalAsTheLobeGetsRougher) {
  EXPECT_EQ(specularLookupBlend(lobe(scene::Lobe::Phong, 10.0F)), 1.0F);
  float previous = 1.0F;
  for (const float alpha : {0.01F, 0.1F, 0.3F, 0.6F, 1.0F}) {
    const float blend = specularLookupBlend(ggx(std::sqrt(alpha)));
    EXPECT_LT(blend, previous) << "alpha " << alpha;
    EXPECT_GE(blend, 0.0F);
    previous = blend;
  }
  EXPECT_NEAR(specularLookupBlend(ggx(0.1F)), 1.0F, 0.01F);  // alpha 0.01: as sharp as R
  EXPECT_EQ(specularLookupBlend(ggx(1.0F)), 0.0F);           // alpha 1: the normal
  // Blinn: the GGX blend of the alpha with the same peak, alpha^2 = 2 / (e + 2).
  EXPECT_NEAR(specularLookupBlend(lobe(scene::Lobe::Blinn, 98.0F)),
              specularLookupBlend(ggx(std::sqrt(std::sqrt(0.02F)))), 1e-5F);
  const glm::vec3 n(0.0F, 1.0F, 0.0F);
  const glm::vec3 grazing = glm::normalize(glm::vec3(1.0F, 0.2F, 0.0F));
  const glm::vec3 r = reflectedDirection(n, grazing);
  EXPECT_NEAR(glm::length(specularLookupDirection(n, grazing, 0.5F)), 1.0F, 1e-6F);
  EXPECT_GT(glm::dot(specularLookupDirection(n, grazing, 0.5F), n), glm::dot(r, n));
  EXPECT_NEAR(glm::dot(specularLookupDirection(n, n, 0.3F), n), 1.0F, 1e-6F);
}

TEST(EnvironmentLighting, UniformSphereGivesPiIrradianceInEveryDirection) {
  const CubeMap cube = cubeFrom(32, [](glm::vec3) { return glm::vec3(2.0F); });
  const CubeMap e = irradianceCubeOf(cube, 16);
  for (const glm::vec3 n : kNormals) {
    scene::Material white;
    white.diffuseAlbedo = glm::vec3(1.0F);
    EnvironmentLighting lighting;
    lighting.irradiance = e;
    // A white Lambertian surface under a uniform radiance L sends back L.
    EXPECT_NEAR(unshadowedDiffuse(lighting, white, n).y, 2.0F, 2.0F * 0.003F) << n.x << n.y << n.z;
  }
}

TEST(EnvironmentLighting, SkyAboveBlackGroundWeighsTexelsByTheirSolidAngle) {
  // Without the solid-angle weights the corner texels of each face would count as much as the
  // centre ones, and a horizontal surface would not see exactly half the sky's pi.
  const CubeMap cube =
      cubeFrom(32, [](glm::vec3 d) { return glm::vec3(d.y > 0.0F ? 1.0F : 0.0F); });
  EnvironmentLighting lighting;
  lighting.irradiance = irradianceCubeOf(cube, 16);
  scene::Material white;
  white.diffuseAlbedo = glm::vec3(1.0F);
  const auto irradiance = [&](glm::vec3 n) {
    return kPi * unshadowedDiffuse(lighting, white, n).x;
  };
  EXPECT_NEAR(irradiance(glm::vec3(0, 1, 0)), kPi, kPi * 0.003F);
  EXPECT_NEAR(irradiance(glm::vec3(0, -1, 0)), 0.0F, kPi * 0.003F);  // texels 2.5 degrees off
  // A tilted normal at angle t from up: (pi / 2) (1 + cos t); sampled between texel centres.
  // On the edge between the +X and +Y faces, where a clamped read would be 1.4 % off.
  const glm::vec3 tilted = glm::normalize(glm::vec3(1, 1, 0.3F));
  EXPECT_NEAR(irradiance(tilted), kPi / 2.0F * (1.0F + tilted.y), kPi * 0.003F);
}

TEST(EnvironmentLighting, SunAtOneHundredThousandTimesTheSkyKeepsTheSkyAndTheSunsCosine) {
  // A sun of 1e5 times the sky's radiance in one texel of a 32 px cube (1.6e-3 sr): the float
  // sums must keep the sky's share (under 1 %) and follow the sun's cosine.
  constexpr int kFacePx = 32;
  const glm::vec3 sunDir = cubeTexelDirection(4, kFacePx, 20.5, 9.5);  // on face +Z
  const float m = std::max({std::abs(sunDir.x), std::abs(sunDir.y), std::abs(sunDir.z)});
  const float sunSr = (2.0F / kFacePx) * (2.0F / kFacePx) * m * m * m;
  const CubeMap cube = cubeFrom(kFacePx, [&](glm::vec3 d) {
    return glm::vec3(glm::dot(d, sunDir) > 0.99999F ? 1e5F : 1.0F);
  });
  EnvironmentLighting lighting;
  lighting.irradiance = irradianceCubeOf(cube, 16);
  scene::Material white;
  white.diffuseAlbedo = glm::vec3(1.0F);
  for (const glm::vec3 n : kNormals) {
    const float expected = kPi * 1.0F + (1e5F - 1.0F) * sunSr * std::max(0.0F, glm::dot(n, sunDir));
    const float got = kPi * unshadowedDiffuse(lighting, white, n).x;
    ASSERT_TRUE(std::isfinite(got));
    // Bilinear reads of a 16 px irradiance cube: the sun's cosine is linear over a texel, up to
    // the curvature of the cosine, under 2 % of the sun's peak.
    EXPECT_NEAR(got, expected, 0.02F * 1e5F * sunSr + 0.01F * kPi)
        << n.x << " " << n.y << " " << n.z;
  }
}

TEST(EnvironmentLighting, PrefilteringAUniformEnvironmentKeepsItForEveryLobe) {
  const CubeMap cube = cubeFrom(32, [](glm::vec3) { return glm::vec3(3.0F, 2.0F, 1.0F); });
  for (const scene::Material& m : {ggx(0.3F), ggx(0.55F), ggx(0.77F), lobe(scene::Lobe::Phong, 10),
                                   lobe(scene::Lobe::Phong, 100), lobe(scene::Lobe::Blinn, 40)}) {
    const CubeMap p = prefilteredCubeOf(cube, m);
    for (const glm::vec3 r : kNormals) {
      EnvironmentLighting lighting;
      lighting.specularModel = SpecularModel::SplitSum;
      lighting.specular.resize(1);
      lighting.specular[0] = SpecularEnvironment{p, {}};
      lighting.specular[0]->albedo.scale.fill(1.0F);
      scene::Material grey = m;
      grey.specularAlbedo = glm::vec3(1.0F);
      // n = wo = r: R = r, rho = 1 by the table above.
      const glm::vec3 got = unshadowedSpecular(lighting, 0, grey, r, r);
      EXPECT_NEAR(got.x, 3.0F, 3.0F * 1e-4F) << scene::lobeName(m.lobe) << " " << m.exponent;
      EXPECT_NEAR(got.z, 1.0F, 1e-4F);
    }
  }
}

// The directional albedo toward wo by a midpoint rule over the hemisphere (n = +Y), green.
float bruteForceAlbedo(const scene::Material& m, float mu) {
  const glm::vec3 n(0, 1, 0);
  const glm::vec3 wo(std::sqrt(1.0F - mu * mu), mu, 0.0F);
  constexpr int kSteps = 800;
  double sum = 0.0;
  for (int i = 0; i < kSteps; ++i) {
    const double c = (i + 0.5) / kSteps;
    const double s = std::sqrt(1.0 - c * c);
    for (int j = 0; j < 2 * kSteps; ++j) {
      const double phi = (j + 0.5) * std::numbers::pi / kSteps;
      const glm::vec3 wi(glm::dvec3(s * std::cos(phi), c, s * std::sin(phi)));
      sum += double(specularBrdf(m, n, wo, wi).y) * c;
    }
  }
  return float(sum / kSteps * std::numbers::pi / kSteps);
}

TEST(EnvironmentLighting, DirectionalAlbedoTableMatchesTheHemisphereIntegralOfTheSameBrdf) {
  for (const scene::Material& m : {ggx(0.3F), ggx(0.77F), lobe(scene::Lobe::Phong, 10),
                                   lobe(scene::Lobe::Phong, 100), lobe(scene::Lobe::Blinn, 40)}) {
    const DirectionalAlbedo table = directionalAlbedoOf(m);
    for (const float mu : {0.2F, 0.5F, 0.9F}) {
      const float expected = bruteForceAlbedo(m, mu);
      const float got = directionalAlbedo(table, m, mu).y;
      // The table is linear between 32 cosines; GGX at 0.2 changes fastest there.
      EXPECT_NEAR(got, expected, 0.015F * expected + 2e-3F)
          << scene::lobeName(m.lobe) << " roughness " << m.roughness << " exponent " << m.exponent
          << " mu " << mu;
    }
  }
}

TEST(EnvironmentLighting, PrefilteredSunPeaksInItsOwnDirectionAndFallsWithTheLobe) {
  const glm::vec3 sunDir = glm::normalize(glm::vec3(0.3F, 0.8F, 0.2F));
  const CubeMap cube = cubeFrom(
      32, [&](glm::vec3 d) { return glm::vec3(glm::dot(d, sunDir) > 0.995F ? 1e5F : 1.0F); });
  const scene::Material rough = ggx(0.55F);
  const scene::Material sharp = ggx(0.3F);
  const CubeMap pRough = prefilteredCubeOf(cube, rough);
  const CubeMap pSharp = prefilteredCubeOf(cube, sharp);
  const auto at = [](const CubeMap& c, glm::vec3 d) {
    EnvironmentLighting l;
    l.specularModel = SpecularModel::SplitSum;
    l.specular.resize(1);
    l.specular[0] = SpecularEnvironment{c, {}};
    l.specular[0]->albedo.scale.fill(1.0F);
    scene::Material one = ggx(0.5F);
    one.specularAlbedo = glm::vec3(1.0F);
    return unshadowedSpecular(l, 0, one, d, d).x;
  };
  // 40 degrees from the sun's centre (34 from its edge): a tenth of GGX 0.3's lobe width in h is
  // 4.5 degrees, of GGX 0.55's 14 degrees.
  const glm::vec3 side = glm::normalize(glm::cross(sunDir, glm::vec3(0, 0, 1)));
  const float angle = 40.0F * kPi / 180.0F;
  const glm::vec3 off = std::cos(angle) * sunDir + std::sin(angle) * side;
  EXPECT_GT(at(pSharp, sunDir), at(pRough, sunDir));  // the sharper lobe keeps more of the peak
  EXPECT_GT(at(pSharp, sunDir), 10.0F * at(pSharp, off));
  EXPECT_GT(at(pRough, off), at(pSharp, off));  // the rough lobe spreads it wider
}

TEST(EnvironmentLighting, BlackAndNanTexelsGiveZeroNotNan) {
  const CubeMap black = cubeFrom(16, [](glm::vec3) { return glm::vec3(0.0F); });
  const CubeMap nanPatch = cubeFrom(
      16, [](glm::vec3 d) { return d.x > 0.9F ? glm::vec3(std::nanf("")) : glm::vec3(0.0F); });
  std::vector<scene::Material> materials{ggx(0.3F), lobe(scene::Lobe::Blinn, 40)};
  for (const auto& [cube, model] : {std::pair{&black, SpecularModel::FilteredSampling},
                                    std::pair{&nanPatch, SpecularModel::FilteredSampling},
                                    std::pair{&black, SpecularModel::SplitSum},
                                    std::pair{&nanPatch, SpecularModel::SplitSum}}) {
    EnvironmentLightingOptions options;
    options.specularModel = model;
    const EnvironmentLighting lighting = makeEnvironmentLighting(*cube, materials, options);
    for (const glm::vec3 n : kNormals) {
      for (std::size_t i = 0; i < materials.size(); ++i) {
        const glm::vec3 d = unshadowedDiffuse(lighting, materials[i], n);
        const glm::vec3 s = unshadowedSpecular(lighting, i, materials[i], n, n);
        EXPECT_EQ(d, glm::vec3(0.0F));
        EXPECT_EQ(s, glm::vec3(0.0F));
      }
    }
  }
}

TEST(EnvironmentLighting, PrefilterResolutionFollowsTheLobeWidth) {
  EXPECT_EQ(prefilterFacePxOf(ggx(0.77F)), 4);
  EXPECT_LE(prefilterFacePxOf(ggx(0.77F)), prefilterFacePxOf(ggx(0.55F)));
  EXPECT_EQ(prefilterFacePxOf(ggx(0.3F)), kMaxPrefilterFacePx);
  EXPECT_LT(prefilterFacePxOf(lobe(scene::Lobe::Phong, 10)),
            prefilterFacePxOf(lobe(scene::Lobe::Phong, 100)));
}

TEST(EnvironmentLighting, PeakFractionsGiveTheLightsWhatTheClippedCubesLeaveOut) {
  // A sun of 1e5 in one texel over a sky of 1: the specular cubes are clipped at T = 20 times
  // the mean, and a light on the sun carries 1 - T / 1e5 of its rgb, a light in the sky none.
  constexpr int kFacePx = 32;
  const glm::vec3 sunDir = cubeTexelDirection(4, kFacePx, 20.5, 9.5);
  const CubeMap cube = cubeFrom(kFacePx, [&](glm::vec3 d) {
    return glm::vec3(glm::dot(d, sunDir) > 0.99999F ? 1e5F : 1.0F);
  });
  const std::vector<scene::Material> materials{ggx(0.3F)};
  const EnvironmentLighting lighting = makeEnvironmentLighting(cube, materials);
  const float m = std::max({std::abs(sunDir.x), std::abs(sunDir.y), std::abs(sunDir.z)});
  const float sunSr = (2.0F / kFacePx) * (2.0F / kFacePx) * m * m * m;
  const float mean = (4.0F * kPi + (1e5F - 1.0F) * sunSr) / (4.0F * kPi);
  EXPECT_NEAR(lighting.peakLuminance, 20.0F * mean, 0.01F * 20.0F * mean);
  std::vector<Light> lights(2);
  lights[0].dir = sunDir;
  lights[1].dir = glm::vec3(0, 1, 0);
  const std::vector<float> fractions = peakFractionsOf(lighting, cube, lights);
  EXPECT_NEAR(fractions[0], 1.0F - lighting.peakLuminance / 1e5F, 1e-4F);
  EXPECT_EQ(fractions[1], 0.0F);
  // Without a glossy material nothing is clipped, and no light carries a peak.
  const EnvironmentLighting diffuseOnly = makeEnvironmentLighting(cube, {});
  EXPECT_EQ(peakFractionsOf(diffuseOnly, cube, lights), std::vector<float>(2, 0.0F));
}

// The clip follows the light count: 20 sqrt(64 / N) within [5, 40]; no light at all is the few
// lights' 40, not a division by zero.
// Catches the split sum's view-independent lobe, and a wrong density, level or sample set in the
// filtered importance sampling: a GGX 0.3 surface under a sky that brightens toward the zenith
// over a dark ground, seen from the normal to grazing. Against the brute-force integral over
// every texel, filtered sampling stays within 3 % (measured 1.4 % at most; 7 % at n . wo = 0.15
// with GGX drawn from D(h) (n . h) rather than its visible normals); the split sum is off by 13 %
// at grazing.
TEST(EnvironmentLighting, FilteredSamplingFollowsTheViewDependentLobeWhereTheSplitSumCannot) {
  const CubeMap level0 =
      cubeFrom(64, [](glm::vec3 d) { return glm::vec3(d.y > 0.0F ? 0.2F + 2.0F * d.y : 0.05F); });
  const CubeMap cube = cubeMapFromLevel0(level0.levels.front(), 16);
  const std::vector<scene::Material> materials{ggx(0.3F)};
  EnvironmentLightingOptions options;
  options.peakFactor = 1e9;  // nothing clipped: the integral is the whole environment's
  const EnvironmentLighting filtered = makeEnvironmentLighting(cube, materials, options);
  options.specularModel = SpecularModel::SplitSum;
  const EnvironmentLighting splitSum = makeEnvironmentLighting(cube, materials, options);
  ASSERT_FALSE(filtered.clipped.levels.empty());
  const int f = 64;
  const float cellArea = (2.0F / float(f)) * (2.0F / float(f));
  float worstFiltered = 0.0F;
  float worstSplit = 0.0F;
  const glm::vec3 n = glm::normalize(glm::vec3(0.3F, 1.0F, 0.2F));
  for (const float cosView : {0.95F, 0.6F, 0.3F, 0.15F}) {
    glm::vec3 t = glm::normalize(glm::cross(n, glm::vec3(0.0F, 0.0F, 1.0F)));
    const glm::vec3 wo = cosView * n + std::sqrt(1.0F - cosView * cosView) * t;
    double exact = 0.0;
    for (int face = 0; face < 6; ++face) {
      for (int row = 0; row < f; ++row) {
        for (int column = 0; column < f; ++column) {
          const glm::vec3 l = cubeTexelDirection(face, f, column + 0.5, row + 0.5);
          const float cosI = glm::dot(n, l);
          if (cosI <= 0.0F) continue;
          const float m = std::max({std::abs(l.x), std::abs(l.y), std::abs(l.z)});
          const float radiance = l.y > 0.0F ? 0.2F + 2.0F * l.y : 0.05F;
          exact += double(specularBrdf(materials[0], n, wo, l).y * radiance * cosI * cellArea *
                          m * m * m);
        }
      }
    }
    const float f1 = unshadowedSpecular(filtered, 0, materials[0], n, wo).y;
    const float s1 = unshadowedSpecular(splitSum, 0, materials[0], n, wo).y;
    const auto e = float(exact);
    std::printf("n . wo %.2f: exact %.4f, filtered %.4f, split sum %.4f\n", double(cosView),
                double(e), double(f1), double(s1));
    worstFiltered = std::max(worstFiltered, std::abs(f1 - e) / e);
    worstSplit = std::max(worstSplit, std::abs(s1 - e) / e);
  }
  EXPECT_LT(worstFiltered, 0.03F);
  EXPECT_GT(worstSplit, 2.0F * worstFiltered);
}

TEST(EnvironmentLighting, PeakFactorFollowsTheLightCount) {
  EXPECT_DOUBLE_EQ(peakFactorFor(0), 40.0);
  EXPECT_DOUBLE_EQ(peakFactorFor(16), 40.0);
  EXPECT_DOUBLE_EQ(peakFactorFor(64), 20.0);
  EXPECT_DOUBLE_EQ(peakFactorFor(256), 10.0);
  EXPECT_DOUBLE_EQ(peakFactorFor(1024), 5.0);
  EXPECT_DOUBLE_EQ(peakFactorFor(4096), 5.0);
}

}  // namespace
}  // namespace vem::render
