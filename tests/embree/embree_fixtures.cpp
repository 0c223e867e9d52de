#include "embree/embree_fixtures.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include "client/scene/primitives.h"
#include "core/color.h"
#include "core/default_pattern.h"
#include "core/light_generator.h"
#include "core/sampling_tables.h"
#include "mapio/map_file.h"

namespace vem::embree::testing {

scene::Material lambertian(float albedo) {
  scene::Material m;
  m.name = "lambertian";
  m.diffuseAlbedo = glm::vec3(albedo);
  return m;
}

scene::Material phong(float diffuse, float specular, float exponent) {
  scene::Material m = lambertian(diffuse);
  m.name = "phong";
  m.lobe = scene::Lobe::Phong;
  m.specularAlbedo = glm::vec3(specular);
  m.exponent = exponent;
  return m;
}

scene::Scene sphereScene(glm::vec3 centre, float radius, bool withPlane, scene::Material sphere,
                         scene::Material plane) {
  scene::Scene s;
  s.name = "test";
  s.materials = {sphere, plane};
  s.meshes.push_back(scene::sphereMesh(centre, radius, 64, 128, 0));
  if (withPlane) {
    s.meshes.push_back(scene::groundPlane(0.0F, 6.0F, 0.0F, 0.0F, 1));
  }
  return s;
}

scene::Scene planeScene(scene::Material plane, float size) {
  scene::Scene s;
  s.name = "plane";
  s.materials = {plane};
  s.meshes.push_back(scene::groundPlane(0.0F, size, 0.0F, 0.0F, 0));
  return s;
}

EmbreeScene built(const scene::Scene& scene) {
  auto result = EmbreeScene::build(scene, "threads=1");
  EXPECT_TRUE(result.has_value()) << (result ? "" : result.error());
  return std::move(result).value();
}

scene::OrbitCamera cameraAt(glm::vec3 target, float distance, float elevationRad) {
  scene::OrbitCamera camera;
  camera.targetWorld = target;
  camera.distance = distance;
  camera.azimuthRad = 0.5F * std::numbers::pi_v<float>;
  camera.elevationRad = elevationRad;
  camera.nearPlane = 0.05F;
  camera.farPlane = 50.0F;
  return camera;
}

EnvMap hotPixelMap(int width, int height, glm::ivec2 hot, float hotValue, float background) {
  EnvMap map = EnvMap::filled(MapLayout::Sphere, width, height, glm::vec3(background));
  map.set(hot.x, hot.y, glm::vec3(hotValue));
  return map;
}

glm::ivec2 pixelOfDirection(const EnvMap& map, glm::vec3 dir) {
  const double theta = std::acos(std::clamp(double(dir.y), -1.0, 1.0));
  const double phi = std::atan2(double(dir.z), double(dir.x));
  const int x = int((phi + std::numbers::pi) / (2 * std::numbers::pi) * map.width);
  const int y = int(theta / std::numbers::pi * map.height);
  return {std::clamp(x, 0, map.width - 1), std::clamp(y, 0, map.height - 1)};
}

ReferenceOptions fixedSamples(int samplesPerPixel) {
  ReferenceOptions options;
  options.minSamples = samplesPerPixel;
  options.maxSamples = samplesPerPixel;
  return options;
}

EnvMap sharedHdri(const std::string& name) {
  auto map = mapio::loadMap(std::string(VEM_SHARED_DATA_DIR) + "/hdri/" + name + ".exr");
  EXPECT_TRUE(map.has_value()) << name << ": " << (map ? std::string() : map.error().message);
  return map ? std::move(*map) : EnvMap::filled(MapLayout::Sphere, 2, 1, glm::vec3(0.0F));
}

EnvMap smoothSky(int width, int height) {
  EnvMap map = EnvMap::filled(MapLayout::Sphere, width, height, glm::vec3(0.0F));
  const glm::dvec3 warm = glm::normalize(glm::dvec3(1.0, 0.6, 0.2));
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const glm::dvec3 d = pixelCentreDirection(map, x, y);
      const double sky = d.y > 0 ? 0.3 + 0.7 * d.y : 0.1;
      const double band = 6.0 * std::exp(-8.0 * (1.0 - glm::dot(d, warm)));
      map.set(x, y, glm::vec3(glm::dvec3(sky + band, sky + 0.8 * band, sky + 0.5 * band)));
    }
  }
  return map;
}

LightSet lightsFrom(const EnvMap& map, std::size_t n) {
  return generateLights(buildSamplingTables(map), defaultSamplingPattern(map.layout).first(n),
                        SamplerKind::Havran);
}

render::ShadingLights shadingLightsFor(const LightSet& lights,
                                       const render::LightingGeometry& geometry, bool glossyPass,
                                       std::size_t highCount) {
  render::LightingOptions options;
  options.lightCount = lights.lights.size();
  options.shadowedCount = 0;
  options.glossyPass = glossyPass;
  options.highCount = highCount;
  options.maxConeLights = 100000;
  return render::buildShadingLights(lights, geometry, options);
}

std::optional<glm::ivec2> pixelOf(const scene::OrbitCamera& camera, glm::vec3 pointWorld,
                                  int widthPx, int heightPx) {
  const glm::vec4 clip = camera.clipFromView(float(widthPx) / float(heightPx)) *
                         camera.viewFromWorld() * glm::vec4(pointWorld, 1.0F);
  if (clip.w <= 0.0F) {
    return std::nullopt;
  }
  const float xPx = (clip.x / clip.w + 1.0F) * 0.5F * float(widthPx);
  const float yPx = (1.0F - clip.y / clip.w) * 0.5F * float(heightPx);
  const glm::ivec2 p(int(std::floor(xPx)), int(std::floor(yPx)));
  if (p.x < 1 || p.y < 1 || p.x >= widthPx - 1 || p.y >= heightPx - 1) {
    return std::nullopt;
  }
  return p;
}

double neighbourhoodMean(const render::LinearImage& image, glm::ivec2 p) {
  double sum = 0.0;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      sum += double(image.at(p.x + dx, p.y + dy).y);
    }
  }
  return sum / 9.0;
}

std::vector<std::size_t> coveredPixels(const render::LinearImage& image) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < image.pixelCount(); ++i) {
    if (image.covered[i] != 0) {
      out.push_back(i);
    }
  }
  return out;
}

double luminanceAt(const render::LinearImage& image, std::size_t pixel) {
  return luminance(double(image.rgb[3 * pixel]), double(image.rgb[3 * pixel + 1]),
                   double(image.rgb[3 * pixel + 2]));
}

double relativeRmsOver(const render::LinearImage& a, const render::LinearImage& r,
                       const std::vector<std::size_t>& pixels) {
  double error = 0.0;
  double energy = 0.0;
  for (const std::size_t i : pixels) {
    const double d = luminanceAt(a, i) - luminanceAt(r, i);
    error += d * d;
    energy += luminanceAt(r, i) * luminanceAt(r, i);
  }
  return energy > 0.0 ? std::sqrt(error / energy) : 0.0;
}

}  // namespace vem::embree::testing
