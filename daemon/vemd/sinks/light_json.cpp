#include "vemd/sinks/light_json.h"

#include <cstdlib>
#include <string>
#include <vector>

#include <fmt/format.h>

namespace vem::vemd {
namespace {

// A float as the double with the same shortest decimal form, so JSON shows 0.3, not 0.30000001.
double shortest(float value) { return std::strtod(fmt::format("{}", value).c_str(), nullptr); }

nlohmann::ordered_json lightJson(const Light& light) {
  return {{"id", light.id},
          {"dir", {shortest(light.dir.x), shortest(light.dir.y), shortest(light.dir.z)}},
          {"rgb", {shortest(light.rgb.x), shortest(light.rgb.y), shortest(light.rgb.z)}}};
}

}  // namespace

nlohmann::ordered_json frameJson(const LightSet& lights, std::uint64_t frame) {
  nlohmann::ordered_json array = nlohmann::ordered_json::array();
  for (const Light& light : lights.lights) array.push_back(lightJson(light));
  return {{"frame", frame}, {"count", lights.lights.size()}, {"lights", std::move(array)}};
}

nlohmann::ordered_json clusteredFrameJson(const LightSet& lights, int clusterQ, MapLayout layout,
                                          std::uint64_t frame) {
  ClusteringParams params;
  params.clusterBudget = clusterQ;
  params.layout = layout;
  return clusteredFrameJson(lights, clusterLights(lights, params), frame);
}

nlohmann::ordered_json clusteredFrameJson(const LightSet& lights, const Clustering& clustering,
                                          std::uint64_t frame) {
  nlohmann::ordered_json out = frameJson(clustering.clusters, frame);
  std::vector<nlohmann::ordered_json> members(clustering.clusters.lights.size(),
                                              nlohmann::ordered_json::array());
  for (std::size_t i = 0; i < lights.lights.size(); ++i) {
    members[clustering.clusterOfLight[i]].push_back(lights.lights[i].id);
  }
  for (std::size_t c = 0; c < members.size(); ++c) out["lights"][c]["members"] = members[c];
  out["clustered_from"] = lights.lights.size();
  out["radius_rad"] = clustering.radiusRad;
  return out;
}

}  // namespace vem::vemd
