#include "client/gl/shadow_atlas.h"

#include <algorithm>
#include <cmath>

#include "client/gl/light_clip.h"

namespace vem::gl {

std::expected<ShadowAtlas, std::string> ShadowAtlas::create(int tilePx, std::size_t maxMaps) {
  GLint maxTexturePx = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxTexturePx);
  ShadowAtlas atlas;
  atlas.tilePx_ = std::min(tilePx, int(maxTexturePx));
  const int wantedGrid = int(std::ceil(std::sqrt(double(std::max<std::size_t>(maxMaps, 1)))));
  atlas.grid_ = std::max(1, std::min(wantedGrid, int(maxTexturePx) / atlas.tilePx_));
  atlas.capacity_ = std::min(maxMaps, std::size_t(atlas.grid_) * std::size_t(atlas.grid_));
  const int side = atlas.atlasPx();

  atlas.depth_ = GlTexture::create();
  glBindTexture(GL_TEXTURE_2D, atlas.depth_.id());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, side, side, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
               nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);

  atlas.framebuffer_ = GlFramebuffer::create();
  glBindFramebuffer(GL_FRAMEBUFFER, atlas.framebuffer_.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, atlas.depth_.id(), 0);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    return std::unexpected("the shadow atlas framebuffer (" + std::to_string(side) + "x" +
                           std::to_string(side) + " DEPTH_COMPONENT32F) is incomplete (status " +
                           std::to_string(status) + ")");
  }
  return atlas;
}

void ShadowAtlas::render(std::span<const glm::vec3> dirsToLight, const scene::Bounds& bounds,
                         const GlProgram& depthProgram, std::span<const GlMesh> meshes) const {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  const std::size_t count = std::min(dirsToLight.size(), capacity_);
  const int rowsUsed = int((count + std::size_t(grid_) - 1) / std::size_t(grid_));
  glEnable(GL_SCISSOR_TEST);  // clear only the rows of tiles in use
  glScissor(0, 0, atlasPx(), rowsUsed * tilePx_);
  glDepthMask(GL_TRUE);
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);  // two-sided casters
  // The view spans the casters' bounding sphere (scene::shadowCasterBounds); a ground beyond its
  // near or far plane is clamped onto it rather than clipped, so it still hides what lies behind
  // it from a light below it.
  glEnable(GL_DEPTH_CLAMP);
  depthProgram.use();
  for (std::size_t slot = 0; slot < count; ++slot) {
    const int column = int(slot) % grid_;
    const int row = int(slot) / grid_;
    glViewport(column * tilePx_, row * tilePx_, tilePx_, tilePx_);
    depthProgram.set("uLightClipFromWorld", lightClipFromWorld(dirsToLight[slot], bounds));
    for (const GlMesh& mesh : meshes) mesh.draw();
  }
  glDisable(GL_DEPTH_CLAMP);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void ShadowAtlas::bind(GLenum unit) const {
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D, depth_.id());
}

}  // namespace vem::gl
