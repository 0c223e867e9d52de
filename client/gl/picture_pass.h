// PicturePass: a picture computed on the CPU (8-bit RGB, row 0 at the top, display-encoded
// already: a composite of vemview --plate) drawn into a framebuffer (0: the window's back buffer)
// as large as fits with its aspect kept, centred, black around it. Each draw uploads the picture
// (a new one a frame). Needs a current GlContext for its life.
#pragma once

#include <cstdint>
#include <expected>
#include <span>
#include <string>

#include <glm/vec2.hpp>

#include "client/gl/gl_handle.h"
#include "client/gl/gl_program.h"

namespace vem::gl {

class PicturePass {
 public:
  [[nodiscard]] static std::expected<PicturePass, std::string> create();
  // rgb8: widthPx * heightPx * 3 bytes.
  void draw(GLuint framebuffer, glm::ivec2 targetSizePx, std::span<const std::uint8_t> rgb8,
            int widthPx, int heightPx);

 private:
  explicit PicturePass(GlProgram program) : program_(std::move(program)) {}

  GlProgram program_;
  GlVertexArray emptyVertexArray_;
  GlTexture texture_;
};

}  // namespace vem::gl
