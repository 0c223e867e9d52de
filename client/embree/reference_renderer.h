// renderReference: the ground truth for every accuracy figure of vemview (issue 7): per pixel, the
// radiance the whole environment map sends to the eye after one bounce with ray-traced
// visibility, integrated by Monte Carlo until converged:
//   L_o = integral over the sphere of f(wi, wo) L_env(wi) max(0, n . wi) V(wi) dwi.
//
// - Primary rays as renderWithLights (scene::ViewCamera::primaryRay through pixel centres), so
//   the two images are pixel-aligned; normals turned toward the eye (shading_point.h).
// - L_env(wi) is the value of the map pixel that contains wi (sanitised, core/sampling_tables.h):
//   piecewise constant per pixel, the function core/standard_sampler.h's density is proportional
//   to, so the estimate is unbiased for the map as stored.
// - Each sample takes one direction from the environment (standardSample over the map's
//   SamplingTables, density standardPdfSr) and one from the BRDF (brdf_sampling.h), combined by
//   multiple importance sampling with the balance heuristic, each with its own shadow ray.
// - Mirror-like materials: the specular part is mirrorReflectance(n, wo) L_env,bilinear(R) V(R)
//   (0 when R is blocked: one bounce only); their diffuse part is integrated as above.
// - Pixels whose ray leaves the scene: sampleEnvMapBilinear (core/cube_map.h) in the ray's
//   direction, not covered.
// - Convergence: passes of samplesPerPass samples per covered pixel, each sample drawn from a
//   counter-based generator keyed by (seed, pixel, sample index), so the image depends on the seed
//   and the sample count only (not on threads or passes). After each pass with at least minSamples
//   samples, the relative standard error of each covered pixel's luminance, sqrt(var / n) / mean
//   (0 for a pixel with no variance), is averaged over the covered pixels; rendering stops when the
//   average is below targetRelativeError or maxSamples is reached.
// Units: the map's radiance units; the map is Sphere or Hemisphere layout (core/env_map.h), not
// empty.
#pragma once

#include <cstdint>

#include "client/embree/embree_scene.h"
#include "client/render/linear_image.h"
#include "client/scene/view_camera.h"
#include "core/env_map.h"

namespace vem::embree {

struct ReferenceOptions {
  int samplesPerPass = 16;             // K >= 1
  int minSamples = 64;                 // no convergence test before this many samples
  int maxSamples = 4096;               // per pixel
  double targetRelativeError = 0.005;  // mean relative standard error over covered pixels
  std::uint64_t seed = 0x5eedULL;
  int threadCount = 2;  // <= 0: one per hardware thread
};

struct ReferenceResult {
  render::LinearImage image;
  int samplesPerPixel = 0;     // the same for every covered pixel
  double relativeError = 0.0;  // the achieved mean relative standard error
  bool converged = false;      // relativeError < targetRelativeError
};

[[nodiscard]] ReferenceResult renderReference(const EmbreeScene& scene,
                                              const scene::ViewCamera& camera, int widthPx,
                                              int heightPx, const EnvMap& map,
                                              const ReferenceOptions& options = {});

}  // namespace vem::embree
