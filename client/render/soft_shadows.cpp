#include "client/render/soft_shadows.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "client/render/tangent_frame.h"
#include "client/render/texel_samples.h"
#include "core/color.h"
#include "core/direction_tree.h"

namespace vem::render {
namespace {

std::uint32_t hash32(std::uint32_t x) {
  x ^= x >> 16U;
  x *= 0x7feb352dU;
  x ^= x >> 15U;
  x *= 0x846ca68bU;
  x ^= x >> 16U;
  return x;
}

// A texel's place on a Z-order (Morton) curve over the plane tangent to the sphere at `dir`:
// neighbours along the curve are neighbours on the sphere, so a band of a stratum's table is a
// compact patch of it, and stratifying the draws over the table stratifies them in two dimensions.
std::uint32_t zOrderOf(glm::vec3 texelDir, glm::vec3 t, glm::vec3 b) {
  const auto quantised = [](float x) {
    return std::uint32_t(std::clamp((x + 1.0F) * 0.5F, 0.0F, 1.0F) * 65535.0F);
  };
  const std::uint32_t x = quantised(glm::dot(texelDir, t));
  const std::uint32_t y = quantised(glm::dot(texelDir, b));
  std::uint32_t code = 0;
  for (std::uint32_t bit = 0; bit < 16; ++bit) {
    code |= ((x >> bit) & 1U) << (2U * bit) | ((y >> bit) & 1U) << (2U * bit + 1U);
  }
  return code;
}

void sortAlongZCurve(std::vector<std::uint32_t>::iterator first,
                     std::vector<std::uint32_t>::iterator last,
                     const std::vector<TexelSample>& texels, glm::vec3 lightDir) {
  const auto [t, b] = tangentFrameAround(glm::normalize(lightDir));
  std::vector<std::uint64_t> keyed;  // (z-order << 32) | texel: one sort, ties by texel
  keyed.reserve(std::size_t(last - first));
  for (auto it = first; it != last; ++it) {
    keyed.push_back(std::uint64_t(zOrderOf(texels[*it].dir, t, b)) << 32U | *it);
  }
  std::sort(keyed.begin(), keyed.end());
  for (const std::uint64_t k : keyed) *first++ = std::uint32_t(k & 0xffffffffU);
}

}  // namespace

glm::vec3 fixedUniforms(std::uint32_t a, std::uint32_t b) {
  const std::uint32_t h1 = hash32(a * 0x9e3779b1U ^ hash32(b + 0x68e31da4U));
  const std::uint32_t h2 = hash32(h1 ^ 0xb5297a4dU);
  const std::uint32_t h3 = hash32(h2 ^ 0x1b56c4e9U);
  constexpr float kScale = 1.0F / 16777216.0F;
  return {float(h1 >> 8U) * kScale, float(h2 >> 8U) * kScale, float(h3 >> 8U) * kScale};
}

glm::vec3 ShadowStrata::sample(std::size_t light, glm::vec3 lightDir, float u1, float u2,
                               float u3) const {
  const auto first = cdf.begin() + std::ptrdiff_t(offsets[light]);
  const auto last = cdf.begin() + std::ptrdiff_t(offsets[light + 1]);
  if (!softAt(light) || first == last) return lightDir;
  const auto at = std::min(std::upper_bound(first, last, u1), last - 1);
  return directionInCubeTexel(texel[std::size_t(at - cdf.begin())], facePx, u2, u3);
}

ShadowStrata buildShadowStrata(std::span<const Light> lights, const CubeMap& cube) {
  const std::size_t n = lights.size();
  ShadowStrata out;
  out.soft.assign(n, 0);
  out.powerRgb.assign(n, glm::vec3(0.0F));
  out.spreadSr.assign(n, 0.0F);
  out.offsets.assign(n + 1, 0);
  const CubeMapLevel& level = cubeLevelAtMost(cube, kStrataFacePx);
  out.facePx = level.facePx;
  std::vector<glm::dvec3> dirs;
  std::vector<std::uint32_t> lightOf;  // the index in `lights` of each entry of dirs
  for (std::uint32_t i = 0; i < n; ++i) {
    const glm::dvec3 d(lights[i].dir);
    const double length = glm::length(d);
    if (!(length > 0.0) || !std::isfinite(length)) continue;
    dirs.push_back(d / length);
    lightOf.push_back(i);
  }
  if (dirs.empty()) return out;
  const DirectionCloud cloud{dirs};
  const DirectionTree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));

  // Each texel's nearest light, then the texels grouped by light (a counting sort).
  const std::vector<TexelSample> texels = texelSamplesOf(level);
  std::vector<std::uint32_t> owner(texels.size());
  std::vector<std::uint32_t> count(n, 0);
  std::vector<glm::dvec3> weightedDir(n, glm::dvec3(0.0));
  std::vector<double> weight(n, 0.0);
  for (std::size_t t = 0; t < texels.size(); ++t) {
    const glm::dvec3 d(texels[t].dir);
    std::uint32_t nearest = 0;
    double chord2 = 0.0;
    tree.knnSearch(&d.x, 1, &nearest, &chord2);
    const std::uint32_t i = lightOf[nearest];
    owner[t] = i;
    ++count[i];
    const double y = luminance(texels[t].radianceSr);
    out.powerRgb[i] += texels[t].radianceSr;
    weightedDir[i] += y * d;
    weight[i] += y;
  }
  for (std::size_t i = 0; i < n; ++i) out.offsets[i + 1] = out.offsets[i] + count[i];
  out.texel.resize(texels.size());
  out.cdf.resize(texels.size());
  std::vector<std::uint32_t> next(out.offsets.begin(), out.offsets.end() - 1);
  for (std::size_t t = 0; t < texels.size(); ++t) out.texel[next[owner[t]]++] = std::uint32_t(t);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t begin = out.offsets[i];
    const std::uint32_t end = out.offsets[i + 1];
    sortAlongZCurve(out.texel.begin() + begin, out.texel.begin() + end, texels, lights[i].dir);
    if (!(weight[i] > 0.0) || !std::isfinite(weight[i])) {
      // No light to draw from: a hard shadow, and a uniform table that sample() never needs.
      for (std::uint32_t k = begin; k < end; ++k) out.cdf[k] = float(k - begin + 1) / float(end - begin);
      out.powerRgb[i] = glm::vec3(0.0F);
      continue;
    }
    double sum = 0.0;
    for (std::uint32_t k = begin; k < end; ++k) {
      sum += luminance(texels[out.texel[k]].radianceSr);
      out.cdf[k] = float(sum / weight[i]);
    }
    out.cdf[end - 1] = 1.0F;
    const double meanLength = std::min(1.0, glm::length(weightedDir[i]) / weight[i]);
    out.spreadSr[i] = float(4.0 * std::numbers::pi * (1.0 - meanLength));
    out.soft[i] = out.spreadSr[i] >= kSoftShadowMinSr ? 1 : 0;
  }
  return out;
}

}  // namespace vem::render
