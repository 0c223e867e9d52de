#include "client/render/shadow_groups.h"

#include <algorithm>

#include <glm/geometric.hpp>

#include "core/color.h"
#include "core/light_clustering.h"

namespace vem::render {
namespace {

// The group means of Lloyd's update step, in double. A group without weight, or whose mean is
// too short, keeps `previous`.
std::vector<glm::vec3> groupMeans(std::span<const Light> lights, std::span<const double> weights,
                                  std::span<const std::int32_t> slots,
                                  std::span<const glm::vec3> previous) {
  std::vector<glm::dvec3> sums(previous.size(), glm::dvec3(0.0));
  std::vector<double> weightOf(previous.size(), 0.0);
  for (std::size_t i = 0; i < lights.size(); ++i) {
    const auto slot = std::size_t(slots[i]);
    sums[slot] += weights[i] * glm::dvec3(lights[i].dir);
    weightOf[slot] += weights[i];
  }
  std::vector<glm::vec3> means(previous.begin(), previous.end());
  for (std::size_t slot = 0; slot < means.size(); ++slot) {
    const double length = glm::length(sums[slot]);
    if (weightOf[slot] > 0.0 && length > kMinClusterMeanLength * weightOf[slot]) {
      means[slot] = glm::vec3(sums[slot] / length);
    }
  }
  return means;
}

}  // namespace

std::vector<std::int32_t> nearestShadowSlots(std::span<const Light> lights,
                                             std::span<const glm::vec3> dirs) {
  std::vector<std::int32_t> slots(lights.size(), -1);
  if (dirs.empty()) return slots;
  for (std::size_t i = 0; i < lights.size(); ++i) {
    float best = -2.0F;
    for (std::size_t slot = 0; slot < dirs.size(); ++slot) {
      const float d = glm::dot(lights[i].dir, dirs[slot]);
      if (d > best) {
        best = d;
        slots[i] = std::int32_t(slot);
      }
    }
  }
  return slots;
}

ShadowGroups groupShadows(std::span<const Light> lights, std::span<const std::uint32_t> seeds,
                          ShadowGrouping grouping) {
  ShadowGroups groups;
  groups.dirs.reserve(seeds.size());
  for (std::uint32_t seed : seeds) groups.dirs.push_back(lights[seed].dir);
  groups.slots = nearestShadowSlots(lights, groups.dirs);
  // A seed is its own nearest (ties between equal directions aside): keep it in its own slot, so
  // no slot starts empty.
  for (std::size_t slot = 0; slot < seeds.size(); ++slot) {
    groups.slots[seeds[slot]] = std::int32_t(slot);
  }
  if (grouping == ShadowGrouping::NearestCaster || seeds.empty()) return groups;

  double brightest = 0.0;
  for (const Light& light : lights) brightest = std::max(brightest, luminance(light.rgb));
  std::vector<double> weights(lights.size());
  for (std::size_t i = 0; i < lights.size(); ++i) {
    weights[i] = std::max(luminance(lights[i].rgb), kBlackLightWeight * brightest);
  }
  while (groups.iterations < kMaxShadowGroupIterations) {
    ++groups.iterations;
    groups.dirs = groupMeans(lights, weights, groups.slots, groups.dirs);
    std::vector<std::int32_t> next = nearestShadowSlots(lights, groups.dirs);
    if (next == groups.slots) break;
    groups.slots = std::move(next);
  }
  // The maps are rendered from the means of the groups as they finally are.
  groups.dirs = groupMeans(lights, weights, groups.slots, groups.dirs);
  return groups;
}

}  // namespace vem::render
