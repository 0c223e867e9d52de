// JSON forms of light sets, as `vemtool lights` prints them (docs/lights-format.md):
//   {"frame":F,"count":N,"lights":[{"id":K,"dir":[x,y,z],"rgb":[r,g,b]},...]}
// Numbers are the lights' float values written in their shortest round-trip form.
// A clustered frame adds "clustered_from" (the lights before clustering), "radius_rad" and per
// cluster "members" (the ids of the lights it holds); its "id" is its seed light's id.
// vemd's JSON-lines sink (daemon/vemd/sinks/jsonl_light_sink.h) writes the same objects from the
// clustering each frame already has; "radius_rad" is always the radius that clustering was made
// with.
#pragma once

#include <cstdint>

#include <nlohmann/json.hpp>

#include "core/env_map.h"
#include "core/light.h"
#include "core/light_clustering.h"

namespace vem::vemd {

[[nodiscard]] nlohmann::ordered_json frameJson(const LightSet& lights, std::uint64_t frame);
[[nodiscard]] nlohmann::ordered_json clusteredFrameJson(const LightSet& lights, int clusterQ,
                                                        MapLayout layout, std::uint64_t frame);
// The same for a clustering of `lights` made elsewhere (clustering.clusterOfLight has one entry per
// light); "radius_rad" is clustering.radiusRad.
[[nodiscard]] nlohmann::ordered_json clusteredFrameJson(const LightSet& lights,
                                                        const Clustering& clustering,
                                                        std::uint64_t frame);

}  // namespace vem::vemd
