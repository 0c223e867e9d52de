// The material study of issue 20 (`vem_render_bench --materials`): a sphere on a plane (the
// built-in "spheres" scene, its sphere given one material at a time: diffuse, GGX alpha 0.1, 0.3
// and 0.6, Phong 10 and 100, a mirror), and the default scene as it is (the bunny, a gold GGX
// sphere, a Blinn box, with vemview's starting camera), under real HDRIs, drawn by the Embree and
// the OpenGL renderers with the paper's sums over the lights (glossy L/H) and by ratio (the
// prefiltered environment shadowed by the lights' ratio, light_renderer.h), at N = 16 ... 1024,
// each against the Monte Carlo reference (cached like the main study's).
//
// Equal time: the reference's own error against its samples per pixel is measured (renders at 4,
// 16 and 64 samples with another seed, timed, against the converged reference); Monte Carlo error
// falls as c / sqrt(spp), so the reference reaches error e after (c / e)^2 spp, at its measured
// time per sample. "x faster" is that time over the frame time of vemview's render. Prefiltering
// runs when the cube map changes, not every frame: its time is a column of its own.
#pragma once

#include <string>
#include <vector>

#include "bench/render/study_renderer.h"

namespace vem::bench {

struct MaterialStudyOptions {
  std::vector<std::string> maps;
  std::string hdriDir;
  StudyImageSize size;
  double referenceError = 0.01;
  int referenceMaxSamples = 8192;
  std::string cacheDir;
  std::vector<std::size_t> counts{16, 64, 256, 1024};
  bool gl = true;     // also the OpenGL renderer (headless)
  int glFrames = 3;   // timed OpenGL frames per point (the median is reported)
  std::size_t glShadowMaps = 256;  // OpenGL: min(N, this) shadow maps, shared by group below N
  int cubeFacePx = 0;  // the cube map both renderers read (level 0); 0: render::cubeFacePxFor
  // By ratio: soft shadows (render/soft_shadows.h; OpenGL's from the spare maps,
  // render/shadow_draws.h).
  bool softShadows = false;
  std::vector<std::string> materials;  // names of materialStudyMaterials(); empty: all
  std::string command;                 // for the report
  // When set: per material, map, N and renderer, a PNG of the reference, the lights' and the
  // ratio's render side by side, all at the reference's exposure (to look at where the errors
  // are): <material>-<map>-<N>-embree.png and -gl.png.
  std::string dumpDir;
  // When set: per material, <plotPrefix>-<material>.svg, the error against the frame time (the
  // mean over the maps) of each renderer and shading as N grows, beside the Monte Carlo
  // reference's own curve (its error at each time, the mean over the maps).
  std::string plotPrefix;
};

// The report (markdown), or the error.
[[nodiscard]] std::expected<std::string, std::string> runMaterialStudy(
    const MaterialStudyOptions& options);

}  // namespace vem::bench
