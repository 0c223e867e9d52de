// EnvironmentCube: core/cube_map.h's CubeMap as a GL_TEXTURE_CUBE_MAP (RGB32F, every level of its
// box-filtered chain, faces in GL order as they come), for the background and mirror-like
// reflections. Linear filtering within a face (seamless filtering is off, as
// render/cube_map_sampling.h's sampleCubeMap assumes, except in the pass that shades by ratio:
// gl_renderer.h). Re-uploaded only when the caller's version changes.
#pragma once

#include <cstdint>
#include <optional>

#include "client/gl/gl_handle.h"
#include "core/cube_map.h"

namespace vem::gl {

class EnvironmentCube {
 public:
  // Uploads `cube` unless the same (pointer, version) was uploaded last; nullptr forgets it.
  // Returns true when it uploaded.
  bool update(const CubeMap* cube, std::uint64_t version);
  [[nodiscard]] bool present() const { return present_; }
  void bind(GLenum unit) const;  // no texture (reads black) unless present()
  static void unbind(GLenum unit);

 private:
  GlTexture texture_;
  const CubeMap* lastCube_ = nullptr;
  std::optional<std::uint64_t> lastVersion_;
  bool present_ = false;
};

}  // namespace vem::gl
