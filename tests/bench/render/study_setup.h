// The render study's inputs (issue 7, "What accuracy costs in time"): the default scene seen by
// vemview's starting camera, and per environment map the 1024 Havran lights of the core (prefixes
// give every N), the sampling-ready map for the reference, and the cube map both renderers use for
// mirrors and the background.
//
// Conventions: images widthPx x heightPx (320 x 240 by default), world frame of core/env_map.h,
// radiance in the map's units. Maps are the shared HDRIs (../shared/data/hdri/NAME.exr), Sphere
// layout.
#pragma once

#include <cstdint>
#include <expected>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "client/render/cube_resolution.h"
#include "client/render/shading_lights.h"
#include "client/scene/orbit_camera.h"
#include "client/scene/scene.h"
#include "core/cube_map.h"
#include "core/env_map.h"
#include "core/light.h"

namespace vem::bench {

inline constexpr std::size_t kStudyMaxLights = 1024;

// How concentrated a map's light is.
struct MapCharacter {
  double peakToMean = 0.0;       // the largest pixel luminance over the mean (solid-angle weighted)
  double topShareOfPower = 0.0;  // share of the power in the brightest 0.1 % of the solid angle
};
[[nodiscard]] MapCharacter characterOf(const EnvMap& map);

struct StudyMap {
  std::string name;  // the file's stem ("park")
  std::filesystem::path path;
  EnvMap map;
  LightSet lights;  // kStudyMaxLights lights; the first N are the N-light set
  CubeMap cube;
  MapCharacter character;
  std::optional<std::string> damage;  // knownDamage(name)
};

// The damage ../shared/data/README.md lists for a shared HDRI ("its sun is blue only ..."), or
// nothing for a sound map. A damaged map stays in the study as a hard case, labelled, and out of
// the means over the maps.
[[nodiscard]] std::optional<std::string> knownDamage(const std::string& mapName);

// cubeFacePx: the cube map's level 0, as vemview --cube-face-px.
[[nodiscard]] std::expected<StudyMap, std::string> loadStudyMap(
    const std::filesystem::path& path, int cubeFacePx = render::kCubeFacePx);

struct StudyScene {
  scene::Scene scene;
  scene::ViewCamera camera;  // vemview's starting camera, or a plate camera
  std::string description;  // one line for the report
  std::uint64_t key = 0;    // hash of the geometry, materials and camera (the reference cache key)
};

// `scene` seen by vemview's starting camera (scene::viewingCamera), with its key and description.
[[nodiscard]] std::expected<StudyScene, std::string> studySceneOf(scene::Scene scene);

// `scene` seen by a fixed camera (a plate camera), keyed by both.
[[nodiscard]] std::expected<StudyScene, std::string> studySceneSeenBy(
    scene::Scene scene, const scene::ViewCamera& camera);

// The glossy default scene (client/scene/default_scene.h) and vemview's starting camera.
[[nodiscard]] std::expected<StudyScene, std::string> studyScene();

// The frame's lights for `options` (glossyPass and clusterLayout set from the scene and the map).
[[nodiscard]] render::ShadingLights studyLights(const StudyMap& map, const StudyScene& scene,
                                                const render::LightingGeometry& geometry,
                                                render::LightingOptions options);

}  // namespace vem::bench
