#include "client/scene/orbit_camera.h"

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace vem::scene {

glm::vec3 OrbitCamera::eyeWorld() const {
  const glm::vec3 offset(std::cos(elevationRad) * std::cos(azimuthRad), std::sin(elevationRad),
                         std::cos(elevationRad) * std::sin(azimuthRad));
  return targetWorld + distance * offset;
}

glm::mat4 OrbitCamera::viewFromWorld() const {
  return glm::lookAt(eyeWorld(), targetWorld, glm::vec3(0.0F, 1.0F, 0.0F));
}

glm::mat4 OrbitCamera::clipFromView(float aspect) const { return view().clipFromView(aspect); }

Ray OrbitCamera::primaryRay(float xPx, float yPx, int widthPx, int heightPx) const {
  return view().primaryRay(xPx, yPx, widthPx, heightPx);
}

ViewCamera OrbitCamera::view() const {
  ViewCamera camera;
  camera.eyeWorld = eyeWorld();
  camera.viewFromWorld = viewFromWorld();
  camera.tanHalfFovY = std::tan(0.5F * verticalFovRad);
  camera.nearPlane = nearPlane;
  camera.farPlane = farPlane;
  return camera;
}

OrbitCamera framingCamera(const Bounds& bounds, float azimuthRad, float elevationRad) {
  OrbitCamera camera;
  camera.targetWorld = bounds.centre();
  camera.azimuthRad = azimuthRad;
  camera.elevationRad = elevationRad;
  const float radius = std::max(bounds.radius(), 1e-3F);
  camera.distance = 1.15F * radius / std::sin(0.5F * camera.verticalFovRad);
  camera.nearPlane = std::max(camera.distance - 1.5F * radius, 0.01F * radius);
  camera.farPlane = camera.distance + 1.5F * radius;
  return camera;
}

OrbitCamera viewingCamera(const Scene& scene, float azimuthRad, float elevationRad) {
  Scene objects;
  for (const Mesh& mesh : scene.meshes) {
    Scene one;
    one.meshes = {mesh};
    const Bounds b = sceneBounds(one);
    if (b.max.y - b.min.y > 1e-6F * b.radius()) {
      objects.meshes.push_back(mesh);
    }
  }
  OrbitCamera camera = framingCamera(sceneBounds(objects.meshes.empty() ? scene : objects),
                                     azimuthRad, elevationRad);
  const float sceneRadius = sceneBounds(scene).radius();
  camera.farPlane = camera.distance + 2.0F * sceneRadius;
  camera.nearPlane = std::max(0.02F * camera.distance, camera.distance - 2.0F * sceneRadius);
  return camera;
}

OrbitCamera orbited(OrbitCamera camera, float deltaAzimuthRad) {
  camera.azimuthRad += deltaAzimuthRad;
  return camera;
}

}  // namespace vem::scene
