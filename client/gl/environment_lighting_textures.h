// EnvironmentLightingTextures: render::EnvironmentLighting (issue 20, shading by ratio) as the
// lighting shader reads it, RGB32F cube maps (EnvironmentCube) read with seamless filtering as
// render::sampleCubeMapSeamless reads them on the CPU: the irradiance cube; with filtered
// importance sampling (the default), the clipped environment with its chain, one for every glossy
// material; with the split sum, each glossy material's prefiltered cube and its
// directional-albedo table as two uniform arrays (scale, bias) of render::kAlbedoTableSize floats.
// Re-uploaded only when the caller's version changes (a new cube map).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "client/gl/environment_cube.h"
#include "client/gl/gl_program.h"
#include "client/render/environment_lighting.h"

namespace vem::gl {

class EnvironmentLightingTextures {
 public:
  // Uploads `lighting` unless the same (pointer, version) was uploaded last; nullptr forgets it.
  void update(const render::EnvironmentLighting* lighting, std::uint64_t version);
  [[nodiscard]] bool present() const { return lighting_ != nullptr; }
  // Sets the ratio uniforms of `program` (in use) for one material: the irradiance cube on
  // `irradianceUnit`, on `specularUnit` the clipped environment (filtered importance sampling) or
  // the material's prefiltered cube and its albedo table (the split sum).
  void bindMaterial(const GlProgram& program, std::size_t materialIndex, GLenum irradianceUnit,
                    GLenum specularUnit) const;

 private:
  const render::EnvironmentLighting* lighting_ = nullptr;
  std::optional<std::uint64_t> version_;
  EnvironmentCube irradiance_;
  EnvironmentCube clipped_;  // filtered importance sampling
  std::vector<std::optional<EnvironmentCube>> specular_;  // per material
};

}  // namespace vem::gl
