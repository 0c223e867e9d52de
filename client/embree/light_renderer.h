// renderWithLights: the Embree renderer of vemview's lights, the same estimator as the OpenGL
// renderer (paper 004 sections 4 and 5.2) with ray-traced visibility for every light instead of
// shadow maps.
//
// Per pixel, the primary ray of scene::ViewCamera::primaryRay through the pixel's centre; at its
// hit (normal turned toward the eye, shading_point.h), in the units of render/shading_model.h:
//   L_o = sum over the diffuse lights i (render/shading_lights.h; the region list of n when the
//         lights carry lists, else all of them) of
//           (diffuseBrdf + S) rgb_i max(0, n . dir_i) V_i,
//         S = specularBrdf(dir_i) when the material is glossy and no glossy set is given, else 0;
//       + for glossy materials with ShadingLights::glossy set: the L/H lights of
//         glossyLightsFor(R) (core/glossy_light_sets.h, R = the reflected direction, at most
//         ShadingLights::maxConeLights cone lights), each
//           specularBrdf(dir_k) low.rgb_k weight_k max(0, n . dir_k) V_k;
//       + for mirror-like materials when a cube map is given, instead of the specular lights:
//           mirrorReflectance(n, wo) sampleCubeMap(cube, R) V_R, V_R the occlusion of the
//           reflected ray (0 where the scene blocks it: direct light only, as the Monte Carlo
//           reference; the GL renderer through gl/mirror_occlusion.h). A mirror without a diffuse
//           part traces no light rays.
// With LightRenderOptions::environment set, shading by ratio instead (issue 20; Heitz et al. 2018,
// "Combining analytic direct illumination and stochastic shadows"): the unshadowed light comes
// from the prefiltered environment (render/environment_lighting.h), the lights give only the
// shadowing, per channel:
//   L_o = unshadowedDiffuse(n) ratio_d + unshadowedSpecular(n, wo) ratio_s + peaks
//   ratio_d = sum_i rgb_i max(0, n . dir_i) V_i / sum_i rgb_i max(0, n . dir_i)
//   ratio_s = the same sums weighted by specularBrdf(dir_i) (1 - p_i)
//   peaks   = sum_i specularBrdf(dir_i) rgb_i p_i max(0, n . dir_i) V_i
// with p_i the light's share of the peaks the specular cubes leave out (peakFractionsOf, from the
// cube map given here); every sum runs over the same diffuse lights (no L/H sets). A ratio whose denominator is 0 (no light faces the
// surface) is 1: nothing is known to block the environment. Where few lights carry the specular
// sums (their effective count, (sum y)^2 / sum y^2 of the terms' luminances y, under
// minEffectiveLights: sharp lobes, few lights) ratio_s blends linearly into ratio_d, the wider
// lobe's estimate of the same visibility. Mirror-like materials keep the cube map's reflection
// above, with the diffuse part by ratio.
// Soft shadows (by ratio, LightRenderOptions::softShadows; render/soft_shadows.h): a light whose
// stratum of the sky is not compact casts that stratum's soft shadow: per (pixel, light) a fixed
// draw of one direction from the stratum (radiance x solid angle), weighed by the stratum's power
// times the cosine there (0 below the surface), with one occlusion ray for its V. The pixel's sums
// of those lights (numerators and denominators apart) are averaged over the pixels within
// softShadowFilterPx that see the same material at a depth within about 2 % and a normal within
// about 37 degrees (weights: a Gaussian of sigma = radius / 2 in pixels, exp(-(dt / 0.02 t)^2),
// (n . n')^16). Compact lights keep one ray toward their own direction.
// V is an occlusion ray toward the light (1 with shadows off). Pixels whose ray leaves the scene
// show the cube map in the ray's direction (black without one) and are not covered.
// Rows are shared by up to options.threadCount of TBB's threads (parallel_rows.h); the image does
// not depend on the count.
#pragma once

#include "client/embree/embree_scene.h"
#include "client/render/environment_lighting.h"
#include "client/render/linear_image.h"
#include "client/render/shading_lights.h"
#include "client/scene/view_camera.h"
#include "core/cube_map.h"

namespace vem::embree {

struct LightRenderOptions {
  bool shadows = true;  // false: V = 1 for every light (to compare with unshadowed renders)
  int threadCount = 2;  // <= 0: one per hardware thread
  // What the cube map covers: nothing below the horizon of a Hemisphere one (vemd's stream), so
  // the background is black there (render::sampleBackground).
  MapLayout cubeCoverage = MapLayout::Sphere;
  // Shading by ratio (above) when set; borrowed, built for this scene's materials.
  const render::EnvironmentLighting* environment = nullptr;
  double minEffectiveLights = render::kMinEffectiveLights;
  // Shading by ratio only: soft shadows (above).
  bool softShadows = false;
  int softShadowFilterPx = 4;  // >= 0
};

// widthPx, heightPx >= 1. `cube` may be null (black background, mirrors lit by the lights).
[[nodiscard]] render::LinearImage renderWithLights(
    const EmbreeScene& scene, const scene::ViewCamera& camera, int widthPx, int heightPx,
    const render::ShadingLights& lights, const render::LightingGeometry& geometry,
    const CubeMap* cube, const LightRenderOptions& options = {});

}  // namespace vem::embree
