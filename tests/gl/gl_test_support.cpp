#include "gl_test_support.h"

#include <cmath>
#include <cstdio>
#include <numbers>

#include <glm/glm.hpp>

#include "client/scene/primitives.h"

namespace vem::gl::test {

GlContext* headlessContext() {
  static std::unique_ptr<GlContext> context = [] {
    auto made = GlContext::headless(64, 64);
    if (!made) {
      std::fprintf(stderr, "headless context: %s\n", made.error().c_str());
      return std::unique_ptr<GlContext>();
    }
    return std::move(*made);
  }();
  return context.get();
}

const render::LightingGeometry& testGeometry() {
  static const render::LightingGeometry geometry = render::makeLightingGeometry();
  return geometry;
}

scene::Material lambertian(glm::vec3 albedo) {
  scene::Material m;
  m.name = "lambertian";
  m.diffuseAlbedo = albedo;
  return m;
}

scene::Material blinn(glm::vec3 diffuse, glm::vec3 specular, float exponent) {
  scene::Material m;
  m.name = "blinn";
  m.diffuseAlbedo = diffuse;
  m.lobe = scene::Lobe::Blinn;
  m.specularAlbedo = specular;
  m.exponent = exponent;
  return m;
}

scene::Scene sphereScene(const scene::Material& material, glm::vec3 centre, float radius) {
  scene::Scene s;
  s.name = "sphere";
  s.materials = {material};
  s.meshes = {scene::sphereMesh(centre, radius, 96, 192, 0)};
  return s;
}

scene::Scene sphereOverPlane() {
  scene::Scene s;
  s.name = "sphere over plane";
  s.materials = {lambertian(glm::vec3(0.8F))};
  s.meshes = {scene::sphereMesh({0.0F, 1.0F, 0.0F}, 0.5F, 32, 64, 0),
              scene::groundPlane(0.0F, 6.0F, 0.0F, 0.0F, 0)};
  return s;
}

render::ShadingLights plainLights(const std::vector<Light>& lights) {
  render::ShadingLights out;
  out.diffuse.lights = lights;
  out.shadowSlotOfDiffuse.assign(lights.size(), -1);
  return out;
}

render::ShadingLights withRegions(render::ShadingLights lights) {
  lights.diffuseLists = visibleLightLists(testGeometry().diffuseRegions, lights.diffuse);
  return lights;
}

render::ShadingLights withAllCasting(render::ShadingLights lights, std::uint64_t key) {
  lights.shadowDirs.clear();
  for (std::size_t i = 0; i < lights.diffuse.lights.size(); ++i) {
    lights.shadowDirs.push_back(lights.diffuse.lights[i].dir);
    lights.shadowSlotOfDiffuse[i] = std::int32_t(i);
  }
  lights.lightsKey = key;
  return lights;
}

render::ShadingLights withGlossy(render::ShadingLights lights, std::size_t highCount,
                                 std::size_t maxConeLights) {
  lights.glossy = makeGlossyLightSets(lights.diffuse, highCount, testGeometry().glossyRegions);
  lights.shadowSlotOfLow.assign(lights.diffuse.lights.size(), -1);
  lights.maxConeLights = maxConeLights;
  return lights;
}

scene::OrbitCamera shadowCamera() {
  scene::OrbitCamera camera;
  camera.targetWorld = {0.0F, 0.0F, 0.0F};
  camera.distance = 7.0F;
  camera.azimuthRad = 3.14159265F;
  camera.elevationRad = 1.1F;
  camera.verticalFovRad = 0.8F;
  return camera;
}

std::vector<Light> spreadLights(int count, glm::vec3 total) {
  std::vector<Light> out;
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < count; ++i) {
    const double y = 1.0 - (double(i) + 0.5) / double(count);  // upper hemisphere
    const double ring = std::sqrt(1.0 - y * y);
    const double phi = golden * double(i);
    Light light;
    light.id = std::uint32_t(i);
    light.dir = glm::normalize(
        glm::vec3(float(ring * std::cos(phi)), float(y), float(ring * std::sin(phi))));
    light.rgb = total / float(count);
    out.push_back(light);
  }
  return out;
}

std::unique_ptr<GlRenderer> makeRenderer(const scene::Scene& scene, int widthPx, int heightPx,
                                         int shadowMapPx, MapLayout environmentCoverage) {
  if (headlessContext() == nullptr) return nullptr;
  GlRendererOptions options;
  options.widthPx = widthPx;
  options.heightPx = heightPx;
  options.shadowMapPx = shadowMapPx;
  options.geometry = &testGeometry();
  options.environmentCoverage = environmentCoverage;
  auto renderer = GlRenderer::create(scene, options);
  if (!renderer) {
    std::fprintf(stderr, "GlRenderer::create: %s\n", renderer.error().c_str());
    return nullptr;
  }
  return std::move(*renderer);
}

std::optional<SphereHit> hitSphere(const scene::OrbitCamera& camera, int x, int y, int widthPx,
                                   int heightPx, glm::vec3 centre, float radius) {
  const scene::Ray ray = camera.primaryRay(float(x) + 0.5F, float(y) + 0.5F, widthPx, heightPx);
  const glm::dvec3 o = glm::dvec3(ray.originWorld) - glm::dvec3(centre);
  const glm::dvec3 d = glm::normalize(glm::dvec3(ray.dirWorld));
  const double b = glm::dot(o, d);
  const double disc = b * b - (glm::dot(o, o) - double(radius) * double(radius));
  if (disc <= 0.0) return std::nullopt;
  const double t = -b - std::sqrt(disc);
  if (t <= 0.0) return std::nullopt;
  SphereHit hit;
  const glm::dvec3 p = o + t * d;
  hit.pointWorld = glm::vec3(p) + centre;
  hit.normal = glm::vec3(glm::normalize(p));
  hit.toEye = glm::vec3(-d);
  hit.cosView = glm::dot(hit.normal, hit.toEye);
  return hit;
}

glm::vec2 projectToPixel(const scene::OrbitCamera& camera, glm::vec3 pointWorld, int widthPx,
                         int heightPx) {
  const float aspect = float(widthPx) / float(heightPx);
  const glm::vec4 clip =
      camera.clipFromView(aspect) * camera.viewFromWorld() * glm::vec4(pointWorld, 1.0F);
  const glm::vec2 ndc = glm::vec2(clip) / clip.w;
  return {(ndc.x + 1.0F) * 0.5F * float(widthPx), (1.0F - ndc.y) * 0.5F * float(heightPx)};
}

}  // namespace vem::gl::test
