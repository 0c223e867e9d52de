#include "client/embree/light_renderer.h"

#include <algorithm>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "client/embree/parallel_rows.h"
#include "client/embree/shading_point.h"
#include "client/render/cube_map_sampling.h"
#include "client/render/shading_model.h"
#include "core/color.h"
#include "core/glossy_light_sets.h"

namespace vem::embree {
namespace {

struct Frame {
  const EmbreeScene& scene;
  const render::ShadingLights& lights;
  const render::LightingGeometry& geometry;
  const CubeMap* cube;
  LightRenderOptions options;
  std::vector<float> peakFractions;  // per diffuse light, with an environment (ratio shading)
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

// The cube map's reflection of a mirror-like material (unoccluded, as the GL renderer).
glm::vec3 mirrorTerm(const Frame& frame, const ShadingPoint& p) {
  const glm::vec3 r = render::reflectedDirection(p.normal, p.wo);
  return render::mirrorReflectance(*p.material, p.normal, p.wo) *
         render::sampleCubeMap(*frame.cube, r);
}

// Per channel S / U; 1 where U is 0 (nothing known to block), the luminance ratio for a channel
// that carries under 1e-6 of the largest.
glm::vec3 ratioOf(glm::vec3 shadowed, glm::vec3 unshadowed) {
  const float largest = std::max({unshadowed.x, unshadowed.y, unshadowed.z});
  if (!(largest > 0.0F)) return glm::vec3(1.0F);
  const auto overall = float(luminance(shadowed) / std::max(luminance(unshadowed), 1e-30));
  glm::vec3 out;
  for (int c = 0; c < 3; ++c) {
    out[c] = unshadowed[c] > 1e-6F * largest ? shadowed[c] / unshadowed[c] : overall;
  }
  return out;
}

glm::vec3 shadeByRatio(const Frame& frame, const ShadingPoint& p) {
  const render::EnvironmentLighting& env = *frame.options.environment;
  const scene::Material& m = *p.material;
  const std::size_t materialIndex = p.hit.materialIndex;
  const bool specularByRatio = m.glossy() && !m.mirrorLike() &&
                               materialIndex < env.specular.size() &&
                               env.specular[materialIndex].has_value();
  glm::vec3 unshadowedD(0.0F);
  glm::vec3 shadowedD(0.0F);
  glm::vec3 unshadowedS(0.0F);
  glm::vec3 shadowedS(0.0F);
  glm::vec3 peakS(0.0F);  // the clipped peaks' specular light, exact per light
  double sumY = 0.0;
  double sumY2 = 0.0;
  for (const std::uint32_t i : diffuseCandidates(frame, p.normal)) {
    const Light& light = frame.lights.diffuse.lights[i];
    const float cosine = glm::dot(p.normal, light.dir);
    if (cosine <= 0.0F) continue;
    const float v = visible(frame, p, light.dir) ? 1.0F : 0.0F;
    const glm::vec3 wd = light.rgb * cosine;
    unshadowedD += wd;
    shadowedD += v * wd;
    if (specularByRatio) {
      const glm::vec3 full = render::specularBrdf(m, p.normal, p.wo, light.dir) * wd;
      const float peak = frame.peakFractions.empty() ? 0.0F : frame.peakFractions[i];
      peakS += (v * peak) * full;
      const glm::vec3 ws = (1.0F - peak) * full;
      unshadowedS += ws;
      shadowedS += v * ws;
      const double y = luminance(ws);
      sumY += y;
      sumY2 += y * y;
    }
  }
  const glm::vec3 ratioD = ratioOf(shadowedD, unshadowedD);
  glm::vec3 radiance = render::unshadowedDiffuse(env, m, p.normal) * ratioD;
  if (specularByRatio) {
    const double effective = sumY2 > 0.0 ? sumY * sumY / sumY2 : 0.0;
    const auto t = float(std::clamp(effective / frame.options.minEffectiveLights, 0.0, 1.0));
    const glm::vec3 ratioS = glm::mix(ratioD, ratioOf(shadowedS, unshadowedS), t);
    radiance += render::unshadowedSpecular(env, materialIndex, m, p.normal, p.wo) * ratioS + peakS;
  } else if (m.mirrorLike() && frame.cube != nullptr) {
    radiance += mirrorTerm(frame, p);
  }
  return radiance;
}

glm::vec3 shade(const Frame& frame, const ShadingPoint& p) {
  if (frame.options.environment != nullptr) return shadeByRatio(frame, p);
  const scene::Material& m = *p.material;
  if (m.mirrorLike() && frame.cube != nullptr) {
    return diffuseLightsTerm(frame, p, false) + mirrorTerm(frame, p);
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
  Frame frame{scene, lights, geometry, cube, options, {}};
  if (options.environment != nullptr && cube != nullptr) {
    frame.peakFractions =
        render::peakFractionsOf(*options.environment, *cube, lights.diffuse.lights);
  }
  forEachRow(heightPx, options.threadCount, [&](int row) { renderRow(frame, camera, row, image); });
  return image;
}

}  // namespace vem::embree
