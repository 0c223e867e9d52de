#include "client/embree/light_renderer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "client/embree/parallel_rows.h"
#include "client/embree/shading_point.h"
#include "client/render/cube_map_sampling.h"
#include "client/render/shading_model.h"
#include "client/render/soft_shadows.h"
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
  // The diffuse lights' strata (render/soft_shadows.h); none: hard shadows.
  std::optional<render::ShadowStrata> strata;
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

// The cube map's reflection of a mirror-like material, 0 where the scene blocks the reflected ray
// (direct light only, as the reference renderer).
glm::vec3 mirrorTerm(const Frame& frame, const ShadingPoint& p) {
  const glm::vec3 r = glm::normalize(render::reflectedDirection(p.normal, p.wo));
  if (!visible(frame, p, r)) return glm::vec3(0.0F);
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

// The sums of a set of lights that the ratios divide: shadowed and unshadowed, diffuse and specular.
struct LightSums {
  glm::vec3 unshadowedD{0.0F};
  glm::vec3 shadowedD{0.0F};
  glm::vec3 unshadowedS{0.0F};
  glm::vec3 shadowedS{0.0F};

  void add(const LightSums& o, float weight) {
    unshadowedD += weight * o.unshadowedD;
    shadowedD += weight * o.shadowedD;
    unshadowedS += weight * o.unshadowedS;
    shadowedS += weight * o.shadowedS;
  }
};

// One pixel's sums: of the hard lights (shadow rays toward the light) and of the soft ones
// (shadow rays jittered over the light's cone, then filtered over neighbouring pixels).
struct RatioSums {
  LightSums hard;
  LightSums soft;
  glm::vec3 peakS{0.0F};  // the clipped peaks' specular light, exact per light
  float specularBlend = 0.0F;  // t: ratio_s = mix(ratio_d, S_s / U_s, t)
};

bool specularByRatio(const Frame& frame, const ShadingPoint& p) {
  const render::EnvironmentLighting& env = *frame.options.environment;
  const std::size_t materialIndex = p.hit.materialIndex;
  return p.material->glossy() && !p.material->mirrorLike() && materialIndex < env.specular.size() &&
         env.specular[materialIndex].has_value();
}

RatioSums ratioSumsOf(const Frame& frame, const ShadingPoint& p, std::uint32_t pixel) {
  const scene::Material& m = *p.material;
  const bool bySpecular = specularByRatio(frame, p);
  RatioSums out;
  double sumY = 0.0;
  double sumY2 = 0.0;
  // No shadow rays where no light term is used (a mirror without a diffuse part).
  const bool lightsUsed =
      bySpecular || std::max({m.diffuseAlbedo.x, m.diffuseAlbedo.y, m.diffuseAlbedo.z}) > 0.0F;
  for (const std::uint32_t i :
       lightsUsed ? diffuseCandidates(frame, p.normal) : std::vector<std::uint32_t>{}) {
    const Light& light = frame.lights.diffuse.lights[i];
    const float cosine = glm::dot(p.normal, light.dir);
    const bool soft = frame.strata.has_value() && frame.strata->softAt(i);
    glm::vec3 shadowDir = light.dir;
    glm::vec3 wd = light.rgb * cosine;
    if (soft) {
      // One direction of the light's stratum, weighed by the stratum's power and its own cosine.
      const glm::vec3 u = render::fixedUniforms(pixel, i);
      shadowDir = frame.strata->sample(i, light.dir, u.x, u.y, u.z);
      const float drawnCosine = glm::dot(p.normal, shadowDir);
      if (drawnCosine <= 0.0F) continue;  // this draw lies below the surface
      wd = frame.strata->powerRgb[i] * drawnCosine;
    } else if (cosine <= 0.0F) {
      continue;
    }
    const float v = visible(frame, p, shadowDir) ? 1.0F : 0.0F;
    LightSums& sums = soft ? out.soft : out.hard;
    sums.unshadowedD += wd;
    sums.shadowedD += v * wd;
    if (bySpecular && cosine > 0.0F) {
      const glm::vec3 full = render::specularBrdf(m, p.normal, p.wo, light.dir) * light.rgb * cosine;
      const float peak = frame.peakFractions.empty() ? 0.0F : frame.peakFractions[i];
      out.peakS += (v * peak) * full;
      const glm::vec3 ws = (1.0F - peak) * full;
      sums.unshadowedS += ws;
      sums.shadowedS += v * ws;
      const double y = luminance(ws);
      sumY += y;
      sumY2 += y * y;
    }
  }
  const double effective = sumY2 > 0.0 ? sumY * sumY / sumY2 : 0.0;
  out.specularBlend = float(std::clamp(effective / frame.options.minEffectiveLights, 0.0, 1.0));
  return out;
}

glm::vec3 composeByRatio(const Frame& frame, const ShadingPoint& p, const RatioSums& sums) {
  const render::EnvironmentLighting& env = *frame.options.environment;
  const scene::Material& m = *p.material;
  LightSums all = sums.hard;
  all.add(sums.soft, 1.0F);
  const glm::vec3 ratioD = ratioOf(all.shadowedD, all.unshadowedD);
  glm::vec3 radiance = render::unshadowedDiffuse(env, m, p.normal) * ratioD;
  if (specularByRatio(frame, p)) {
    const glm::vec3 ratioS =
        glm::mix(ratioD, ratioOf(all.shadowedS, all.unshadowedS), sums.specularBlend);
    radiance += render::unshadowedSpecular(env, p.hit.materialIndex, m, p.normal, p.wo) * ratioS +
                sums.peakS;
  } else if (m.mirrorLike() && frame.cube != nullptr) {
    radiance += mirrorTerm(frame, p);
  }
  return radiance;
}

glm::vec3 backgroundOf(const Frame& frame, const scene::Ray& ray) {
  return frame.cube != nullptr
             ? render::sampleBackground(*frame.cube, frame.options.cubeCoverage, ray.dirWorld)
             : glm::vec3(0.0F);
}

glm::vec3 shade(const Frame& frame, const ShadingPoint& p) {
  const scene::Material& m = *p.material;
  if (m.mirrorLike() && frame.cube != nullptr) {
    return diffuseLightsTerm(frame, p, false) + mirrorTerm(frame, p);
  }
  if (m.glossy() && frame.lights.glossy) {
    return diffuseLightsTerm(frame, p, false) + glossyLightsTerm(frame, p);
  }
  return diffuseLightsTerm(frame, p, m.glossy());
}

void renderRow(const Frame& frame, const scene::ViewCamera& camera, int row,
               render::LinearImage& image) {
  for (int x = 0; x < image.widthPx; ++x) {
    const scene::Ray ray =
        camera.primaryRay(float(x) + 0.5F, float(row) + 0.5F, image.widthPx, image.heightPx);
    if (const std::optional<ShadingPoint> p = shadingPointOf(frame.scene, ray)) {
      const glm::vec3 radiance =
          frame.options.environment != nullptr
              ? composeByRatio(frame, *p,
                               ratioSumsOf(frame, *p, std::uint32_t(row * image.widthPx + x)))
              : shade(frame, *p);
      image.set(x, row, radiance, true);
    } else {
      image.set(x, row, backgroundOf(frame, ray), false);
    }
  }
}

// Soft shadows: one pixel's shading point and sums, before the filter.
struct PixelRecord {
  std::optional<ShadingPoint> point;
  RatioSums sums;
};

void recordRow(const Frame& frame, const scene::ViewCamera& camera, int row,
               std::vector<PixelRecord>& records, render::LinearImage& image) {
  for (int x = 0; x < image.widthPx; ++x) {
    const scene::Ray ray =
        camera.primaryRay(float(x) + 0.5F, float(row) + 0.5F, image.widthPx, image.heightPx);
    PixelRecord& record = records[std::size_t(row * image.widthPx + x)];
    record.point = shadingPointOf(frame.scene, ray);
    if (record.point) {
      record.sums = ratioSumsOf(frame, *record.point, std::uint32_t(row * image.widthPx + x));
    } else {
      image.set(x, row, backgroundOf(frame, ray), false);
    }
  }
}

// The pixel's shadowed and unshadowed sums averaged over its neighbours within the filter radius
// that see the same material at about the same depth and normal (a cross-bilateral filter of
// numerator and denominator apart, so the ratio is one of averages).
RatioSums filteredSums(const Frame& frame, const std::vector<PixelRecord>& records, int x, int y,
                       int widthPx, int heightPx) {
  const PixelRecord& centre = records[std::size_t(y * widthPx + x)];
  const ShadingPoint& c = *centre.point;
  const int radius = frame.options.softShadowFilterPx;
  const float sigmaPx = std::max(1.0F, 0.5F * float(radius));
  RatioSums out = centre.sums;
  out.soft = LightSums{};
  float weightSum = 0.0F;
  for (int dy = -radius; dy <= radius; ++dy) {
    const int ny = y + dy;
    if (ny < 0 || ny >= heightPx) continue;
    for (int dx = -radius; dx <= radius; ++dx) {
      const int nx = x + dx;
      if (nx < 0 || nx >= widthPx) continue;
      const PixelRecord& n = records[std::size_t(ny * widthPx + nx)];
      if (!n.point || n.point->hit.materialIndex != c.hit.materialIndex) continue;
      const float cosine = glm::dot(n.point->normal, c.normal);
      if (cosine < 0.8F) continue;  // another face or a sharp bend
      const float depthOff =
          std::abs(n.point->hit.distance - c.hit.distance) / (0.02F * c.hit.distance);
      const float c2 = cosine * cosine;
      const float c4 = c2 * c2;
      const float c16 = c4 * c4 * c4 * c4;
      const float w = std::exp(-float(dx * dx + dy * dy) / (2.0F * sigmaPx * sigmaPx) -
                               depthOff * depthOff) *
                      c16;
      out.soft.add(n.sums.soft, w);
      weightSum += w;
    }
  }
  // The centre's own weight is 1, so weightSum >= 1.
  LightSums mean;
  mean.add(out.soft, 1.0F / weightSum);
  out.soft = mean;
  return out;
}

}  // namespace

render::LinearImage renderWithLights(const EmbreeScene& scene, const scene::ViewCamera& camera,
                                     int widthPx, int heightPx, const render::ShadingLights& lights,
                                     const render::LightingGeometry& geometry, const CubeMap* cube,
                                     const LightRenderOptions& options) {
  render::LinearImage image = render::LinearImage::black(widthPx, heightPx);
  Frame frame{scene, lights, geometry, cube, options, {}, {}};
  const bool byRatio = options.environment != nullptr;
  if (byRatio && cube != nullptr) {
    frame.peakFractions =
        render::peakFractionsOf(*options.environment, *cube, lights.diffuse.lights);
  }
  if (!byRatio || !options.softShadows || cube == nullptr) {
    forEachRow(heightPx, options.threadCount,
               [&](int row) { renderRow(frame, camera, row, image); });
    return image;
  }
  frame.strata = render::buildShadowStrata(lights.diffuse.lights, *cube);
  std::vector<PixelRecord> records(std::size_t(widthPx) * std::size_t(heightPx));
  forEachRow(heightPx, options.threadCount,
             [&](int row) { recordRow(frame, camera, row, records, image); });
  forEachRow(heightPx, options.threadCount, [&](int row) {
    for (int x = 0; x < widthPx; ++x) {
      const PixelRecord& record = records[std::size_t(row * widthPx + x)];
      if (!record.point) continue;
      const RatioSums sums = filteredSums(frame, records, x, row, widthPx, heightPx);
      image.set(x, row, composeByRatio(frame, *record.point, sums), true);
    }
  });
  return image;
}

}  // namespace vem::embree
