// The study's ground truth: embree::renderReference (Monte Carlo over the whole map) of the study
// scene under one map, cached in the build folder as linear EXR plus a small text file with the
// samples and the achieved error, so that reruns skip the expensive part. The cache file is keyed
// by the map's name and pixels, the image size, the scene (geometry, materials and camera) and
// the target error; a key mismatch renders again, and so does a cached reference that stopped
// short of the target at a smaller sample cap than the one asked for.
//
// EXR holds no coverage, so the coverage of a cached image is recomputed from the primary rays
// (the same rays as the renderers: scene::ViewCamera::primaryRay through pixel centres).
#pragma once

#include <expected>
#include <filesystem>
#include <string>

#include "bench/render/study_setup.h"
#include "client/embree/embree_scene.h"
#include "client/embree/reference_renderer.h"
#include "client/render/linear_image.h"

namespace vem::bench {

struct StudyReference {
  render::LinearImage image;
  int samplesPerPixel = 0;
  double relativeError = 0.0;  // mean relative standard error over covered pixels
  bool converged = false;
  double renderSeconds = 0.0;  // of the render that made it (also when loaded from the cache)
  bool fromCache = false;
};

[[nodiscard]] std::expected<StudyReference, std::string> cachedReference(
    const embree::EmbreeScene& embreeScene, const StudyScene& scene, const StudyMap& map,
    int widthPx, int heightPx, const embree::ReferenceOptions& options,
    const std::filesystem::path& cacheDir);

// 1 where a primary ray hits the scene.
void setCoverage(const embree::EmbreeScene& embreeScene, const scene::ViewCamera& camera,
                 render::LinearImage& image);

}  // namespace vem::bench
