#include "client/gl/mirror_occlusion.h"

#include <algorithm>
#include <array>

#include <glm/gtc/matrix_transform.hpp>

namespace vem::gl {
namespace {

scene::Bounds boundsOf(const scene::Mesh& mesh) {
  scene::Bounds b{mesh.positions.front(), mesh.positions.front()};
  for (const glm::vec3& p : mesh.positions) {
    b.min = glm::min(b.min, p);
    b.max = glm::max(b.max, p);
  }
  return b;
}

// GL's cube faces (+X, -X, +Y, -Y, +Z, -Z): the view direction and the up vector that put texel
// (s, t) where a samplerCube lookup of that direction reads it.
struct FaceView {
  glm::vec3 forward;
  glm::vec3 up;
};
constexpr std::array<FaceView, 6> kFaces{{{{1, 0, 0}, {0, -1, 0}},
                                          {{-1, 0, 0}, {0, -1, 0}},
                                          {{0, 1, 0}, {0, 0, 1}},
                                          {{0, -1, 0}, {0, 0, -1}},
                                          {{0, 0, 1}, {0, -1, 0}},
                                          {{0, 0, -1}, {0, -1, 0}}}};

}  // namespace

std::expected<MirrorOcclusion, std::string> MirrorOcclusion::create(
    const scene::Scene& scene, std::span<const GlMesh> meshes) {
  MirrorOcclusion out;
  const scene::Bounds all = scene::sceneBounds(scene);
  out.sceneDiameter_ = 2.0F * all.radius();
  std::vector<std::size_t> mirrors;
  for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
    const scene::Mesh& mesh = scene.meshes[i];
    if (mesh.triangleCount() > 0 && scene.materials.at(mesh.material).mirrorLike()) {
      mirrors.push_back(i);
    }
  }
  if (mirrors.empty()) return out;
  auto program = GlProgram::build("mirror distance", {"mirror_distance.vert.glsl"},
                                  {"mirror_distance.frag.glsl"});
  if (!program) return std::unexpected(program.error());
  GlRenderbuffer depth = GlRenderbuffer::create();
  glBindRenderbuffer(GL_RENDERBUFFER, depth.id());
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, kMirrorDistancePx,
                        kMirrorDistancePx);
  GlFramebuffer framebuffer = GlFramebuffer::create();
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth.id());
  glViewport(0, 0, kMirrorDistancePx, kMirrorDistancePx);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);
  program->use();
  for (const std::size_t meshIndex : mirrors) {
    const scene::Bounds b = boundsOf(scene.meshes[meshIndex]);
    Cube cube{meshIndex, b.centre(), std::max(b.radius(), 1e-6F), GlTexture::create()};
    glBindTexture(GL_TEXTURE_CUBE_MAP, cube.texture.id());
    for (int face = 0; face < 6; ++face) {
      glTexImage2D(GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face), 0, GL_R32F, kMirrorDistancePx,
                   kMirrorDistancePx, 0, GL_RED, GL_FLOAT, nullptr);
    }
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    const float nearPlane = 1e-3F * cube.radius;
    const float farPlane = 4.0F * out.sceneDiameter_ + cube.radius;
    const glm::mat4 clipFromView = glm::perspective(glm::radians(90.0F), 1.0F, nearPlane, farPlane);
    program->set("uCentre", cube.centre);
    for (int face = 0; face < 6; ++face) {
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                             GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face), cube.texture.id(), 0);
      const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
      if (status != GL_FRAMEBUFFER_COMPLETE) {
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        return std::unexpected("the mirror distance framebuffer (R32F, " +
                               std::to_string(kMirrorDistancePx) + " px) is incomplete (status " +
                               std::to_string(status) + ")");
      }
      glClearColor(kNoSurface, 0.0F, 0.0F, 1.0F);
      glClearDepth(1.0);
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
      const glm::mat4 viewFromWorld = glm::lookAt(
          cube.centre, cube.centre + kFaces[std::size_t(face)].forward, kFaces[std::size_t(face)].up);
      program->set("uClipFromWorld", clipFromView * viewFromWorld);
      for (std::size_t i = 0; i < meshes.size(); ++i) {
        if (i != meshIndex) meshes[i].draw();
      }
    }
    out.cubes_.push_back(std::move(cube));
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glClearColor(0.0F, 0.0F, 0.0F, 0.0F);
  return out;
}

void MirrorOcclusion::bindMesh(const GlProgram& program, std::size_t meshIndex,
                               GLenum unit) const {
  const auto cube = std::ranges::find(cubes_, meshIndex, &Cube::meshIndex);
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_CUBE_MAP, cube == cubes_.end() ? 0 : cube->texture.id());
  program.set("uMirrorOccluded", cube == cubes_.end() ? 0 : 1);
  if (cube == cubes_.end()) return;
  program.set("uMirrorCentre", cube->centre);
  program.set("uMirrorRadius", cube->radius);
  program.set("uSceneDiameter", sceneDiameter_);
}

}  // namespace vem::gl
