// ViewCamera: the pinhole camera both renderers take their rays and projections from: a pose and
// intrinsics that do not depend on the image size. vemview's orbit camera is one
// (orbit_camera.h); a calibrated scene ("plate") camera is another (issue 21: its intrinsics and
// pose from calib/core/plate_camera.h, its lens distortion applied by remapping the render).
//
// Conventions:
// - World frame of core/env_map.h (right-handed, +Y up); view frame OpenGL's (the eye at the
//   origin looking down -Z, +Y up, +X right).
// - Images: row 0 is the top row; pixel (x, y) has its centre at (x + 0.5, y + 0.5) in pixel units,
//   NDC ((x + 0.5) / W * 2 - 1, 1 - (y + 0.5) / H * 2).
// - Intrinsics: a view-frame direction (x, y, -1) lands at
//     ndcX = x / tanHalfFovX + principalNdc.x,  ndcY = y / tanHalfFovY + principalNdc.y,
//   tanHalfFovX = tanHalfFovY * aspect * fyOverFx, aspect = W / H of the image rendered. An orbit
//   camera has fyOverFx = 1 and principalNdc = 0 (a symmetric frustum, its horizontal field
//   following the image's aspect); a calibrated camera rendered at its own aspect reproduces its
//   focal lengths and principal point (pinholeViewCamera).
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace vem::scene {

struct Ray {
  glm::vec3 originWorld{0.0F};
  glm::vec3 dirWorld{0.0F, 0.0F, -1.0F};  // unit
};

struct ViewCamera {
  glm::vec3 eyeWorld{0.0F, 0.0F, 5.0F};
  glm::mat4 viewFromWorld{1.0F};  // a rigid transform
  float tanHalfFovY = 0.365F;     // > 0
  float fyOverFx = 1.0F;          // > 0: the pixel aspect of the focal lengths
  glm::vec2 principalNdc{0.0F};   // where the optical axis meets the image, in NDC
  float nearPlane = 0.05F;
  float farPlane = 100.0F;

  [[nodiscard]] glm::mat4 clipFromView(float aspect) const;  // OpenGL clip space, depth -1..1
  // The primary ray through image point (xPx, yPx) (pixel units, centres at +0.5) of a W x H image.
  [[nodiscard]] Ray primaryRay(float xPx, float yPx, int widthPx, int heightPx) const;
  // Where a world point lands in a W x H image (pixel units, centres at +0.5); behindEye when it
  // is not in front of the eye (then the pixel is meaningless).
  struct Projection {
    glm::vec2 pixel{0.0F};
    bool behindEye = true;
  };
  [[nodiscard]] Projection project(const glm::vec3& pointWorld, int widthPx, int heightPx) const;
};

// A calibrated pinhole camera (OpenCV's camera matrix: fx, fy, cx, cy in pixels of a W x H image,
// pixel centres at integer coordinates) placed by viewFromWorld (OpenGL's view frame); rendered at
// any size of the same aspect it shows what the camera sees.
[[nodiscard]] ViewCamera pinholeViewCamera(const glm::mat4& viewFromWorld, double fxPx, double fyPx,
                                           double cxPx, double cyPx, int widthPx, int heightPx,
                                           float nearPlane, float farPlane);

}  // namespace vem::scene
