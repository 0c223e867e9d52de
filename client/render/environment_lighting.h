// EnvironmentLighting: the unshadowed light a surface receives from the whole streamed environment,
// prefiltered once per cube map for the BRDFs a scene uses (issue 20), so that shading needs no
// lights for it, has no noise and shows no spot per light:
//
// - diffuse: the irradiance E(n) = integral of L(l) max(0, n . l) dl, tabulated on a small cube
//   (irradianceFacePx a side) and read bilinearly; the diffuse radiance is diffuseBrdf E(n).
// - specular (per glossy, non-mirror material), by default filtered importance sampling
//   (SpecularModel::FilteredSampling; Colbert and Krivanek, "GPU-based importance sampling", GPU
//   Gems 3, 2007, chapter 20): kFilteredSamples directions l_k drawn from the material's own lobe
//   for this n and wo (the Hammersley set: u1 = (k + 0.5) / K, u2 the base-2 radical inverse of
//   k), each reading the environment's box-filtered chain at the level whose texels span the
//   sample's share of the sphere, lod = 0.5 log2(1 / (K pdf(l_k) Omega_0)) (Omega_0 = 4 pi /
//   (6 F^2), a level-0 texel), trilinearly; the radiance is the mean of f_s L (n . l) / pdf. Its
//   lobe is the true, view-dependent one, so it has none of the split sum's bias at grazing
//   angles: against 1 %-noise references at N = 1024 GGX 0.3 under city.exr went from 2.9 % (the
//   split sum's plateau) to 1.4 %, and no material is worse (docs/shading-by-ratio.md). It needs
//   no per-material prefilter, only the clipped environment and its chain (clipped below).
// - specular, SpecularModel::SplitSum (the comparison): the integral of f_s(l, wo) L(l) (n . l) dl
//   is taken as P(R) rho(n . wo):
//     P(R)      the environment averaged over the lobe with n = wo = R (R: wo mirrored about n),
//               weights w(l) = D(h) max(0, R . l) for GGX and Blinn (h the half vector of R and l,
//               D the material's distribution), max(0, R . l)^(e + 1) for Phong, summed over the
//               input level whose texels resolve the lobe (a third of its width at a tenth of its
//               peak, at most kMaxPrefilterFacePx a side: prefilterFacePxOf), onto a cube of that
//               size or 16 px, whichever is larger;
//     rho(mu)   the material's directional albedo, the integral of f_s (n . l) over l for
//               n . wo = mu: tabulated at kAlbedoTableSize cosines by stratified importance
//               sampling of the same BRDF functions the renderers call (shading_model.h), so it
//               carries their exact Smith G and Schlick F; rho is linear in F0, stored as
//               rho = F0 scale + bias.
// Both average the environment with its bright peaks clipped: with a small bright source the
// split sum is far off (on studio.exr, GGX alpha 0.3: 0.14 to 2.3 times the exact integral,
// docs/render-accuracy.md), and either would be noisy or blurred there. The environment is
// clipped at peakLuminance (texels brighter than peakFactor times the map's mean luminance are
// scaled down to it, hue kept), and the clipped light is left to the lights: each
// light carries the share peakFractionsOf gives it, 1 - T / Y of the texel under it, whose
// specular sum the renderer takes exactly, light by light (in expectation the lights' shares sum
// to the clipped energy, since they sample the map in proportion to its luminance).
//
// The input is a cube map as core/cube_map.h makes it and vemd streams it (every level a box
// filter of the one above); texels below a Hemisphere map's horizon are black there, and add
// nothing. Integrals run over the texels of one input level, each weighted by its exact solid
// angle.
// Pure: no state, thread-safe; the two builders run on TBB's worker threads.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "client/scene/scene.h"
#include "core/cube_map.h"
#include "core/light.h"

namespace vem::render {

inline constexpr int kAlbedoTableSize = 32;
inline constexpr int kMaxPrefilterFacePx = 32;
// Below this effective count of lights carrying a point's specular sums, the renderers blend the
// specular ratio into the diffuse one (client/embree/light_renderer.h).
inline constexpr double kMinEffectiveLights = 4.0;
// Filtered importance sampling's directions per pixel: 32 left GGX 0.3 under city.exr at 2.1 %
// (N = 1024), 64 at 1.4 %, 128 at 1.0 %, for about 0.1 ms per 1000 glossy pixels more each
// doubling (Embree, 2 threads).
inline constexpr int kFilteredSamples = 64;

enum class SpecularModel { FilteredSampling, SplitSum };

// rho(mu) = specularAlbedo * scale(mu) + bias(mu), mu = n . wo in (0, 1], linear between entries
// at mu_i = (i + 0.5) / kAlbedoTableSize (clamped at the ends).
struct DirectionalAlbedo {
  std::array<float, kAlbedoTableSize> scale{};
  std::array<float, kAlbedoTableSize> bias{};
};

// A glossy material's specular environment. FilteredSampling reads EnvironmentLighting::clipped
// and leaves these empty; SplitSum reads them.
struct SpecularEnvironment {
  CubeMap prefiltered;  // P(R), one level
  DirectionalAlbedo albedo;
  float lookupBlend = 1.0F;  // specularLookupBlend of the material
};

struct EnvironmentLighting {
  CubeMap irradiance;          // E(n), one level; empty when not built (no diffuse material)
  float peakLuminance = 0.0F;  // T: the specular environment is clipped at T
  SpecularModel specularModel = SpecularModel::FilteredSampling;
  // FilteredSampling: the environment clipped at T with its box-filtered chain (empty without a
  // glossy material, or with SplitSum).
  CubeMap clipped;
  // One entry per scene material: set for glossy materials that are not mirror-like.
  std::vector<std::optional<SpecularEnvironment>> specular;
};

struct EnvironmentLightingOptions {
  int irradianceFacePx = 16;
  bool diffuse = true;       // build the irradiance cube
  bool specular = true;      // build the glossy materials' specular environment
  double peakFactor = 20.0;  // T = peakFactor x the mean luminance of the environment
  SpecularModel specularModel = SpecularModel::FilteredSampling;
};

// The peak factor for N lights: 20 sqrt(64 / N), within [5, 40] (40 at N = 16, 10 at 256, 5 from
// 1024). The more lights, the more of the bright peaks they carry exactly and the less the split
// sum has to average; the fewer, the noisier those peaks. Against 1 %-noise references, by ratio,
// against a fixed 20: GGX under studio.exr at N = 1024 from 2.7-3.4 % to 1.5-1.7 % (the split sum's
// plateau), and the default scene at N = 16 from 3.7-4.4 % to 3.3-3.4 %
// (docs/shading-by-ratio.md).
[[nodiscard]] double peakFactorFor(std::size_t lightCount);

// The directional albedo table of a glossy material (0 everywhere for a Lambertian one).
[[nodiscard]] DirectionalAlbedo directionalAlbedoOf(const scene::Material& material);
[[nodiscard]] glm::vec3 directionalAlbedo(const DirectionalAlbedo& table,
                                          const scene::Material& material, float cosNormalEye);

// The face size of the cube that resolves the material's lobe (a power of two in
// [4, kMaxPrefilterFacePx]).
[[nodiscard]] int prefilterFacePxOf(const scene::Material& material);

// E(n) on a facePx cube, from the input level whose face is at most 32 px.
[[nodiscard]] CubeMap irradianceCubeOf(const CubeMap& radiance, int facePx);
// P(R) for one glossy material.
[[nodiscard]] CubeMap prefilteredCubeOf(const CubeMap& radiance, const scene::Material& material);

[[nodiscard]] EnvironmentLighting makeEnvironmentLighting(
    const CubeMap& radiance, std::span<const scene::Material> materials,
    const EnvironmentLightingOptions& options = {});

// Per light, the share of its rgb that the clipped specular cubes leave out: 1 - T / Y of the
// radiance cube's level-0 texel under it, 0 where Y <= T (all 0 without a specular environment).
[[nodiscard]] std::vector<float> peakFractionsOf(const EnvironmentLighting& lighting,
                                                 const CubeMap& radiance,
                                                 std::span<const Light> lights);

// Where P is read: the lobe's dominant direction, normalize(mix(n, R, b)) with b this blend. The
// split sum's P(R) was prefiltered with n = wo = R; a rough GGX or Blinn lobe seen away from the
// normal leans toward n (its off-specular peak), so with broad light P(R) takes light from too
// near the horizon. b = s (sqrt(s) + r) with s = 1 - r and r the linear roughness (Lagarde and
// de Rousiers, "Moving Frostbite to PBR", 2014, section 4.9.3; for Blinn r from the exponent by
// alpha^2 = 2 / (e + 2)); 1 for Phong, whose lobe is centred on R.
[[nodiscard]] float specularLookupBlend(const scene::Material& material);
[[nodiscard]] glm::vec3 specularLookupDirection(glm::vec3 n, glm::vec3 wo, float blend);

// The unshadowed radiances toward wo (n unit, turned toward wo): diffuseBrdf E(n), and the
// specular one by the lighting's model: filtered importance sampling of `clipped`, or
// P(D) rho(n . wo) with D = specularLookupDirection (0 without a specular environment for the
// material).
[[nodiscard]] glm::vec3 unshadowedDiffuse(const EnvironmentLighting& lighting,
                                          const scene::Material& material, glm::vec3 n);
[[nodiscard]] glm::vec3 unshadowedSpecular(const EnvironmentLighting& lighting,
                                           std::size_t materialIndex,
                                           const scene::Material& material, glm::vec3 n,
                                           glm::vec3 wo);

}  // namespace vem::render
