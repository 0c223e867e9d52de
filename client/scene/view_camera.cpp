#include "client/scene/view_camera.h"

#include <glm/glm.hpp>

#include "util/contract.h"

namespace vem::scene {

glm::mat4 ViewCamera::clipFromView(float aspect) const {
  VEM_EXPECTS(aspect > 0.0F && tanHalfFovY > 0.0F && fyOverFx > 0.0F);
  VEM_EXPECTS(nearPlane > 0.0F && farPlane > nearPlane);
  const float tanHalfFovX = tanHalfFovY * aspect * fyOverFx;
  glm::mat4 clip(0.0F);
  clip[0][0] = 1.0F / tanHalfFovX;
  clip[1][1] = 1.0F / tanHalfFovY;
  // ndc = clip.xy / w with w = -z: the principal point's shift enters through z.
  clip[2][0] = -principalNdc.x;
  clip[2][1] = -principalNdc.y;
  clip[2][2] = -(farPlane + nearPlane) / (farPlane - nearPlane);
  clip[2][3] = -1.0F;
  clip[3][2] = -2.0F * farPlane * nearPlane / (farPlane - nearPlane);
  return clip;
}

Ray ViewCamera::primaryRay(float xPx, float yPx, int widthPx, int heightPx) const {
  const float aspect = float(widthPx) / float(heightPx);
  const float tanHalfFovX = tanHalfFovY * aspect * fyOverFx;
  const float ndcX = xPx / float(widthPx) * 2.0F - 1.0F;
  const float ndcY = 1.0F - yPx / float(heightPx) * 2.0F;
  const glm::vec3 dirView((ndcX - principalNdc.x) * tanHalfFovX,
                          (ndcY - principalNdc.y) * tanHalfFovY, -1.0F);
  const glm::mat4 worldFromView = glm::inverse(viewFromWorld);
  const glm::vec3 dirWorld = glm::normalize(glm::vec3(worldFromView * glm::vec4(dirView, 0.0F)));
  return Ray{eyeWorld, dirWorld};
}

ViewCamera::Projection ViewCamera::project(const glm::vec3& pointWorld, int widthPx,
                                           int heightPx) const {
  const glm::vec3 pointView = glm::vec3(viewFromWorld * glm::vec4(pointWorld, 1.0F));
  if (!(pointView.z < 0.0F)) {
    return {};
  }
  const float aspect = float(widthPx) / float(heightPx);
  const float tanHalfFovX = tanHalfFovY * aspect * fyOverFx;
  const float ndcX = pointView.x / -pointView.z / tanHalfFovX + principalNdc.x;
  const float ndcY = pointView.y / -pointView.z / tanHalfFovY + principalNdc.y;
  return Projection{
      glm::vec2((ndcX + 1.0F) * 0.5F * float(widthPx), (1.0F - ndcY) * 0.5F * float(heightPx)),
      false};
}

ViewCamera pinholeViewCamera(const glm::mat4& viewFromWorld, double fxPx, double fyPx, double cxPx,
                             double cyPx, int widthPx, int heightPx, float nearPlane,
                             float farPlane) {
  VEM_EXPECTS(fxPx > 0.0 && fyPx > 0.0 && widthPx > 0 && heightPx > 0);
  ViewCamera camera;
  camera.viewFromWorld = viewFromWorld;
  camera.eyeWorld = glm::vec3(glm::inverse(viewFromWorld) * glm::vec4(0.0F, 0.0F, 0.0F, 1.0F));
  camera.tanHalfFovY = float(0.5 * double(heightPx) / fyPx);
  camera.fyOverFx = float(fyPx / fxPx);
  // OpenCV's pixel centres sit at integers, ours at +0.5.
  camera.principalNdc = glm::vec2(float((cxPx + 0.5) / double(widthPx) * 2.0 - 1.0),
                                  float(1.0 - (cyPx + 0.5) / double(heightPx) * 2.0));
  camera.nearPlane = nearPlane;
  camera.farPlane = farPlane;
  return camera;
}

}  // namespace vem::scene
