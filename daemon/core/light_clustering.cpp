#include "core/light_clustering.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>
#include <utility>

#include "core/direction_tree.h"
#include "util/contract.h"

namespace vem {
namespace {

inline constexpr std::uint32_t kUnassigned = std::numeric_limits<std::uint32_t>::max();
// Slack on the squared chord of the kd-tree search; the exact test on the dot product follows.
inline constexpr double kChordSquaredSlack = 1e-9;

struct ClusterSum {
  std::uint32_t seed = 0;
  std::size_t memberCount = 0;
  glm::dvec3 dirSum{0.0};
  glm::dvec3 rgbSum{0.0};
};

std::vector<glm::dvec3> unitDirections(const LightSet& lights) {
  std::vector<glm::dvec3> dirs;
  dirs.reserve(lights.lights.size());
  for (const Light& light : lights.lights) dirs.push_back(glm::normalize(glm::dvec3(light.dir)));
  return dirs;
}

void addMember(ClusterSum& cluster, glm::dvec3 dir, glm::vec3 rgb) {
  ++cluster.memberCount;
  cluster.dirSum += dir;
  cluster.rgbSum += glm::dvec3(rgb);
}

Light representative(const ClusterSum& cluster, const LightSet& lights,
                     const std::vector<glm::dvec3>& dirs) {
  const glm::dvec3 mean = cluster.dirSum / double(cluster.memberCount);
  const double length = glm::length(mean);
  const glm::dvec3 dir = length >= kMinClusterMeanLength ? mean / length : dirs[cluster.seed];
  return {lights.lights[cluster.seed].id, glm::vec3(dir), glm::vec3(cluster.rgbSum)};
}

LightSet representatives(const std::vector<ClusterSum>& sums, const LightSet& lights,
                         const std::vector<glm::dvec3>& dirs) {
  LightSet clusters;
  clusters.luminanceSr = lights.luminanceSr;
  clusters.black = lights.black;
  clusters.lights.reserve(sums.size());
  for (const ClusterSum& sum : sums) clusters.lights.push_back(representative(sum, lights, dirs));
  return clusters;
}

// One greedy pass over the lights in index order; the state its seeds share.
class GreedyClustering {
 public:
  GreedyClustering(const LightSet& lights, double radiusRad)
      : lights_(lights),
        dirs_(unitDirections(lights)),
        cloud_{dirs_},
        tree_(3, cloud_, nanoflann::KDTreeSingleIndexAdaptorParams(16)),
        // e = pi takes every light, exact antipodes included (their dot may round below -1).
        minDot_(radiusRad >= std::numbers::pi ? -2.0 : std::cos(radiusRad)),
        // nanoflann 1.4.3 takes the squared radius for L2 metrics; chord^2 = 2 - 2 cos(angle).
        chordSquared_(2.0 - 2.0 * minDot_ + kChordSquaredSlack),
        owner_(dirs_.size(), kUnassigned) {}

  Clustering run() {
    for (std::uint32_t seed = 0; seed < dirs_.size(); ++seed) {
      if (owner_[seed] == kUnassigned) grow(seed);
    }
    return {representatives(sums_, lights_, dirs_), std::move(owner_)};
  }

 private:
  void grow(std::uint32_t seed) {
    sums_.push_back({seed, 0, glm::dvec3(0.0), glm::dvec3(0.0)});
    assign(seed);  // the seed joins first, even when e = 0 and rounding would say otherwise
    tree_.radiusSearch(&dirs_[seed].x, chordSquared_, found_,
                       nanoflann::SearchParams(32, 0.0F, false));
    for (const auto& hit : found_) {
      const std::uint32_t index = hit.first;
      if (owner_[index] == kUnassigned && glm::dot(dirs_[seed], dirs_[index]) >= minDot_) {
        assign(index);
      }
    }
  }

  void assign(std::uint32_t index) {
    owner_[index] = std::uint32_t(sums_.size() - 1);
    addMember(sums_.back(), dirs_[index], lights_.lights[index].rgb);
  }

  const LightSet& lights_;
  const std::vector<glm::dvec3> dirs_;
  const DirectionCloud cloud_;
  const DirectionTree tree_;
  const double minDot_;
  const double chordSquared_;
  std::vector<std::uint32_t> owner_;
  std::vector<ClusterSum> sums_;
  std::vector<std::pair<std::uint32_t, double>> found_;
};

}  // namespace

double clusterRadiusRad(const ClusteringParams& params) {
  VEM_EXPECTS(params.clusterBudget >= 1 && params.correctionFactor > 0.0);
  const double share =
      coveredSolidAngleSr(params.layout) / (std::numbers::pi * params.clusterBudget);
  // share >= 1: one disc already has to cover the whole map, so one cluster takes every light.
  if (share >= 1.0) return std::numbers::pi;
  return std::min(params.correctionFactor * std::asin(std::sqrt(share)), std::numbers::pi);
}

Clustering clusterLights(const LightSet& lights, const ClusteringParams& params) {
  return clusterLightsWithinRadius(lights, clusterRadiusRad(params));
}

Clustering clusterLightsWithinRadius(const LightSet& lights, double radiusRad) {
  VEM_EXPECTS(radiusRad >= 0.0 && radiusRad <= std::numbers::pi);
  Clustering out = GreedyClustering(lights, radiusRad).run();
  out.radiusRad = radiusRad;
  return out;
}

}  // namespace vem
