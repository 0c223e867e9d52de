// The mixed-reality study (issue 21, "Measured against a ground truth"): synthetic objects
// composited into a simulated plate by differential rendering, against the truth.
//
// The simulated real world (client/scene/mixed_reality_world.h) under each map: the plate is
// embree::renderReference of the real surfaces alone from the plate camera, the truth the same
// with the synthetic objects added (same seed). The composite takes the plate, the map's first N
// lights and its cube map, renders the local scene (floor plane and proxies) with and without the
// objects by ratio (Embree, and OpenGL with its shadow maps spent on the strata) and composites (render/differential_composite.h). Errors against the
// truth: relative RMS over the whole image and over the shadow region (local pixels that the
// objects darken by more than 5 % in the truth), beside "pasted" (the objects over the plate, no
// differential pass); times per frame, and what a registration error costs (the plate camera
// turned by 0.5 and 1 degree, the probe's yaw off by 2 degrees).
#pragma once

#include <expected>
#include <string>
#include <vector>

#include "bench/render/study_run.h"

namespace vem::bench {

struct CompositeStudyOptions {
  std::vector<std::string> maps = {"sky", "park", "city"};
  std::string hdriDir;
  StudyImageSize size;
  double referenceError = 0.02;
  int referenceMaxSamples = 65536;
  std::vector<std::size_t> counts = {16, 64, 256, 1024};
  std::string cacheDir;
  std::string dumpDir;  // plate | composite | truth | difference PNGs at N = 256, when set
  int frames = 3;       // timed frames per point (median)
  bool gl = true;       // also the OpenGL layers (headless), S = glShadowMaps with soft shadows
  std::size_t glShadowMaps = 256;
  int glShadowMapPx = 256;  // vemview's default; the maps look at the objects alone
};

// The report (markdown), or the first failure in one sentence.
[[nodiscard]] std::expected<std::string, std::string> runCompositeStudy(
    const CompositeStudyOptions& options);

}  // namespace vem::bench
