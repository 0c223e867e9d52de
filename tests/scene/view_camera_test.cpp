// The view camera: an orbit camera renders as before, and a calibrated pinhole camera lands world
// points where OpenCV's camera matrix puts them, in the rays, the projection and the clip matrix
// alike.
#include "client/scene/view_camera.h"

#include <cmath>

#include <gtest/gtest.h>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "client/scene/orbit_camera.h"

namespace vem::scene {
namespace {

// OpenCV's camera frame (+Y down, +Z forward) to OpenGL's view frame.
glm::mat4 viewFromWorldOfOpenCv(const glm::mat3& cvFromWorld, const glm::vec3& eyeWorld) {
  const glm::mat3 glFromCv(glm::vec3(1, 0, 0), glm::vec3(0, -1, 0), glm::vec3(0, 0, -1));
  const glm::mat3 rotation = glFromCv * cvFromWorld;
  glm::mat4 view(rotation);
  view[3] = glm::vec4(-(rotation * eyeWorld), 1.0F);
  return view;
}

struct Pinhole {
  double fxPx = 820.0, fyPx = 790.0, cxPx = 350.0, cyPx = 215.0;
  int widthPx = 640, heightPx = 480;
};

// OpenCV's projection (no distortion): u = fx x / z + cx, pixel centres at integers.
glm::dvec2 openCvPixel(const Pinhole& k, const glm::vec3& pointCv) {
  return {k.fxPx * double(pointCv.x) / double(pointCv.z) + k.cxPx,
          k.fyPx * double(pointCv.y) / double(pointCv.z) + k.cyPx};
}

TEST(ViewCamera, OffCentrePinholeLandsPointsWhereOpenCvsCameraMatrixDoes) {
  const Pinhole k;
  const glm::mat3 cvFromWorld =
      glm::mat3(glm::rotate(glm::mat4(1.0F), 0.4F, glm::normalize(glm::vec3(0.3F, 1.0F, 0.2F))));
  const glm::vec3 eyeWorld(0.5F, 1.6F, 2.0F);
  const ViewCamera camera =
      pinholeViewCamera(viewFromWorldOfOpenCv(cvFromWorld, eyeWorld), k.fxPx, k.fyPx, k.cxPx,
                        k.cyPx, k.widthPx, k.heightPx, 0.05F, 50.0F);
  const glm::mat4 clipFromWorld =
      camera.clipFromView(float(k.widthPx) / float(k.heightPx)) * camera.viewFromWorld;
  const glm::mat3 worldFromCv = glm::transpose(cvFromWorld);
  for (const glm::vec3 pointCv : {glm::vec3(0.1F, -0.2F, 2.0F), glm::vec3(-0.7F, 0.4F, 3.5F),
                                  glm::vec3(0.0F, 0.0F, 1.0F), glm::vec3(0.9F, 0.6F, 4.0F)}) {
    const glm::vec3 pointWorld = eyeWorld + worldFromCv * pointCv;
    const glm::dvec2 expected = openCvPixel(k, pointCv) + glm::dvec2(0.5);  // our centres at +0.5
    const ViewCamera::Projection projected = camera.project(pointWorld, k.widthPx, k.heightPx);
    ASSERT_FALSE(projected.behindEye);
    EXPECT_NEAR(projected.pixel.x, expected.x, 1e-3);
    EXPECT_NEAR(projected.pixel.y, expected.y, 1e-3);
    // The clip matrix (OpenGL) agrees.
    const glm::vec4 clip = clipFromWorld * glm::vec4(pointWorld, 1.0F);
    EXPECT_NEAR((double(clip.x / clip.w) + 1.0) * 0.5 * k.widthPx, expected.x, 2e-3);
    EXPECT_NEAR((1.0 - double(clip.y / clip.w)) * 0.5 * k.heightPx, expected.y, 2e-3);
    // The primary ray through that pixel passes through the point.
    const Ray ray = camera.primaryRay(float(expected.x), float(expected.y), k.widthPx, k.heightPx);
    EXPECT_NEAR(glm::length(ray.originWorld - eyeWorld), 0.0F, 1e-5F);
    EXPECT_GT(glm::dot(ray.dirWorld, glm::normalize(pointWorld - eyeWorld)), 1.0F - 1e-6F);
  }
  EXPECT_TRUE(
      camera.project(eyeWorld - worldFromCv * glm::vec3(0, 0, 1), k.widthPx, k.heightPx).behindEye);
}

TEST(ViewCamera, PinholeRenderedAtHalfSizeKeepsTheSameView) {
  const Pinhole k;
  const ViewCamera camera = pinholeViewCamera(glm::mat4(1.0F), k.fxPx, k.fyPx, k.cxPx, k.cyPx,
                                              k.widthPx, k.heightPx, 0.05F, 50.0F);
  const glm::vec3 pointWorld(0.3F, -0.1F, -2.0F);
  const ViewCamera::Projection full = camera.project(pointWorld, k.widthPx, k.heightPx);
  const ViewCamera::Projection half = camera.project(pointWorld, k.widthPx / 2, k.heightPx / 2);
  EXPECT_NEAR(half.pixel.x * 2.0F, full.pixel.x, 1e-3);
  EXPECT_NEAR(half.pixel.y * 2.0F, full.pixel.y, 1e-3);
}

TEST(ViewCamera, OrbitCameraKeepsItsSymmetricFrustumAndRays) {
  OrbitCamera orbit;
  orbit.azimuthRad = 0.8F;
  orbit.elevationRad = 0.4F;
  orbit.verticalFovRad = 0.9F;
  const ViewCamera camera = orbit;
  const glm::mat4 expected = glm::perspective(0.9F, 1.5F, orbit.nearPlane, orbit.farPlane);
  const glm::mat4 clip = camera.clipFromView(1.5F);
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      EXPECT_NEAR(clip[c][r], expected[c][r], 1e-5F) << c << "," << r;
    }
  }
  // The centre pixel's ray looks at the target.
  const Ray ray = camera.primaryRay(80.0F, 60.0F, 160, 120);
  EXPECT_GT(glm::dot(ray.dirWorld, glm::normalize(orbit.targetWorld - orbit.eyeWorld())),
            1.0F - 1e-6F);
}

}  // namespace
}  // namespace vem::scene
