// Light clustering: merges lights with similar directions to cut the shadow-map count
// (paper 004 section 4.3).
//
// - Greedy, in index order: the first unassigned light is a seed; every unassigned light within the
//   angular radius e of the seed (angle <= e, i.e. seed . dir >= cos e, in double) joins its
//   cluster. Neighbours come from a kd-tree (nanoflann) over the unit directions, searched by chord
//   length, so the cost is O(N log N) plus the members found, never O(N^2): seeds lie more than e
//   apart, so each light is found by a bounded number of seeds.
// - e = cf asin(sqrt(Omega / (pi Q))) where Omega is the solid angle the map covers (2 pi for the
//   hemisphere, the paper's e = cf asin(sqrt(2 / Q)); 4 pi for the sphere), so Q means "about Q
//   clusters over the map" (each a disc of solid angle ~ pi sin^2 e). When the asin argument
//   reaches 1 (Q <= Omega / pi: one disc must already cover the whole map) e is pi and every light
//   joins the first cluster, so Q = 1 always gives one cluster; otherwise e is clamped to pi.
// - Output, in seed order: id = the seed's id; rgb = sum of the members' rgb (summed in double);
//   dir = the normalised mean of the members' unit directions, or the seed's direction when that
//   mean is shorter than kMinClusterMeanLength (members spread over opposite directions);
//   luminanceSr and black are copied unchanged. clusterOfLight[k] is the index (in the output) of
//   the cluster input light k joined.
// - Directions in the world frame of env_map.h (right-handed, +Y up); angles in radians; rgb in the
//   irradiance units of light.h.
#pragma once

#include <cstdint>
#include <vector>

#include "core/env_map.h"
#include "core/light.h"

namespace vem {

inline constexpr double kDefaultClusterCorrectionFactor = 1.85;  // cf, paper: 1.8 - 1.9
inline constexpr double kMinClusterMeanLength = 1e-6;

struct ClusteringParams {
  int clusterBudget = 72;  // Q >= 1: about Q clusters over the covered solid angle
  double correctionFactor = kDefaultClusterCorrectionFactor;
  MapLayout layout = MapLayout::Hemisphere;  // sets the covered solid angle Omega
};

struct Clustering {
  LightSet clusters;
  std::vector<std::uint32_t> clusterOfLight;  // one entry per input light
  double radiusRad = 0.0;  // the radius e the clusters were made with, in [0, pi]
};

// The angular radius e of the clusters, in [0, pi].
[[nodiscard]] double clusterRadiusRad(const ClusteringParams& params);

[[nodiscard]] Clustering clusterLights(const LightSet& lights, const ClusteringParams& params);
// The same greedy clustering with an explicit radius e in [0, pi].
[[nodiscard]] Clustering clusterLightsWithinRadius(const LightSet& lights, double radiusRad);

}  // namespace vem
