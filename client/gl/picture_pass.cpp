#include "client/gl/picture_pass.h"

#include <algorithm>

#include "util/contract.h"

namespace vem::gl {

std::expected<PicturePass, std::string> PicturePass::create() {
  auto program = GlProgram::build("picture", {"fullscreen.vert.glsl"}, {"picture.frag.glsl"});
  if (!program) return std::unexpected(program.error());
  PicturePass pass(std::move(*program));
  pass.emptyVertexArray_ = GlVertexArray::create();
  pass.texture_ = GlTexture::create();
  glBindTexture(GL_TEXTURE_2D, pass.texture_.id());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return pass;
}

void PicturePass::draw(GLuint framebuffer, glm::ivec2 targetSizePx,
                       std::span<const std::uint8_t> rgb8, int widthPx, int heightPx) {
  VEM_EXPECTS(widthPx > 0 && heightPx > 0 &&
              rgb8.size() == std::size_t(widthPx) * std::size_t(heightPx) * 3);
  glBindTexture(GL_TEXTURE_2D, texture_.id());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, widthPx, heightPx, 0, GL_RGB, GL_UNSIGNED_BYTE,
               rgb8.data());
  // As large as fits, the picture's aspect kept, centred.
  const double scale =
      std::min(double(targetSizePx.x) / double(widthPx), double(targetSizePx.y) / double(heightPx));
  const glm::ivec2 sizePx{std::max(1, int(double(widthPx) * scale)),
                          std::max(1, int(double(heightPx) * scale))};
  const glm::ivec2 originPx = (targetSizePx - sizePx) / 2;
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, targetSizePx.x, targetSizePx.y);
  glClearColor(0.0F, 0.0F, 0.0F, 1.0F);
  glClear(GL_COLOR_BUFFER_BIT);
  glViewport(originPx.x, originPx.y, sizePx.x, sizePx.y);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  program_.use();
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, texture_.id());
  program_.set("uPicture", 0);
  program_.set("uOriginPx", originPx);
  program_.set("uSizePx", sizePx);
  glBindVertexArray(emptyVertexArray_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glViewport(0, 0, targetSizePx.x, targetSizePx.y);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace vem::gl
