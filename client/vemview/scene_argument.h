// What vemview's --scene and its default input name: a built-in scene
// (client/scene/default_scene.h) or a scene file (client/scene/scene_file.h), checked against the
// scene contract; and the map the viewer uses when no input is given (a real HDRI of the shared
// data, compiled in as VEM_SHARED_DATA_DIR). A scene file's references (mtllib, glTF URIs) must lie
// in its folder unless `allowOutside` (--scene-allow-outside; client/scene/scene_folder.h).
#pragma once

#include <expected>
#include <string>

#include "client/scene/scene.h"

namespace vem::view {

[[nodiscard]] std::expected<scene::Scene, std::string> loadSceneArgument(
    const std::string& argument, bool allowOutside = false);
[[nodiscard]] std::string defaultMapPath();

}  // namespace vem::view
