#include "client/gl/environment_cube.h"

namespace vem::gl {

bool EnvironmentCube::update(const CubeMap* cube, std::uint64_t version) {
  if (cube == nullptr || cube->levels.empty()) {
    present_ = false;
    lastCube_ = nullptr;
    lastVersion_.reset();
    return false;
  }
  present_ = true;
  if (cube == lastCube_ && lastVersion_ == version) return false;
  if (!texture_) texture_ = GlTexture::create();
  glBindTexture(GL_TEXTURE_CUBE_MAP, texture_.id());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  for (std::size_t level = 0; level < cube->levels.size(); ++level) {
    const CubeMapLevel& l = cube->levels[level];
    for (int face = 0; face < 6; ++face) {
      glTexImage2D(GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face), GLint(level), GL_RGB32F,
                   l.facePx, l.facePx, 0, GL_RGB, GL_FLOAT, l.faces[std::size_t(face)].data());
    }
  }
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_BASE_LEVEL, 0);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LEVEL, GLint(cube->levels.size() - 1));
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  lastCube_ = cube;
  lastVersion_ = version;
  return true;
}

void EnvironmentCube::unbind(GLenum unit) {
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
}

void EnvironmentCube::bind(GLenum unit) const {
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_CUBE_MAP, present_ ? texture_.id() : 0);
}

}  // namespace vem::gl
