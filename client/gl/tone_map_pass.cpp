#include "client/gl/tone_map_pass.h"

namespace vem::gl {

std::expected<ToneMapPass, std::string> ToneMapPass::create(int widthPx, int heightPx) {
  auto program =
      GlProgram::build("tone map", {"fullscreen.vert.glsl"}, {"tone_map.frag.glsl"});
  if (!program) return std::unexpected(program.error());
  ToneMapPass pass(std::move(*program), widthPx, heightPx);
  pass.emptyVertexArray_ = GlVertexArray::create();
  pass.colour_ = GlTexture::create();
  glBindTexture(GL_TEXTURE_2D, pass.colour_.id());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, widthPx, heightPx, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  pass.framebuffer_ = GlFramebuffer::create();
  glBindFramebuffer(GL_FRAMEBUFFER, pass.framebuffer_.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, pass.colour_.id(),
                         0);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    return std::unexpected("the tone-mapping framebuffer (RGBA8) is incomplete (status " +
                           std::to_string(status) + ")");
  }
  return pass;
}

void ToneMapPass::run(GLuint linearTexture, const render::ToneParams& params,
                      bool toWindow) const {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  glViewport(0, 0, widthPx_, heightPx_);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  program_.use();
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, linearTexture);
  program_.set("uLinear", 0);
  program_.set("uScale", float(params.key / params.worldLuminance));
  program_.set("uWhite2", float(params.whiteLuminance * params.whiteLuminance));
  glBindVertexArray(emptyVertexArray_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  if (toWindow) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_.id());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, widthPx_, heightPx_, 0, 0, widthPx_, heightPx_, GL_COLOR_BUFFER_BIT,
                      GL_NEAREST);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

std::vector<std::uint8_t> ToneMapPass::readSrgb8(bool fromWindow) const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fromWindow ? 0 : framebuffer_.id());
  glReadBuffer(fromWindow ? GL_BACK : GL_COLOR_ATTACHMENT0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  std::vector<std::uint8_t> rgba(std::size_t(widthPx_) * std::size_t(heightPx_) * 4);
  glReadPixels(0, 0, widthPx_, heightPx_, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  return flipRgba8ToRgbTopFirst(rgba, widthPx_, heightPx_);
}

std::vector<std::uint8_t> flipRgba8ToRgbTopFirst(const std::vector<std::uint8_t>& rgba,
                                                 int widthPx, int heightPx) {
  const auto w = std::size_t(widthPx);
  const auto h = std::size_t(heightPx);
  std::vector<std::uint8_t> out(w * h * 3);
  for (std::size_t y = 0; y < h; ++y) {
    const std::size_t glRow = h - 1 - y;
    for (std::size_t x = 0; x < w; ++x) {
      for (std::size_t c = 0; c < 3; ++c) out[(y * w + x) * 3 + c] = rgba[(glRow * w + x) * 4 + c];
    }
  }
  return out;
}

}  // namespace vem::gl
