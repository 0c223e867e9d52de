// OrbitCamera: vemview's camera, orbiting a target point. It is a ViewCamera (view_camera.h), the
// pinhole camera both renderers take their rays and projections from, so the OpenGL and Embree
// images are pixel-aligned.
//
// Conventions:
// - World frame of core/env_map.h (right-handed, +Y up). The eye sits at
//     target + distance (cos(elev) cos(azim), sin(elev), cos(elev) sin(azim))
//   and looks at the target with +Y up (elevation in (-pi/2, pi/2), radians).
// - View frame: OpenGL's (camera at the origin looking down -Z, +Y up, +X right).
// - Images: row 0 is the top row, column 0 the left; pixel (x, y) has its centre at
//   NDC ((x + 0.5) / W * 2 - 1, 1 - (y + 0.5) / H * 2). verticalFovRad is the full vertical angle.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "client/scene/scene.h"
#include "client/scene/view_camera.h"

namespace vem::scene {

struct OrbitCamera {
  glm::vec3 targetWorld{0.0F};
  float distance = 5.0F;
  float azimuthRad = 0.0F;
  float elevationRad = 0.3F;
  float verticalFovRad = 0.7F;
  float nearPlane = 0.05F;
  float farPlane = 100.0F;

  [[nodiscard]] glm::vec3 eyeWorld() const;
  [[nodiscard]] glm::mat4 viewFromWorld() const;
  [[nodiscard]] glm::mat4 clipFromView(float aspect) const;  // OpenGL clip space, depth -1..1
  // The primary ray through image point (xPx, yPx) (pixel units, centres at +0.5) of a W x H image.
  [[nodiscard]] Ray primaryRay(float xPx, float yPx, int widthPx, int heightPx) const;
  // The same camera as the renderers take it (a symmetric frustum, square pixels). Implicit: an
  // orbit camera is a view camera, wherever one is asked for.
  [[nodiscard]] ViewCamera view() const;
  operator ViewCamera() const { return view(); }  // NOLINT(google-explicit-constructor)
};

// A camera that frames `bounds` from azimuth/elevation with a small margin; near and far planes
// follow the bounds.
[[nodiscard]] OrbitCamera framingCamera(const Bounds& bounds, float azimuthRad = 0.6F,
                                        float elevationRad = 0.35F);
// vemview's starting camera: frames the scene's objects, not its floor (meshes flat in y, ground
// planes, are left out of the framed bounds unless there is nothing else); near and far planes
// hold the whole scene. Azimuth 35 degrees, elevation 20 degrees by default.
[[nodiscard]] OrbitCamera viewingCamera(const Scene& scene, float azimuthRad = 0.61F,
                                        float elevationRad = 0.35F);
// The camera turned by `deltaAzimuthRad` about the target (vemview's orbit).
[[nodiscard]] OrbitCamera orbited(OrbitCamera camera, float deltaAzimuthRad);

}  // namespace vem::scene
