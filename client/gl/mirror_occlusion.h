// MirrorOcclusion: what a mirror-like mesh's reflected rays hit, so that the OpenGL renderer, as
// Embree's and the Monte Carlo reference (direct light only), shows black where the scene blocks
// the reflection instead of the sky (a mirror sphere's reflection of the plane under it: 7.4 %
// off the reference under sky.exr without it).
//
// For each mesh with a mirror-like material: a cube map of kMirrorDistancePx a face centred on the
// mesh's bounding box, holding in each direction the distance to the nearest surface of the other
// meshes (R32F; kNoSurface where there is none). Drawn once when the renderer is created: the
// meshes never move, so the cube never changes, whatever the lights and the camera.
// The lighting shader marches the reflected ray p + t R in kMirrorMarchSteps steps growing
// geometrically from 1 % of the mirror's radius to the scene's diameter, and calls it blocked at
// the first point farther from the centre than the cube's surface in its direction
// (shaders/lighting.frag.glsl, reflectionBlocked). The mirror does not occlude itself (exact for a
// convex mirror); occluders thinner than a step between two samples can be missed.
#pragma once

#include <cstddef>
#include <expected>
#include <span>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "client/gl/gl_handle.h"
#include "client/gl/gl_mesh.h"
#include "client/gl/gl_program.h"
#include "client/scene/scene.h"

namespace vem::gl {

inline constexpr int kMirrorDistancePx = 256;
inline constexpr float kNoSurface = 1e30F;

class MirrorOcclusion {
 public:
  // Draws one cube per mirror-like mesh of `scene` (`meshes` are its meshes, uploaded, in order).
  [[nodiscard]] static std::expected<MirrorOcclusion, std::string> create(
      const scene::Scene& scene, std::span<const GlMesh> meshes);

  // Binds mesh `meshIndex`'s cube to `unit` and sets uMirrorOccluded, uMirrorCentre and
  // uMirrorRadius, uSceneDiameter on `program` (in use); uMirrorOccluded 0 for a mesh without one.
  void bindMesh(const GlProgram& program, std::size_t meshIndex, GLenum unit) const;

 private:
  struct Cube {
    std::size_t meshIndex = 0;
    glm::vec3 centre{0.0F};
    float radius = 0.0F;
    GlTexture texture;
  };
  std::vector<Cube> cubes_;
  float sceneDiameter_ = 0.0F;
};

}  // namespace vem::gl
