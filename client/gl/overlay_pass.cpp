#include "client/gl/overlay_pass.h"

namespace vem::gl {

std::expected<OverlayPass, std::string> OverlayPass::create() {
  auto program = GlProgram::build("overlay", {"fullscreen.vert.glsl"}, {"overlay.frag.glsl"});
  if (!program) return std::unexpected(program.error());
  OverlayPass pass(std::move(*program));
  pass.emptyVertexArray_ = GlVertexArray::create();
  pass.texture_ = GlTexture::create();
  glBindTexture(GL_TEXTURE_2D, pass.texture_.id());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  return pass;
}

void OverlayPass::update(glm::ivec2 targetSizePx, std::string_view text) {
  if (text == text_ && targetSizePx == targetSizePx_) return;
  text_ = text;
  targetSizePx_ = targetSizePx;
  const glm::ivec2 roomPx = targetSizePx - 2 * kMarginPx;
  const OverlayImage image =
      rasteriseOverlay(text, roomPx.x, roomPx.y, overlayFontFor(targetSizePx.x));
  imageSizePx_ = {image.widthPx, image.heightPx};
  ++uploads_;
  if (image.empty()) return;
  glBindTexture(GL_TEXTURE_2D, texture_.id());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.widthPx, image.heightPx, 0, GL_RGBA,
               GL_UNSIGNED_BYTE, image.rgba.data());
}

void OverlayPass::draw(GLuint framebuffer, glm::ivec2 targetSizePx, std::string_view text) {
  update(targetSizePx, text);
  if (imageSizePx_.x == 0 || imageSizePx_.y == 0) return;
  const glm::ivec2 originPx{kMarginPx, targetSizePx.y - kMarginPx - imageSizePx_.y};
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(originPx.x, originPx.y, imageSizePx_.x, imageSizePx_.y);
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  program_.use();
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, texture_.id());
  program_.set("uOverlay", 0);
  program_.set("uOriginPx", originPx);
  glBindVertexArray(emptyVertexArray_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDisable(GL_BLEND);
  glViewport(0, 0, targetSizePx.x, targetSizePx.y);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace vem::gl
