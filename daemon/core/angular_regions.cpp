#include "core/angular_regions.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <glm/geometric.hpp>
#include <memory>
#include <numbers>
#include <span>

#include "core/cube_map_lookup.h"
#include "core/sphere_points.h"
#include "util/contract.h"

namespace vem {
namespace {

// Angle between unit vectors, accurate for small and large angles alike.
double angleBetweenRad(glm::dvec3 a, glm::dvec3 b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

std::uint32_t nearestCentre(const std::vector<glm::dvec3>& centres, glm::dvec3 dir) {
  std::size_t best = 0;
  double bestDot = -2.0;
  for (std::size_t i = 0; i < centres.size(); ++i) {
    const double d = glm::dot(centres[i], dir);
    if (d > bestDot) {
      bestDot = d;
      best = i;
    }
  }
  return std::uint32_t(best);
}

// Fills the table and grows each region's radius to cover every texel that maps to it.
void fillTable(AngularRegions& regions) {
  const std::size_t texels = cubeTexelCount(regions.faceSize);
  regions.regionOfTexel.resize(texels);
  regions.radiusRad.assign(regions.count(), 0.0);
  for (std::size_t index = 0; index < texels; ++index) {
    const CubeTexel texel = cubeTexelFromIndex(index, regions.faceSize);
    const glm::dvec3 centre = cubeTexelCentreDirection(texel, regions.faceSize);
    const std::uint32_t region = nearestCentre(regions.centres, centre);
    regions.regionOfTexel[index] = region;
    const double reach = angleBetweenRad(regions.centres[region], centre) +
                         cubeTexelRadiusRad(texel, regions.faceSize);
    regions.radiusRad[region] = std::max(regions.radiusRad[region], reach);
  }
  for (double& radius : regions.radiusRad) radius += kRegionRadiusMarginRad;
}

// Light directions as float arrays, one per axis, so the region tests vectorise.
struct DirectionArrays {
  std::vector<float> x, y, z;
};

DirectionArrays directionArrays(std::span<const Light> lights) {
  DirectionArrays d;
  d.x.reserve(lights.size());
  d.y.reserve(lights.size());
  d.z.reserve(lights.size());
  for (const Light& light : lights) {
    const glm::vec3 u = glm::normalize(light.dir);
    d.x.push_back(u.x);
    d.y.push_back(u.y);
    d.z.push_back(u.z);
  }
  return d;
}

// For each 8-bit mask, the positions of its set bits (left-packed) and how many there are.
struct LeftPackTable {
  std::array<std::array<std::uint8_t, 8>, 256> positions{};
  std::array<std::uint8_t, 256> counts{};
  LeftPackTable() {
    for (unsigned mask = 0; mask < 256; ++mask) {
      for (unsigned bit = 0; bit < 8; ++bit)
        if ((mask >> bit) & 1U) positions[mask][counts[mask]++] = std::uint8_t(bit);
    }
  }
};

// Writes at `out` the indices of the lights within `limitRad` of `centre`, in light order, and
// returns how many. `out` must have room for the light count rounded up to 8. The test runs in
// float with kFloatDotSlack of slack toward inclusion, so it stays conservative. Branch-free: the
// tests fill `keep` (vectorised), then each group of eight lights writes its kept indices at once
// through a left-pack table (a serial compaction costs a dependent store per light).
std::size_t writeLightsWithin(glm::dvec3 centre, const DirectionArrays& dirs, double limitRad,
                              std::uint8_t* keep, std::uint32_t* out) {
  static const LeftPackTable pack;
  constexpr float kFloatDotSlack = 1e-5F;
  const float minDot =
      limitRad >= std::numbers::pi ? -2.0F : float(std::cos(limitRad)) - kFloatDotSlack;
  const float cx = float(centre.x), cy = float(centre.y), cz = float(centre.z);
  const std::size_t n = dirs.x.size();
  const float* x = dirs.x.data();
  const float* y = dirs.y.data();
  const float* z = dirs.z.data();
  for (std::size_t i = 0; i < n; ++i)
    keep[i] = std::uint8_t(cx * x[i] + cy * y[i] + cz * z[i] > minDot);
  std::size_t end = 0;
  for (std::size_t group = 0; group < n; group += 8) {
    std::uint64_t bytes;  // eight 0/1 bytes; the multiply gathers them into one 8-bit mask
    std::memcpy(&bytes, keep + group, sizeof bytes);
    const unsigned mask = unsigned((bytes * 0x0102040810204080ULL) >> 56);
    const auto& positions = pack.positions[mask];
    for (unsigned j = 0; j < 8; ++j) out[end + j] = std::uint32_t(group + positions[j]);
    end += pack.counts[mask];
  }
  return end;
}

}  // namespace

std::uint32_t AngularRegions::regionOf(glm::dvec3 dir) const {
  return regionOfTexel[cubeTexelIndex(cubeTexelOf(dir, faceSize), faceSize)];
}

AngularRegions makeAngularRegions(int regionCount, int faceSize) {
  VEM_EXPECTS(regionCount >= 1 && faceSize >= 1);
  AngularRegions regions;
  regions.centres = fibonacciSphere(regionCount);
  regions.faceSize = faceSize;
  fillTable(regions);
  return regions;
}

double minCentreSeparationRad(const AngularRegions& regions) {
  VEM_EXPECTS(regions.count() >= 2);
  double maxDot = -1.0;
  for (std::size_t i = 0; i < regions.count(); ++i) {
    for (std::size_t j = i + 1; j < regions.count(); ++j) {
      maxDot = std::max(maxDot, glm::dot(regions.centres[i], regions.centres[j]));
    }
  }
  return std::acos(std::clamp(maxDot, -1.0, 1.0));
}

std::span<const std::uint32_t> RegionLightLists::lightsOf(std::uint32_t region) const {
  VEM_EXPECTS(std::size_t(region) + 1 < offsets.size());
  return std::span<const std::uint32_t>(lightIndices)
      .subspan(offsets[region], offsets[region + 1] - offsets[region]);
}

double RegionLightLists::meanFraction(std::size_t lightCount) const {
  const std::size_t regionCount = offsets.empty() ? 0 : offsets.size() - 1;
  if (lightCount == 0 || regionCount == 0) return 0.0;
  return double(lightIndices.size()) / (double(regionCount) * double(lightCount));
}

RegionLightLists regionLightLists(const AngularRegions& regions, std::span<const Light> lights,
                                  double reachRad) {
  const DirectionArrays dirs = directionArrays(lights);
  const std::size_t padded = (lights.size() + 7) / 8 * 8;
  // Scratch without zero-filling: every list is written, then copied out once.
  std::vector<std::uint8_t> keep(padded, 0);
  const auto scratch =
      std::make_unique_for_overwrite<std::uint32_t[]>(regions.count() * padded + 8);
  RegionLightLists lists;
  lists.offsets.reserve(regions.count() + 1);
  lists.offsets.push_back(0);
  std::size_t end = 0;
  for (std::size_t i = 0; i < regions.count(); ++i) {
    end += writeLightsWithin(regions.centres[i], dirs, regions.radiusRad[i] + reachRad, keep.data(),
                             scratch.get() + end);
    lists.offsets.push_back(std::uint32_t(end));
  }
  lists.lightIndices.assign(scratch.get(), scratch.get() + end);
  return lists;
}

RegionLightLists visibleLightLists(const AngularRegions& regions, const LightSet& lights) {
  return regionLightLists(regions, lights.lights, kHemisphereReachRad);
}

}  // namespace vem
