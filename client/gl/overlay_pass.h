// OverlayPass: the window's text overlay (frame rate, lights, shadowed lights, the plan) blended
// over the tone-mapped display after ToneMapPass (tone_map_pass.h). The text is rasterised on the
// CPU (overlay_text.h) and re-uploaded only when it or the target's size changes; drawing is one
// small textured quad with premultiplied-alpha blending in the target's top-left corner.
//
// The overlay never reaches the lighting buffer or the tone-mapping pass's own framebuffer, so
// readLinear() and headless images never contain it. Needs a current GlContext for its life.
#pragma once

#include <expected>
#include <string>
#include <string_view>

#include <glm/vec2.hpp>

#include "client/gl/gl_handle.h"
#include "client/gl/gl_program.h"
#include "client/gl/overlay_text.h"

namespace vem::gl {

class OverlayPass {
 public:
  [[nodiscard]] static std::expected<OverlayPass, std::string> create();
  // Blends `text` over `framebuffer` (0: the window's back buffer), which is targetSizePx large,
  // with its top-left corner marginPx from the target's. Empty text draws nothing.
  void draw(GLuint framebuffer, glm::ivec2 targetSizePx, std::string_view text);
  // Times the picture was rasterised and uploaded (the text or the target size changed).
  [[nodiscard]] int uploads() const { return uploads_; }

  static constexpr int kMarginPx = 4;

 private:
  explicit OverlayPass(GlProgram program) : program_(std::move(program)) {}
  void update(glm::ivec2 targetSizePx, std::string_view text);

  GlProgram program_;
  GlVertexArray emptyVertexArray_;
  GlTexture texture_;
  std::string text_;
  glm::ivec2 targetSizePx_{0, 0};
  glm::ivec2 imageSizePx_{0, 0};
  int uploads_ = 0;
};

}  // namespace vem::gl
