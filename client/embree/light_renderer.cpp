#include "client/embree/light_renderer.h"

#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "client/embree/parallel_rows.h"
#include "client/embree/shading_point.h"
#include "client/render/cube_map_sampling.h"
#include "client/render/shading_model.h"
#include "core/glossy_light_sets.h"

namespace vem::embree {
namespace {

struct Frame {
  const EmbreeScene& scene;
  const render::ShadingLights& lights;
  const render::LightingGeometry& geometry;
  const CubeMap* cube;
  LightRenderOptions options;
};

bool visible(const Frame& frame, const ShadingPoint& p, glm::vec3 dir) {
  return !frame.options.shadows || visibleToward(frame.scene, p, dir);
}

// The diffuse lights that can reach normal n: its region's list, or every light without lists.
std::vector<std::uint32_t> diffuseCandidates(const Frame& frame, glm::vec3 n) {
  const RegionLightLists& lists = frame.lights.diffuseLists;
  if (!lists.offsets.empty()) {
    const std::span<const std::uint32_t> of =
        lists.lightsOf(frame.geometry.diffuseRegions.regionOf(glm::dvec3(n)));
    return {of.begin(), of.end()};
  }
  std::vector<std::uint32_t> all(frame.lights.diffuse.lights.size());
  for (std::size_t i = 0; i < all.size(); ++i) {
    all[i] = std::uint32_t(i);
  }
  return all;
}

glm::vec3 diffuseLightsTerm(const Frame& frame, const ShadingPoint& p, bool withSpecular) {
  const glm::vec3 kd = render::diffuseBrdf(*p.material);
  glm::vec3 sum(0.0F);
  for (const std::uint32_t i : diffuseCandidates(frame, p.normal)) {
    const Light& light = frame.lights.diffuse.lights[i];
    const float cosine = glm::dot(p.normal, light.dir);
    if (cosine <= 0.0F || !visible(frame, p, light.dir)) {
      continue;
    }
    glm::vec3 f = kd;
    if (withSpecular) {
      f += render::specularBrdf(*p.material, p.normal, p.wo, light.dir);
    }
    sum += f * light.rgb * cosine;
  }
  return sum;
}

glm::vec3 glossyLightsTerm(const Frame& frame, const ShadingPoint& p) {
  const GlossyLightSets& sets = *frame.lights.glossy;
  const glm::vec3 r = render::reflectedDirection(p.normal, p.wo);
  glm::vec3 sum(0.0F);
  for (const GlossyShadingLight& g : glossyLightsFor(
           glm::dvec3(r), sets, frame.geometry.glossyRegions, frame.lights.maxConeLights)) {
    const Light& light = sets.low.lights[g.index];
    const float cosine = glm::dot(p.normal, light.dir);
    if (cosine <= 0.0F || !visible(frame, p, light.dir)) {
      continue;
    }
    const glm::vec3 f = render::specularBrdf(*p.material, p.normal, p.wo, light.dir);
    sum += f * light.rgb * (float(g.weight) * cosine);
  }
  return sum;
}

glm::vec3 shade(const Frame& frame, const ShadingPoint& p) {
  const scene::Material& m = *p.material;
  if (m.mirrorLike() && frame.cube != nullptr) {
    const glm::vec3 r = render::reflectedDirection(p.normal, p.wo);
    return diffuseLightsTerm(frame, p, false) +
           render::mirrorReflectance(m, p.normal, p.wo) * render::sampleCubeMap(*frame.cube, r);
  }
  if (m.glossy() && frame.lights.glossy) {
    return diffuseLightsTerm(frame, p, false) + glossyLightsTerm(frame, p);
  }
  return diffuseLightsTerm(frame, p, m.glossy());
}

void renderRow(const Frame& frame, const scene::OrbitCamera& camera, int row,
               render::LinearImage& image) {
  for (int x = 0; x < image.widthPx; ++x) {
    const scene::Ray ray =
        camera.primaryRay(float(x) + 0.5F, float(row) + 0.5F, image.widthPx, image.heightPx);
    if (const std::optional<ShadingPoint> p = shadingPointOf(frame.scene, ray)) {
      image.set(x, row, shade(frame, *p), true);
    } else {
      const glm::vec3 background =
          frame.cube != nullptr
              ? render::sampleBackground(*frame.cube, frame.options.cubeCoverage, ray.dirWorld)
              : glm::vec3(0.0F);
      image.set(x, row, background, false);
    }
  }
}

}  // namespace

render::LinearImage renderWithLights(const EmbreeScene& scene, const scene::OrbitCamera& camera,
                                     int widthPx, int heightPx, const render::ShadingLights& lights,
                                     const render::LightingGeometry& geometry, const CubeMap* cube,
                                     const LightRenderOptions& options) {
  render::LinearImage image = render::LinearImage::black(widthPx, heightPx);
  const Frame frame{scene, lights, geometry, cube, options};
  forEachRow(heightPx, options.threadCount, [&](int row) { renderRow(frame, camera, row, image); });
  return image;
}

}  // namespace vem::embree
