// Scenes by name, as `vemtool synth --scene` and vemd's `synthetic:SCENE` source spell them:
//   sky            sky_scene.h          clouds         cloud_scene.h
//   hdri:FILE      hdri_scene.h         fluorescent    fluorescent_scene.h
//   exposure-jump  exposure_jump_scene.h
// each with its documented defaults (docs/synthetic-scenes.md). The library reads no files: for
// hdri:FILE the caller loads FILE (hdriFileOf tells which) and passes the map in SceneOptions.
#pragma once

#include <cstdint>
#include <expected>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "core/env_map.h"
#include "synth/synthetic_scene.h"

namespace vem::synth {

// The names, for help texts and messages.
inline constexpr std::string_view kSceneNames =
    "sky, clouds, hdri:FILE, fluorescent, exposure-jump";

struct SceneOptions {
  std::shared_ptr<const EnvMap> hdri;  // hdri:FILE: the loaded map (required for that scene)
  double hdriScale = 1.0;              // hdri:FILE: the map's values times this are cd/m^2
  double hdriPanDegPerS = 10.0;        // hdri:FILE: how fast it turns
  std::uint64_t seed = 1;              // clouds: the noise field
};

// The rate in frames per second a scene was designed to be captured at, used when no rate is
// given (`vemtool synth` without --rate). It is 30 for every scene today, the rate vemd's synthetic
// source runs at: the sky's sun moves 1/30 degree per frame, the clouds 1/120 layer height, the
// hdri pans 1/3 degree, the exposure jump falls between frames 29 and 30, and the fluorescent
// room's 100 Hz ripple aliases to 10 Hz, a period of exactly 3 frames (at another rate the flicker
// the lights show is another one; fluorescent_scene.h). nullopt for a spec naming no scene.
[[nodiscard]] std::optional<double> naturalRateHz(std::string_view spec);

// FILE for a spec "hdri:FILE", else nullopt (also for "hdri:" with no file).
[[nodiscard]] std::optional<std::string_view> hdriFileOf(std::string_view spec);

// The scene `spec` names, or one sentence saying why there is none.
[[nodiscard]] std::expected<std::unique_ptr<SyntheticScene>, std::string> makeScene(
    std::string_view spec, const SceneOptions& options);

}  // namespace vem::synth
