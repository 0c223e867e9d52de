// Shared fixtures of the vem_gl tests: one headless EGL context for the whole binary, small
// scenes, hand-built ShadingLights and the analytic sphere hit used as CPU reference.
#pragma once

#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "client/gl/gl_context.h"
#include "client/gl/gl_renderer.h"
#include "client/render/shading_lights.h"
#include "client/scene/orbit_camera.h"
#include "client/scene/scene.h"

namespace vem::gl::test {

// The binary's context (created on first use; nullptr when EGL fails, with the reason printed).
GlContext* headlessContext();
// The region geometry every test's ShadingLights is built on (makeLightingGeometry(), once).
const render::LightingGeometry& testGeometry();

scene::Material lambertian(glm::vec3 albedo);
scene::Material blinn(glm::vec3 diffuse, glm::vec3 specular, float exponent);
// One smooth sphere (finely tessellated, so interpolated normals are close to analytic ones).
scene::Scene sphereScene(const scene::Material& material, glm::vec3 centre, float radius);
// A sphere of radius 0.5 at (0, 1, 0) over a 6 x 6 ground plane at y = 0, both Lambertian.
scene::Scene sphereOverPlane();

// Diffuse lights only: no regions, no shadows, no glossy sets.
render::ShadingLights plainLights(const std::vector<Light>& lights);
// The same with the diffuse region lists of testGeometry().
render::ShadingLights withRegions(render::ShadingLights lights);
// Every diffuse light casts, in light order (slot i = light i), key `key`.
render::ShadingLights withAllCasting(render::ShadingLights lights, std::uint64_t key);
// Glossy L = the diffuse lights, |H| = highCount, k = maxConeLights.
render::ShadingLights withGlossy(render::ShadingLights lights, std::size_t highCount,
                                 std::size_t maxConeLights);

// `count` lights spread over the upper hemisphere (a Fibonacci spiral), equal rgb summing to
// `total`.
std::vector<Light> spreadLights(int count, glm::vec3 total);

std::unique_ptr<GlRenderer> makeRenderer(const scene::Scene& scene, int widthPx, int heightPx,
                                         int shadowMapPx = 256,
                                         MapLayout environmentCoverage = MapLayout::Sphere);

struct SphereHit {
  glm::vec3 pointWorld;
  glm::vec3 normal;   // unit, outward
  glm::vec3 toEye;    // wo
  float cosView = 0;  // n . wo
};
std::optional<SphereHit> hitSphere(const scene::OrbitCamera& camera, int x, int y, int widthPx,
                                   int heightPx, glm::vec3 centre, float radius);

// A camera looking down at the origin from 7 units, steeply (elevation 1.1 rad), from -Z: the
// view of the shadow tests (a shadow on the ground plane around the origin).
scene::OrbitCamera shadowCamera();

// Image position (pixels, row 0 at the top) of a world point.
glm::vec2 projectToPixel(const scene::OrbitCamera& camera, glm::vec3 pointWorld, int widthPx,
                         int heightPx);

}  // namespace vem::gl::test
