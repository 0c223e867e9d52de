// ShadowAtlas: up to 256 shadow maps in one depth texture (paper 004 section 5.2.1): a grid of
// grid x grid square tiles of tilePx texels, slot s at column s % grid, row s / grid (row 0 at the
// bottom, texture coordinates), each an orthographic depth render of the scene from one caster
// (light_clip.h). The atlas side is grid x tilePx, capped to GL_MAX_TEXTURE_SIZE (fewer slots
// then: capacity()). Depth is DEPTH_COMPONENT32F with comparison on, for sampler2DShadow.
#pragma once

#include <expected>
#include <span>
#include <string>

#include <glm/vec3.hpp>

#include "client/gl/gl_handle.h"
#include "client/gl/gl_mesh.h"
#include "client/gl/gl_program.h"
#include "client/scene/scene.h"

namespace vem::gl {

class ShadowAtlas {
 public:
  // tilePx >= 1, maxMaps >= 1; fails when the framebuffer is incomplete.
  [[nodiscard]] static std::expected<ShadowAtlas, std::string> create(int tilePx,
                                                                      std::size_t maxMaps);
  // Renders one tile per direction (slot = position in `dirsToLight`, at most capacity()).
  void render(std::span<const glm::vec3> dirsToLight, const scene::Bounds& bounds,
              const GlProgram& depthProgram, std::span<const GlMesh> meshes) const;
  void bind(GLenum unit) const;
  [[nodiscard]] int tilePx() const { return tilePx_; }
  [[nodiscard]] int grid() const { return grid_; }
  [[nodiscard]] int atlasPx() const { return grid_ * tilePx_; }
  [[nodiscard]] std::size_t capacity() const { return capacity_; }

 private:
  ShadowAtlas() = default;
  GlTexture depth_;
  GlFramebuffer framebuffer_;
  int tilePx_ = 0;
  int grid_ = 0;
  std::size_t capacity_ = 0;
};

}  // namespace vem::gl
