// Loading a scene file by its extension: .obj (obj_loader.h), .gltf and .glb (gltf_loader.h),
// matched case-insensitively; any other extension is refused as UnsupportedFormat. Frames, units
// and material mappings are those of the loaders' headers. Errors are values (SceneFileFailure,
// scene_file_result.h): nothing here throws.
#pragma once

#include <expected>
#include <filesystem>

#include "client/scene/scene.h"
#include "client/scene/scene_file_result.h"
#include "client/scene/scene_folder.h"

namespace vem::scene {

// The scene and the loader's warnings. Files the scene references must lie in its folder unless
// `outside` allows them (scene_folder.h).
[[nodiscard]] std::expected<LoadedScene, SceneFileFailure> loadSceneWithWarnings(
    const std::filesystem::path& path, const OutsideFolderPolicy& outside = {});

// The scene alone (warnings dropped).
[[nodiscard]] std::expected<Scene, SceneFileFailure> loadScene(
    const std::filesystem::path& path, const OutsideFolderPolicy& outside = {});

}  // namespace vem::scene
