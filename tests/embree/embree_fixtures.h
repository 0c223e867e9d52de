// Scenes, maps, cameras and image helpers for the Embree renderer's tests (tests/embree).
// World frame of scene/scene.h (+Y up); maps in the Sphere layout of core/env_map.h.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "client/embree/embree_scene.h"
#include "client/embree/reference_renderer.h"
#include "client/render/linear_image.h"
#include "client/render/shading_lights.h"
#include "client/scene/orbit_camera.h"
#include "client/scene/scene.h"
#include "core/env_map.h"
#include "core/light.h"

namespace vem::embree::testing {

inline constexpr int kWidthPx = 64;
inline constexpr int kHeightPx = 48;

[[nodiscard]] scene::Material lambertian(float albedo);
[[nodiscard]] scene::Material phong(float diffuse, float specular, float exponent);

// A sphere of material 0 at `centre`; with `withPlane`, a ground plane y = 0 of material 1.
[[nodiscard]] scene::Scene sphereScene(glm::vec3 centre, float radius, bool withPlane,
                                       scene::Material sphere, scene::Material plane);
[[nodiscard]] scene::Scene planeScene(scene::Material plane, float size);
// The scene built for Embree (fails the test on an error).
[[nodiscard]] EmbreeScene built(const scene::Scene& scene);

// A camera at azimuth pi/2 (+Z side) looking at `target`.
[[nodiscard]] scene::OrbitCamera cameraAt(glm::vec3 target, float distance, float elevationRad);

[[nodiscard]] EnvMap hotPixelMap(int width, int height, glm::ivec2 hot, float hotValue,
                                 float background);
// The map pixel holding `dir`.
[[nodiscard]] glm::ivec2 pixelOfDirection(const EnvMap& map, glm::vec3 dir);
// Reference options that take exactly `samplesPerPixel` samples (no convergence test).
[[nodiscard]] ReferenceOptions fixedSamples(int samplesPerPixel);

// ../shared/data/hdri/<name>.exr (fails the test when it cannot be read; an empty map then).
[[nodiscard]] EnvMap sharedHdri(const std::string& name);
// A smooth sky (bright zenith, warm band near +X at 30 degrees elevation, dark ground).
[[nodiscard]] EnvMap smoothSky(int width, int height);

// The first n lights core generates from `map` (Havran sampler, the default pattern).
[[nodiscard]] LightSet lightsFrom(const EnvMap& map, std::size_t n);
[[nodiscard]] render::ShadingLights shadingLightsFor(const LightSet& lights,
                                                     const render::LightingGeometry& geometry,
                                                     bool glossyPass, std::size_t highCount);

// The pixel whose centre is nearest to the projection of `pointWorld`, or none off screen.
[[nodiscard]] std::optional<glm::ivec2> pixelOf(const scene::OrbitCamera& camera,
                                                glm::vec3 pointWorld, int widthPx, int heightPx);
// Green-channel radiance at pixel p averaged over its 3 x 3 neighbourhood.
[[nodiscard]] double neighbourhoodMean(const render::LinearImage& image, glm::ivec2 p);

[[nodiscard]] std::vector<std::size_t> coveredPixels(const render::LinearImage& image);
[[nodiscard]] double luminanceAt(const render::LinearImage& image, std::size_t pixel);
// sqrt(sum (Y(a) - Y(r))^2 / sum Y(r)^2) over `pixels`.
[[nodiscard]] double relativeRmsOver(const render::LinearImage& a, const render::LinearImage& r,
                                     const std::vector<std::size_t>& pixels);

}  // namespace vem::embree::testing
