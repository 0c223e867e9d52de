#include "client/embree/reference_renderer.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "client/embree/brdf_sampling.h"
#include "client/embree/parallel_rows.h"
#include "client/embree/sample_rng.h"
#include "client/embree/shading_point.h"
#include "client/render/shading_model.h"
#include "core/color.h"
#include "core/cube_map.h"
#include "core/sampling_tables.h"
#include "core/standard_sampler.h"
#include "util/contract.h"

namespace vem::embree {
namespace {

struct Environment {
  const EnvMap& map;
  SamplingTables tables;
};

// The (sanitised) value of the map pixel holding `dir`: what standardPdfSr's density follows.
glm::vec3 envPixel(const Environment& env, glm::vec3 dir) {
  if (env.map.layout == MapLayout::Hemisphere && dir.y < 0.0F) {
    return glm::vec3(0.0F);
  }
  const MapCoords c = mapCoordsFromDirection(env.tables, glm::dvec3(dir));
  const int y = std::clamp(int(c.r), 0, env.map.height - 1);
  const int x = std::clamp(int(c.xc), 0, env.map.width - 1);
  return glm::vec3(sanitizedRgb(env.map, x, y));
}

// One pixel's running estimate. `fixed` is the deterministic part (a mirror's reflection).
struct PixelState {
  std::optional<ShadingPoint> point;
  BrdfLobes lobes;
  glm::vec3 fixed{0.0F};
  glm::dvec3 sumRgb{0.0};
  double sumY = 0.0;
  double sumY2 = 0.0;
};

struct Context {
  const EmbreeScene& scene;
  const Environment& env;
  const ReferenceOptions& options;
  int widthPx;
};

// f L cos / (p_env + p_brdf) for one direction, whichever strategy drew it (balance heuristic
// with one sample per strategy).
glm::vec3 misTerm(const Context& c, const PixelState& s, glm::vec3 wi) {
  const float cosine = glm::dot(s.point->normal, wi);
  if (cosine <= 0.0F) {
    return glm::vec3(0.0F);
  }
  const glm::vec3 f = brdfValue(s.lobes, wi);
  const glm::vec3 radiance = envPixel(c.env, wi);
  const double pdfSum =
      standardPdfSr(c.env.tables, glm::dvec3(wi)) + double(brdfPdfSr(s.lobes, wi));
  if (f == glm::vec3(0.0F) || radiance == glm::vec3(0.0F) || !(pdfSum > 0.0)) {
    return glm::vec3(0.0F);
  }
  if (!visibleToward(c.scene, *s.point, wi)) {
    return glm::vec3(0.0F);
  }
  return f * radiance * float(double(cosine) / pdfSum);
}

glm::vec3 oneSample(const Context& c, const PixelState& s, SampleRng& rng) {
  const double u0 = rng.nextDouble();
  const double u1 = rng.nextDouble();
  const MapSample fromEnv = standardSample(c.env.tables, glm::dvec2(u0, u1));
  const glm::vec3 u(rng.nextFloat(), rng.nextFloat(), rng.nextFloat());
  const glm::vec3 fromBrdf = sampleBrdfDirection(s.lobes, u);
  return s.fixed + misTerm(c, s, glm::normalize(glm::vec3(fromEnv.dir))) + misTerm(c, s, fromBrdf);
}

void samplePixel(const Context& c, PixelState& s, std::size_t pixel, int firstSample, int count) {
  for (int k = firstSample; k < firstSample + count; ++k) {
    SampleRng rng(c.options.seed, pixel, std::uint64_t(k));
    const glm::dvec3 value(oneSample(c, s, rng));
    const double y = luminance(value);
    s.sumRgb += value;
    s.sumY += y;
    s.sumY2 += y * y;
  }
}

PixelState primaryState(const Context& c, const scene::ViewCamera& camera, int x, int y,
                        int heightPx) {
  PixelState s;
  const scene::Ray ray = camera.primaryRay(float(x) + 0.5F, float(y) + 0.5F, c.widthPx, heightPx);
  s.point = shadingPointOf(c.scene, ray);
  if (!s.point) {
    s.fixed = sampleEnvMapBilinear(c.env.map, glm::dvec3(ray.dirWorld));
    return s;
  }
  const scene::Material& m = *s.point->material;
  const bool mirror = m.mirrorLike();
  s.lobes = BrdfLobes{&m, !mirror, s.point->normal, s.point->wo};
  if (mirror) {
    const glm::vec3 r = glm::normalize(render::reflectedDirection(s.point->normal, s.point->wo));
    if (visibleToward(c.scene, *s.point, r)) {
      s.fixed = render::mirrorReflectance(m, s.point->normal, s.point->wo) *
                sampleEnvMapBilinear(c.env.map, glm::dvec3(r));
    }
  }
  return s;
}

double relativeStandardError(const PixelState& s, int n) {
  const double mean = s.sumY / n;
  const double variance = std::max(0.0, (s.sumY2 - s.sumY * mean) / std::max(n - 1, 1));
  if (variance <= 0.0) {
    return 0.0;
  }
  return mean > 0.0 ? std::sqrt(variance / n) / mean : 1.0;
}

double meanRelativeError(const std::vector<PixelState>& pixels, int n) {
  double sum = 0.0;
  std::size_t covered = 0;
  for (const PixelState& s : pixels) {
    if (s.point) {
      sum += relativeStandardError(s, n);
      ++covered;
    }
  }
  return covered > 0 ? sum / double(covered) : 0.0;
}

render::LinearImage imageOf(const std::vector<PixelState>& pixels, int widthPx, int heightPx,
                            int n) {
  render::LinearImage image = render::LinearImage::black(widthPx, heightPx);
  for (int y = 0; y < heightPx; ++y) {
    for (int x = 0; x < widthPx; ++x) {
      const PixelState& s = pixels[std::size_t(y) * std::size_t(widthPx) + std::size_t(x)];
      const bool covered = s.point.has_value() && n > 0;
      image.set(x, y, covered ? glm::vec3(s.sumRgb / double(n)) : s.fixed, s.point.has_value());
    }
  }
  return image;
}

}  // namespace

ReferenceResult renderReference(const EmbreeScene& scene, const scene::ViewCamera& camera,
                                int widthPx, int heightPx, const EnvMap& map,
                                const ReferenceOptions& options) {
  VEM_EXPECTS(map.pixelCount() > 0 && options.samplesPerPass >= 1);
  const Environment env{map, buildSamplingTables(map)};
  const Context c{scene, env, options, widthPx};
  std::vector<PixelState> pixels(std::size_t(widthPx) * std::size_t(heightPx));
  forEachRow(heightPx, options.threadCount, [&](int y) {
    for (int x = 0; x < widthPx; ++x) {
      pixels[std::size_t(y) * std::size_t(widthPx) + std::size_t(x)] =
          primaryState(c, camera, x, y, heightPx);
    }
  });
  ReferenceResult result;
  int n = 0;
  while (n < options.maxSamples) {
    const int count = std::min(options.samplesPerPass, options.maxSamples - n);
    forEachRow(heightPx, options.threadCount, [&](int y) {
      for (int x = 0; x < widthPx; ++x) {
        const std::size_t i = std::size_t(y) * std::size_t(widthPx) + std::size_t(x);
        if (pixels[i].point) {
          samplePixel(c, pixels[i], i, n, count);
        }
      }
    });
    n += count;
    result.relativeError = meanRelativeError(pixels, n);
    if (n >= options.minSamples && result.relativeError < options.targetRelativeError) {
      result.converged = true;
      break;
    }
  }
  result.samplesPerPixel = n;
  result.image = imageOf(pixels, widthPx, heightPx, n);
  return result;
}

}  // namespace vem::embree
