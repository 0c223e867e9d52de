// The built-in scenes, so vemview runs with no scene file.
//
// "default": the Stanford bunny of VEM_SHARED_DATA_DIR/models/bunny.obj (loaded with
// obj_loader.h), rescaled to a height of 1 scene unit (metres), standing on y = 0 and centred on
// the origin in x and z, on a 6 x 6 ground plane (y = 0, facing +Y), with a sphere (radius 0.35)
// to its right (+X) and a 0.6 box to its left (-X). World frame of scene/scene.h (+Y up).
// Materials (scene/scene.h's model), material index in brackets:
//   [0] bunny   Lambertian, albedo 0.75
//   [1] ground  Lambertian, albedo 0.5
//   [2] sphere  glossy: gold-like metal: GGX, roughness 0.3, F0 = (0.9, 0.7, 0.35), no diffuse
//               (a metal's colour is all in its specular lobe); else Lambertian (0.8, 0.6, 0.3)
//   [3] box     glossy: Blinn, exponent 40, specular albedo 0.25, diffuse (0.25, 0.35, 0.6);
//               else Lambertian (0.25, 0.35, 0.6)
// When the bunny cannot be loaded, a sphere of radius 0.5 stands in its place and a note says
// why. Neither material is mirror-like (scene.h's kMirrorRoughness / kMirrorExponent).
//
// builtinScene(name) knows:
//   "default"  the scene above, glossy
//   "diffuse"  the scene above, every material Lambertian (anyGlossy() false)
//   "spheres"  one Lambertian sphere (radius 0.5, albedo 0.8) resting on a 4 x 4 plane (albedo 0.5)
//   "mixed-reality"  the simulated real world's synthetic objects (mixed_reality_world.h): two
//              spheres standing on y = 0, no ground (vemview --plate's default)
//   "sphere"   one lone Lambertian sphere (radius 1 at the origin): convex, so it can shadow
//              nothing (canCastShadows() false)
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "client/scene/scene.h"

namespace vem::scene {

// VEM_SHARED_DATA_DIR/models/bunny.obj, as configured at build time.
[[nodiscard]] std::filesystem::path defaultBunnyPath();

struct DefaultSceneOptions {
  bool glossy = true;  // false: the all-Lambertian variant
  std::filesystem::path bunnyPath = defaultBunnyPath();
};

struct DefaultScene {
  Scene scene;
  std::vector<std::string> notes;  // what was substituted and why (a missing bunny), for the log
};

[[nodiscard]] DefaultScene defaultScene(const DefaultSceneOptions& options = {});

inline constexpr std::array<std::string_view, 4> kBuiltinSceneNames{"default", "diffuse", "spheres",
                                                                    "sphere"};

// The built-in scene of that name, or nothing for an unknown name. ("default" and "diffuse" drop
// defaultScene()'s notes: call it directly to report them.)
[[nodiscard]] std::optional<Scene> builtinScene(std::string_view name);

}  // namespace vem::scene
