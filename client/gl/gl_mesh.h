// GlMesh: one scene::Mesh uploaded once to the GPU: a vertex array with interleaved positions
// and normals (attributes 0 aPosition, 1 aNormal, world frame) and 32-bit indices.
#pragma once

#include <cstdint>

#include "client/gl/gl_handle.h"
#include "client/scene/scene.h"

namespace vem::gl {

class GlMesh {
 public:
  explicit GlMesh(const scene::Mesh& mesh);
  void draw() const;
  [[nodiscard]] std::uint32_t material() const { return material_; }

 private:
  GlVertexArray vertexArray_;
  GlBuffer vertices_;
  GlBuffer indices_;
  GLsizei indexCount_ = 0;
  std::uint32_t material_ = 0;
};

}  // namespace vem::gl
