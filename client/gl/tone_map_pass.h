// ToneMapPass: the separate full-screen pass of paper 004 section 5.1 that tone-maps the float
// lighting buffer into an 8-bit display image, mirroring render::toneMap and render::srgbEncode
// (shaders/tone_map.frag.glsl), into its own RGBA8 framebuffer (stored values are sRGB-encoded;
// no GL sRGB conversion), optionally blitted 1:1 into the default framebuffer (a window).
//
// Images: widthPx x heightPx; readSrgb8 returns RGB bytes with row 0 at the top.
#pragma once

#include <cstdint>
#include <expected>
#include <string>
#include <vector>

#include "client/gl/gl_handle.h"
#include "client/gl/gl_program.h"
#include "client/render/tone_mapping.h"

namespace vem::gl {

class ToneMapPass {
 public:
  [[nodiscard]] static std::expected<ToneMapPass, std::string> create(int widthPx, int heightPx);
  // Draws from `linearTexture` (RGBA32F, widthPx x heightPx) into the display framebuffer, then,
  // when toWindow, blits it to framebuffer 0 (the window's back buffer).
  void run(GLuint linearTexture, const render::ToneParams& params, bool toWindow) const;
  // The display image (fromWindow: framebuffer 0's back buffer instead of the pass's own).
  [[nodiscard]] std::vector<std::uint8_t> readSrgb8(bool fromWindow) const;

 private:
  ToneMapPass(GlProgram program, int widthPx, int heightPx)
      : program_(std::move(program)), widthPx_(widthPx), heightPx_(heightPx) {}
  GlProgram program_;
  GlVertexArray emptyVertexArray_;
  GlTexture colour_;
  GlFramebuffer framebuffer_;
  int widthPx_ = 0;
  int heightPx_ = 0;
};

// RGBA8 (or RGB) rows read bottom-first from GL -> RGB bytes, row 0 at the top.
[[nodiscard]] std::vector<std::uint8_t> flipRgba8ToRgbTopFirst(const std::vector<std::uint8_t>& rgba,
                                                               int widthPx, int heightPx);

}  // namespace vem::gl
