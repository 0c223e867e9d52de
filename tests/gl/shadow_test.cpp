// Shadow maps (paper 004 section 5.2.1): a sphere over a plane lit by one light has a dark disc on
// the plane centred on the sphere centre's projection along the light direction (catches a light
// view in the shader that differs from lightClipFromWorld, a flipped tile, a missing bias or an
// inverted depth compare); the maps are reused while lightsKey is unchanged; with 256 casters the
// slot picks the right tile of the atlas.
#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include "client/gl/light_clip.h"
#include "gl_test_support.h"

namespace vem::gl::test {
namespace {

constexpr int kW = 160;
constexpr int kH = 120;
const glm::vec3 kSphereCentre(0.0F, 1.0F, 0.0F);
constexpr float kSphereRadius = 0.5F;

struct DarkRegion {
  glm::vec2 centroidPx{0.0F};
  int pixels = 0;
  int litPixels = 0;
};

// Plane pixels (not covered by the sphere) darker than half the unshadowed value, and how many
// plane pixels are lit to within 2% of it.
DarkRegion darkRegionOnPlane(const render::LinearImage& image, const scene::OrbitCamera& camera,
                             float unshadowed) {
  DarkRegion out;
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      if (hitSphere(camera, x, y, kW, kH, kSphereCentre, kSphereRadius)) continue;
      const scene::Ray ray = camera.primaryRay(float(x) + 0.5F, float(y) + 0.5F, kW, kH);
      if (ray.dirWorld.y >= 0.0F) continue;
      const glm::vec3 p = ray.originWorld - ray.dirWorld * (ray.originWorld.y / ray.dirWorld.y);
      if (std::abs(p.x) > 2.9F || std::abs(p.z) > 2.9F) continue;
      const float v = image.at(x, y).g;
      if (v < 0.5F * unshadowed) {
        out.centroidPx += glm::vec2(float(x) + 0.5F, float(y) + 0.5F);
        ++out.pixels;
      } else if (std::abs(v - unshadowed) < 0.02F * unshadowed) {
        ++out.litPixels;
      }
    }
  }
  if (out.pixels > 0) out.centroidPx /= float(out.pixels);
  return out;
}

glm::vec2 predictedShadowCentre(glm::vec3 dir, const scene::OrbitCamera& camera) {
  return projectToPixel(camera, kSphereCentre - dir * (kSphereCentre.y / dir.y), kW, kH);
}

render::ShadingLights oneCastingLight(glm::vec3 dir, std::uint64_t key) {
  Light light;
  light.dir = glm::normalize(dir);
  light.rgb = glm::vec3(3.0F);
  return withAllCasting(plainLights({light}), key);
}

void expectShadowAt(GlRenderer& renderer, glm::vec3 dirRaw) {
  const glm::vec3 dir = glm::normalize(dirRaw);
  const scene::OrbitCamera camera = shadowCamera();
  renderer.render(camera, oneCastingLight(dir, std::uint64_t(1000 * dir.x)), nullptr);
  const float unshadowed = 0.8F / 3.14159265F * 3.0F * dir.y;
  const DarkRegion dark = darkRegionOnPlane(renderer.readLinear(), camera, unshadowed);
  const glm::vec2 predicted = predictedShadowCentre(dir, camera);
  EXPECT_GT(dark.pixels, 60);
  EXPECT_GT(dark.litPixels, 2000);  // the rest of the plane is lit (no acne)
  EXPECT_LT(glm::distance(dark.centroidPx, predicted), 3.0F)
      << "centroid " << dark.centroidPx.x << "," << dark.centroidPx.y << " predicted "
      << predicted.x << "," << predicted.y;
}

TEST(Shadows, SphereCastsADarkDiscWhereTheLightDirectionPredicts) {
  auto renderer = makeRenderer(sphereOverPlane(), kW, kH);
  ASSERT_NE(renderer, nullptr);
  expectShadowAt(*renderer, {0.6F, 1.0F, 0.2F});
}

TEST(Shadows, MovingTheLightMovesTheDisc) {
  auto renderer = makeRenderer(sphereOverPlane(), kW, kH);
  ASSERT_NE(renderer, nullptr);
  expectShadowAt(*renderer, {0.6F, 1.0F, 0.2F});
  expectShadowAt(*renderer, {0.2F, 1.0F, -0.7F});
  const scene::OrbitCamera camera = shadowCamera();
  EXPECT_GT(
      glm::distance(predictedShadowCentre(glm::normalize(glm::vec3(0.6F, 1.0F, 0.2F)), camera),
                    predictedShadowCentre(glm::normalize(glm::vec3(0.2F, 1.0F, -0.7F)), camera)),
      15.0F);
}

TEST(Shadows, MapsAreReusedWhileTheLightsKeyIsUnchangedAndRedrawnWhenItChanges) {
  auto renderer = makeRenderer(sphereOverPlane(), 64, 48);
  ASSERT_NE(renderer, nullptr);
  const scene::OrbitCamera camera = shadowCamera();
  GlFrameStats stats = renderer->render(camera, oneCastingLight({0.6F, 1.0F, 0.2F}, 7), nullptr);
  EXPECT_EQ(stats.shadowMapsRendered, 1U);
  EXPECT_EQ(stats.shadowMapsReused, 0U);
  stats = renderer->render(camera, oneCastingLight({0.6F, 1.0F, 0.2F}, 7), nullptr);
  EXPECT_EQ(stats.shadowMapsRendered, 0U);
  EXPECT_EQ(stats.shadowMapsReused, 1U);
  stats = renderer->render(camera, oneCastingLight({0.2F, 1.0F, -0.7F}, 8), nullptr);
  EXPECT_EQ(stats.shadowMapsRendered, 1U);
  EXPECT_EQ(stats.shadowMapsReused, 0U);
  Light light;
  light.rgb = glm::vec3(1.0F);
  stats = renderer->render(camera, plainLights({light}), nullptr);  // no casters: no shadow pass
  EXPECT_EQ(stats.shadowMapsRendered, 0U);
  EXPECT_EQ(stats.shadowMapsReused, 0U);
  stats = renderer->render(camera, oneCastingLight({0.2F, 1.0F, -0.7F}, 8), nullptr);
  EXPECT_EQ(stats.shadowMapsRendered, 1U);
}

TEST(Shadows, WithAFullAtlasOnlyTheCasterInSlot200Occludes) {
  auto renderer = makeRenderer(sphereOverPlane(), kW, kH, 128);
  ASSERT_NE(renderer, nullptr);
  ASSERT_EQ(renderer->shadowMapCapacity(), 256U);
  constexpr std::size_t kSlot = 200;
  std::vector<Light> lights = spreadLights(256, glm::vec3(0.0F));
  for (Light& l : lights) l.dir = glm::normalize(glm::vec3(l.dir.x, l.dir.y + 0.6F, l.dir.z));
  const glm::vec3 dir = glm::normalize(glm::vec3(0.6F, 1.0F, 0.2F));
  lights[kSlot].dir = dir;
  lights[kSlot].rgb = glm::vec3(3.0F);
  const scene::OrbitCamera camera = shadowCamera();
  const GlFrameStats stats =
      renderer->render(camera, withAllCasting(plainLights(lights), 42), nullptr);
  EXPECT_EQ(stats.shadowMapsRendered, 256U);
  const float unshadowed = 0.8F / 3.14159265F * 3.0F * dir.y;
  const DarkRegion dark = darkRegionOnPlane(renderer->readLinear(), camera, unshadowed);
  EXPECT_GT(dark.pixels, 60);
  EXPECT_GT(dark.litPixels, 2000);
  EXPECT_LT(glm::distance(dark.centroidPx, predictedShadowCentre(dir, camera)), 3.0F);
}

TEST(LightClip, BoundsFitTheLightViewAndDepthGrowsAwayFromTheLight) {
  scene::Bounds bounds{{-3.0F, 0.0F, -3.0F}, {3.0F, 1.5F, 3.0F}};
  for (const glm::vec3 raw :
       {glm::vec3(0.6F, 1.0F, 0.2F), glm::vec3(0.0F, 1.0F, 0.0F), glm::vec3(-1.0F, 0.1F, 0.3F)}) {
    const glm::vec3 dir = glm::normalize(raw);
    const glm::mat4 clipFromWorld = lightClipFromWorld(dir, bounds);
    for (int corner = 0; corner < 8; ++corner) {
      const glm::vec3 p((corner & 1) ? bounds.max.x : bounds.min.x,
                        (corner & 2) ? bounds.max.y : bounds.min.y,
                        (corner & 4) ? bounds.max.z : bounds.min.z);
      const glm::vec4 c = clipFromWorld * glm::vec4(p, 1.0F);
      EXPECT_LE(glm::max(glm::abs(c.x), glm::max(glm::abs(c.y), glm::abs(c.z))), 1.0F);
      EXPECT_FLOAT_EQ(c.w, 1.0F);
    }
    const glm::vec4 nearer = clipFromWorld * glm::vec4(bounds.centre() + dir, 1.0F);
    const glm::vec4 farther = clipFromWorld * glm::vec4(bounds.centre() - dir, 1.0F);
    EXPECT_LT(nearer.z, farther.z);
  }
}

}  // namespace
}  // namespace vem::gl::test
