// The cube map's face size a scene calls for. A mirror-like material reflects level 0, so its
// reflection is as sharp as the cube: a mirror sphere under sky.exr was 8.3 % off the Monte Carlo
// reference with 128 px faces and 2.5 % (the reference's own noise) with 512 px; under studio.exr
// 2.5 % and 0.13 % (docs/shading-by-ratio.md). Every other lobe reads blurred levels (its
// filtered importance samples, or the split sum's prefiltered cubes), and 128 px serves it. Both vemview's render plan and the render bench take
// the size from here.
#pragma once

#include "client/scene/scene.h"

namespace vem::render {

inline constexpr int kCubeFacePx = 128;
inline constexpr int kMirrorCubeFacePx = 512;

// kMirrorCubeFacePx when a mesh of the scene has a mirror-like material, else kCubeFacePx.
[[nodiscard]] inline int cubeFacePxFor(const scene::Scene& scene) {
  return scene::anyMirrorLike(scene) ? kMirrorCubeFacePx : kCubeFacePx;
}

}  // namespace vem::render
