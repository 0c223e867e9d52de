#include "client/render/environment_lighting.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <glm/glm.hpp>

#include "client/render/cube_map_sampling.h"
#include "client/render/texel_samples.h"
#include "client/render/shading_model.h"
#include "client/render/tangent_frame.h"
#include "core/color.h"
#include "core/cube_map_lookup.h"
#include "core/sampling_pattern.h"

namespace vem::render {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;
constexpr int kIrradianceSourceMaxPx = 32;
constexpr int kWholeChain = 32;  // levels asked of cubeMapFromLevel0: more than any face has
// The prefiltered cubes have at least this many texels a side whatever their source: bilinear
// reads clamp at face edges (cube_map_sampling.h), which leaves a step of half a texel's
// variation at each edge, invisible at 16 px for a lobe that a coarser source resolves.
constexpr int kMinPrefilteredFacePx = 16;
constexpr int kAlbedoStrata = 64;  // per dimension: 4096 samples per table entry
// Prefilter weights below this fraction of the lobe's peak are skipped (Phong and Blinn only,
// whose weights need a pow).
constexpr float kNegligibleWeight = 1e-4F;

// A one-level cube of facePx texels a side whose texel in direction d is value(d).
template <typename Value>
CubeMap cubeOf(int facePx, const Value& value) {
  CubeMap cube;
  CubeMapLevel& level = cube.levels.emplace_back();
  level.facePx = facePx;
  for (auto& face : level.faces) face.assign(std::size_t(3 * facePx * facePx), 0.0F);
  const int texelCount = 6 * facePx * facePx;
  tbb::parallel_for(tbb::blocked_range<int>(0, texelCount), [&](const tbb::blocked_range<int>& r) {
    for (int t = r.begin(); t != r.end(); ++t) {
      const int face = t / (facePx * facePx);
      const int row = (t / facePx) % facePx;
      const int column = t % facePx;
      const glm::vec3 v = value(cubeTexelDirection(face, facePx, column + 0.5, row + 0.5));
      const std::size_t i = 3 * (std::size_t(row) * std::size_t(facePx) + std::size_t(column));
      std::vector<float>& out = level.faces[std::size_t(face)];
      out[i] = v.x;
      out[i + 1] = v.y;
      out[i + 2] = v.z;
    }
  });
  return cube;
}

// The lobe's angular width in l at a tenth of its peak, radians (for the prefilter resolution).
float lobeWidthRad(const scene::Material& m) {
  switch (m.lobe) {
    case scene::Lobe::Ggx: {
      const float a = m.roughness * m.roughness;
      return 2.0F * std::atan(1.47F * a);  // D falls to a tenth at tan(theta_h) = 1.47 alpha
    }
    case scene::Lobe::Blinn:
      return 2.0F * std::acos(std::pow(0.1F, 1.0F / std::max(m.exponent, 1e-3F)));
    case scene::Lobe::Phong: return std::acos(std::pow(0.1F, 1.0F / std::max(m.exponent, 1e-3F)));
    case scene::Lobe::Lambertian: break;
  }
  return kPi;
}

// A direction at polar cosine cosTheta and azimuth phi around z.
glm::vec3 around(glm::vec3 z, float cosTheta, float phi) {
  const auto [t, b] = tangentFrameAround(z);
  const float sinTheta = std::sqrt(std::max(0.0F, 1.0F - cosTheta * cosTheta));
  return glm::normalize(sinTheta * std::cos(phi) * t + sinTheta * std::sin(phi) * b + cosTheta * z);
}

// One stratified importance sample of the lobe at (u1, u2): the light direction and its density
// over solid angle; density 0 for a sample to skip.
struct LobeSample {
  glm::vec3 wi;
  float pdfSr = 0.0F;
};

// GGX by its distribution of visible normals (Heitz, "Sampling the GGX distribution of visible
// normals", JCGT 2018): h is drawn with density G1(wo) max(0, wo . h) D(h) / (n . wo), so no draw
// is wasted on normals wo cannot see, and the reflected l has density G1(wo) D(h) / (4 n . wo).
// At grazing views the distribution of h itself (D(h) (n . h)) sends most draws below the
// surface: 64 of them were 7 % off the integral at n . wo = 0.15, these 1 %.
LobeSample sampleVisibleGgx(const scene::Material& m, glm::vec3 n, glm::vec3 wo, float u1,
                            float u2) {
  const float a = m.roughness * m.roughness;
  const float a2 = a * a;
  const auto [t, b] = tangentFrameAround(n);
  const float cosO = glm::dot(n, wo);
  if (cosO <= 0.0F) return {n, 0.0F};
  // The view in the frame (t, b, n), stretched to the hemisphere configuration.
  const glm::vec3 v = glm::normalize(glm::vec3(a * glm::dot(wo, t), a * glm::dot(wo, b), cosO));
  const float lengthSquared = v.x * v.x + v.y * v.y;
  const glm::vec3 t1 = lengthSquared > 0.0F
                           ? glm::vec3(-v.y, v.x, 0.0F) / std::sqrt(lengthSquared)
                           : glm::vec3(1.0F, 0.0F, 0.0F);
  const glm::vec3 t2 = glm::cross(v, t1);
  const float r = std::sqrt(u1);
  const float phi = 2.0F * kPi * u2;
  const float p1 = r * std::cos(phi);
  const float s = 0.5F * (1.0F + v.z);
  const float p2 = (1.0F - s) * std::sqrt(std::max(0.0F, 1.0F - p1 * p1)) + s * r * std::sin(phi);
  const glm::vec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0F, 1.0F - p1 * p1 - p2 * p2)) * v;
  const glm::vec3 hLocal = glm::normalize(glm::vec3(a * nh.x, a * nh.y, std::max(0.0F, nh.z)));
  const glm::vec3 h = hLocal.x * t + hLocal.y * b + hLocal.z * n;
  const float woH = glm::dot(wo, h);
  if (woH <= 0.0F) return {h, 0.0F};
  const float density =
      smithG1(cosO, a2) * ggxDistribution(std::max(0.0F, glm::dot(n, h)), a2) / (4.0F * cosO);
  return {2.0F * woH * h - wo, density};
}

LobeSample sampleLobe(const scene::Material& m, glm::vec3 n, glm::vec3 wo, float u1, float u2) {
  const float phi = 2.0F * kPi * u2;
  if (m.lobe == scene::Lobe::Phong) {
    const float e = m.exponent;
    const float cosTheta = std::pow(u1, 1.0F / (e + 1.0F));
    const glm::vec3 r = reflectedDirection(n, wo);
    return {around(r, cosTheta, phi), (e + 1.0F) / (2.0F * kPi) * std::pow(cosTheta, e)};
  }
  if (m.lobe == scene::Lobe::Ggx) return sampleVisibleGgx(m, n, wo, u1, u2);
  // Blinn: density (e + 2) / (2 pi) cos^(e + 1) over h
  const float e = m.exponent;
  const float cosH = std::pow(u1, 1.0F / (e + 2.0F));
  const float pdfHalf = (e + 2.0F) / (2.0F * kPi) * std::pow(cosH, e + 1.0F);
  const glm::vec3 h = around(n, cosH, phi);
  const float woH = glm::dot(wo, h);
  if (woH <= 0.0F) return {h, 0.0F};
  return {2.0F * woH * h - wo, pdfHalf / (4.0F * woH)};
}

// The integral of f_s (n . l) over l for n . wo = mu, by stratified importance sampling.
float albedoAt(const scene::Material& m, float mu) {
  const glm::vec3 n(0.0F, 0.0F, 1.0F);
  const glm::vec3 wo(std::sqrt(std::max(0.0F, 1.0F - mu * mu)), 0.0F, mu);
  double sum = 0.0;
  for (int i = 0; i < kAlbedoStrata; ++i) {
    for (int j = 0; j < kAlbedoStrata; ++j) {
      const float u1 = (float(i) + 0.5F) / kAlbedoStrata;
      const float u2 = (float(j) + 0.5F) / kAlbedoStrata;
      const LobeSample s = sampleLobe(m, n, wo, u1, u2);
      const float cosI = glm::dot(n, s.wi);
      if (s.pdfSr <= 0.0F || cosI <= 0.0F) continue;
      sum += double(specularBrdf(m, n, wo, s.wi).x * cosI / s.pdfSr);
    }
  }
  return float(sum / double(kAlbedoStrata * kAlbedoStrata));
}

// The mean luminance of level 0 over the sphere, solid-angle weighted.
double meanLuminance(const CubeMapLevel& level) {
  double sum = 0.0;
  double sr = 0.0;
  for (const TexelSample& t : texelSamplesOf(level)) {
    sum += luminance(t.radianceSr);
    sr += double(t.solidAngleSr);
  }
  return sr > 0.0 ? sum / sr : 0.0;
}

// The cube with every level-0 texel's luminance clipped at peak (hue kept), its chain rebuilt;
// a texel with a channel not finite or negative is black (as texelSamplesOf reads it).
CubeMap clippedAt(const CubeMap& radiance, float peak) {
  CubeMapLevel base = radiance.levels.front();
  for (std::vector<float>& face : base.faces) {
    for (std::size_t i = 0; i + 2 < face.size(); i += 3) {
      if (!(std::isfinite(face[i]) && std::isfinite(face[i + 1]) && std::isfinite(face[i + 2]) &&
            face[i] >= 0.0F && face[i + 1] >= 0.0F && face[i + 2] >= 0.0F)) {
        face[i] = face[i + 1] = face[i + 2] = 0.0F;
        continue;
      }
      const auto y = float(luminance(glm::vec3(face[i], face[i + 1], face[i + 2])));
      if (y > peak) {
        const float scale = peak / y;
        face[i] *= scale;
        face[i + 1] *= scale;
        face[i + 2] *= scale;
      }
    }
  }
  // The whole chain, whatever the input carries: filtered importance sampling reads its coarse
  // levels (cubeMapFromLevel0 stops at the first odd face).
  return cubeMapFromLevel0(std::move(base), kWholeChain);
}

// Filtered importance sampling of `clipped` for the material's lobe at (n, wo) (the header).
glm::vec3 filteredSpecular(const CubeMap& clipped, const scene::Material& m, glm::vec3 n,
                           glm::vec3 wo) {
  if (clipped.levels.empty()) return glm::vec3(0.0F);
  const auto facePx = float(clipped.levels.front().facePx);
  const float texelSr = 4.0F * kPi / (6.0F * facePx * facePx);
  const auto top = float(clipped.levels.size() - 1);
  glm::vec3 sum(0.0F);
  for (int k = 0; k < kFilteredSamples; ++k) {
    const float u1 = (float(k) + 0.5F) / float(kFilteredSamples);
    const auto u2 = float(radicalInverse(2, std::uint64_t(k)));
    const LobeSample s = sampleLobe(m, n, wo, u1, u2);
    const float cosI = glm::dot(n, s.wi);
    if (s.pdfSr <= 0.0F || cosI <= 0.0F) continue;
    const float lod = std::clamp(
        0.5F * std::log2(1.0F / (float(kFilteredSamples) * s.pdfSr * texelSr)), 0.0F, top);
    const int below = int(lod);
    const int above = std::min(below + 1, int(top));
    const glm::vec3 radiance = glm::mix(sampleCubeMapSeamless(clipped, s.wi, below),
                                        sampleCubeMapSeamless(clipped, s.wi, above),
                                        lod - float(below));
    sum += specularBrdf(m, n, wo, s.wi) * radiance * (cosI / s.pdfSr);
  }
  return sum / float(kFilteredSamples);
}

}  // namespace

DirectionalAlbedo directionalAlbedoOf(const scene::Material& material) {
  DirectionalAlbedo table;
  if (material.lobe == scene::Lobe::Lambertian) return table;
  scene::Material zero = material;
  zero.specularAlbedo = glm::vec3(0.0F);
  scene::Material one = material;
  one.specularAlbedo = glm::vec3(1.0F);
  for (int i = 0; i < kAlbedoTableSize; ++i) {
    const float mu = (float(i) + 0.5F) / kAlbedoTableSize;
    const float atZero = albedoAt(zero, mu);  // only GGX's Fresnel term is non-zero at F0 = 0
    table.bias[std::size_t(i)] = atZero;
    table.scale[std::size_t(i)] = albedoAt(one, mu) - atZero;
  }
  return table;
}

glm::vec3 directionalAlbedo(const DirectionalAlbedo& table, const scene::Material& material,
                            float cosNormalEye) {
  const float x =
      std::clamp(cosNormalEye * kAlbedoTableSize - 0.5F, 0.0F, float(kAlbedoTableSize - 1));
  const int i0 = int(x);
  const int i1 = std::min(i0 + 1, kAlbedoTableSize - 1);
  const float w = x - float(i0);
  const float scale = glm::mix(table.scale[std::size_t(i0)], table.scale[std::size_t(i1)], w);
  const float bias = glm::mix(table.bias[std::size_t(i0)], table.bias[std::size_t(i1)], w);
  return material.specularAlbedo * scale + glm::vec3(bias);
}

int prefilterFacePxOf(const scene::Material& material) {
  const float texelRad = lobeWidthRad(material) / 3.0F;  // a texel spans (pi / 2) / F
  int facePx = 4;
  while (facePx < kMaxPrefilterFacePx && kPi / 2.0F / float(facePx) > texelRad) facePx *= 2;
  return facePx;
}

CubeMap irradianceCubeOf(const CubeMap& radiance, int facePx) {
  const std::vector<TexelSample> source = texelSamplesOf(cubeLevelAtMost(radiance, kIrradianceSourceMaxPx));
  return cubeOf(facePx, [&](glm::vec3 n) {
    glm::vec3 sum(0.0F);
    for (const TexelSample& s : source) {
      sum += s.radianceSr * std::max(0.0F, glm::dot(n, s.dir));
    }
    return sum;
  });
}

CubeMap prefilteredCubeOf(const CubeMap& radiance, const scene::Material& material) {
  const int facePx = prefilterFacePxOf(material);
  const std::vector<TexelSample> source = texelSamplesOf(cubeLevelAtMost(radiance, facePx));
  const bool ggx = material.lobe == scene::Lobe::Ggx;
  const float a = material.roughness * material.roughness;
  const float a2 = a * a;
  const float e = std::max(material.exponent, 0.0F);
  // Phong's weight is (R . l)^(e + 1); Blinn's cos(h)^e (R . l) with R . l = 2 cos(h)^2 - 1.
  const float minCos =
      material.lobe == scene::Lobe::Phong ? std::pow(kNegligibleWeight, 1.0F / (e + 1.0F))
      : material.lobe == scene::Lobe::Blinn
          ? 2.0F * std::pow(std::pow(kNegligibleWeight, 1.0F / std::max(e, 1e-3F)), 2.0F) - 1.0F
          : 0.0F;
  return cubeOf(std::max(facePx, kMinPrefilteredFacePx), [&](glm::vec3 r) {
    glm::vec3 sum(0.0F);
    float weights = 0.0F;
    for (const TexelSample& s : source) {
      const float cosRL = glm::dot(r, s.dir);
      if (cosRL <= minCos || cosRL <= 0.0F) continue;
      float w = 0.0F;
      if (material.lobe == scene::Lobe::Phong) {
        w = std::pow(cosRL, e + 1.0F);
      } else {
        const float cosH = std::sqrt(0.5F * (1.0F + cosRL));  // R . h for h between R and l
        w = (ggx ? ggxDistribution(cosH, a2) : std::pow(cosH, e)) * cosRL;
      }
      sum += w * s.radianceSr;
      weights += w * s.solidAngleSr;
    }
    return weights > 0.0F ? sum / weights : glm::vec3(0.0F);
  });
}

double peakFactorFor(std::size_t lightCount) {
  const double n = double(std::max<std::size_t>(lightCount, 1));
  return std::clamp(20.0 * std::sqrt(64.0 / n), 5.0, 40.0);
}

EnvironmentLighting makeEnvironmentLighting(const CubeMap& radiance,
                                            std::span<const scene::Material> materials,
                                            const EnvironmentLightingOptions& options) {
  EnvironmentLighting out;
  out.specular.resize(materials.size());
  if (radiance.levels.empty()) return out;
  if (options.diffuse) out.irradiance = irradianceCubeOf(radiance, options.irradianceFacePx);
  if (!options.specular) return out;
  out.peakLuminance = float(options.peakFactor * meanLuminance(radiance.levels.front()));
  out.specularModel = options.specularModel;
  std::optional<CubeMap> clipped;
  for (std::size_t i = 0; i < materials.size(); ++i) {
    const scene::Material& m = materials[i];
    if (!m.glossy() || m.mirrorLike()) continue;
    if (!clipped) clipped = clippedAt(radiance, out.peakLuminance);
    out.specular[i] = options.specularModel == SpecularModel::SplitSum
                          ? SpecularEnvironment{prefilteredCubeOf(*clipped, m),
                                                directionalAlbedoOf(m), specularLookupBlend(m)}
                          : SpecularEnvironment{};
  }
  if (clipped && options.specularModel == SpecularModel::FilteredSampling) {
    out.clipped = std::move(*clipped);
  }
  return out;
}

std::vector<float> peakFractionsOf(const EnvironmentLighting& lighting, const CubeMap& radiance,
                                   std::span<const Light> lights) {
  std::vector<float> out(lights.size(), 0.0F);
  const bool anySpecular =
      std::ranges::any_of(lighting.specular, [](const auto& s) { return s.has_value(); });
  if (!anySpecular || radiance.levels.empty() || !(lighting.peakLuminance > 0.0F)) return out;
  const CubeMapLevel& level = radiance.levels.front();
  for (std::size_t i = 0; i < lights.size(); ++i) {
    const CubeTexel t = cubeTexelOf(glm::dvec3(lights[i].dir), level.facePx);
    const std::vector<float>& face = level.faces[std::size_t(t.face)];
    const std::size_t k =
        3 * (std::size_t(t.row) * std::size_t(level.facePx) + std::size_t(t.column));
    const auto y = float(luminance(glm::vec3(face[k], face[k + 1], face[k + 2])));
    out[i] = y > lighting.peakLuminance ? 1.0F - lighting.peakLuminance / y : 0.0F;
  }
  return out;
}

glm::vec3 unshadowedDiffuse(const EnvironmentLighting& lighting, const scene::Material& material,
                            glm::vec3 n) {
  if (lighting.irradiance.levels.empty()) return glm::vec3(0.0F);
  return diffuseBrdf(material) * sampleCubeMapSeamless(lighting.irradiance, n);
}

glm::vec3 unshadowedSpecular(const EnvironmentLighting& lighting, std::size_t materialIndex,
                             const scene::Material& material, glm::vec3 n, glm::vec3 wo) {
  if (materialIndex >= lighting.specular.size() || !lighting.specular[materialIndex]) {
    return glm::vec3(0.0F);
  }
  if (lighting.specularModel == SpecularModel::FilteredSampling) {
    return filteredSpecular(lighting.clipped, material, n, wo);
  }
  const SpecularEnvironment& env = *lighting.specular[materialIndex];
  const glm::vec3 d = specularLookupDirection(n, wo, env.lookupBlend);
  return sampleCubeMapSeamless(env.prefiltered, d) *
         directionalAlbedo(env.albedo, material, glm::dot(n, wo));
}

float specularLookupBlend(const scene::Material& material) {
  float alpha = 0.0F;
  switch (material.lobe) {
    case scene::Lobe::Ggx: alpha = material.roughness * material.roughness; break;
    case scene::Lobe::Blinn:
      alpha = std::sqrt(2.0F / (std::max(material.exponent, 0.0F) + 2.0F));
      break;
    case scene::Lobe::Phong:
    case scene::Lobe::Lambertian: return 1.0F;
  }
  const float r = std::clamp(alpha, 0.0F, 1.0F);
  const float s = 1.0F - r;
  return s * (std::sqrt(s) + r);
}

glm::vec3 specularLookupDirection(glm::vec3 n, glm::vec3 wo, float blend) {
  const glm::vec3 r = reflectedDirection(n, wo);
  const glm::vec3 d = n + (r - n) * blend;
  const float length = glm::length(d);
  return length > 0.0F ? d / length : r;
}

}  // namespace vem::render
