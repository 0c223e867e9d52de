// Shadow groups: which shadow map each light reads when there are fewer maps (S) than lights (N)
// (paper 004 section 5.2.1; issue 20 part 2). A group is rendered into one map of the atlas, from
// one direction, and every light of the group takes its visibility from that map.
//
// - NearestCaster (the paper's "most relevant shadow map"): the S seeds keep their own directions
//   and every other light reads the map of the seed nearest to it in angle. A light far from every
//   seed then reads a shadow cast from a direction it does not come from.
// - Cluster: the lights are partitioned into S groups by luminance-weighted spherical k-means
//   started from the seeds (Lloyd's iterations: each light joins the nearest centre, each centre
//   moves to the normalised luminance-weighted mean of its members' directions), and each map is
//   rendered from its group's mean. The map then stands for the light its group carries, wherever
//   it comes from, and as N grows at fixed S the groups' means converge to those of the map's own
//   light, so the error keeps falling with N.
//   - Iterations stop when no light changes group, or after kMaxShadowGroupIterations.
//   - A group left empty, or whose members' mean is shorter than kMinClusterMeanLength of their
//     weight (members on opposite sides), keeps its previous direction.
//   - Black lights weigh kBlackLightWeight of the brightest, so they still join a group (and
//     never move its centre).
// - Deterministic: the same lights and seeds give the same groups, bit for bit.
// Directions in the world frame of core/env_map.h.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "core/light.h"

namespace vem::render {

enum class ShadowGrouping { NearestCaster, Cluster };

inline constexpr int kMaxShadowGroupIterations = 16;
inline constexpr double kBlackLightWeight = 1e-9;

struct ShadowGroups {
  std::vector<glm::vec3> dirs;      // by slot: the direction the slot's map is rendered from
  std::vector<std::int32_t> slots;  // one per light: the slot of its group's map
  int iterations = 0;               // Lloyd's iterations run (Cluster; 0 for NearestCaster)
};

// Groups `lights` around `seeds` (indices into lights, one per slot, distinct). No seeds: no
// groups (every slot -1).
[[nodiscard]] ShadowGroups groupShadows(std::span<const Light> lights,
                                        std::span<const std::uint32_t> seeds,
                                        ShadowGrouping grouping);

// For each light, the slot whose direction is nearest in angle (-1 when there is none).
[[nodiscard]] std::vector<std::int32_t> nearestShadowSlots(std::span<const Light> lights,
                                                           std::span<const glm::vec3> dirs);

}  // namespace vem::render
