#include "frames/published_lights.h"

#include <algorithm>

namespace vem {
namespace {

// One cluster index per light, each naming an existing cluster.
bool clustersSet(const Clustering& clustering, const LightSet& lights) {
  const std::size_t clusters = clustering.clusters.lights.size();
  return clustering.clusterOfLight.size() == lights.lights.size() &&
         std::ranges::all_of(clustering.clusterOfLight,
                             [clusters](std::uint32_t c) { return c < clusters; });
}

}  // namespace

PublishedLights publishedLights(const ProcessedFrame& frame) {
  PublishedLights out;
  if (frame.filtered) {
    out.lights = &*frame.filtered;
    out.filtered = true;
    out.lightsSeq = frame.filteredSeq;
  } else {
    out.lights = &frame.lights;
    out.lightsSeq = frame.captured->seq;
  }
  if (frame.clustering && clustersSet(*frame.clustering, *out.lights)) {
    out.clustering = &*frame.clustering;
  }
  return out;
}

}  // namespace vem
