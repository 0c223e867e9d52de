#include "client/vemview/scene_argument.h"

#include <filesystem>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "client/scene/default_scene.h"
#include "client/scene/scene_file.h"

namespace vem::view {

std::expected<scene::Scene, std::string> loadSceneArgument(const std::string& argument,
                                                           bool allowOutside) {
  std::optional<scene::Scene> builtin;
  if (argument == "default" || argument == "diffuse") {
    scene::DefaultSceneOptions options;
    options.glossy = argument == "default";
    scene::DefaultScene made = scene::defaultScene(options);
    for (const std::string& note : made.notes) {
      spdlog::warn("{}", note);
    }
    builtin = std::move(made.scene);
  } else {
    builtin = scene::builtinScene(argument);
  }
  scene::Scene loaded;
  if (builtin) {
    loaded = std::move(*builtin);
  } else {
    auto file = scene::loadSceneWithWarnings(
        argument,
        scene::OutsideFolderPolicy{allowOutside, "pass --scene-allow-outside to allow it"});
    if (!file) {
      return std::unexpected(file.error().message);
    }
    for (const std::string& warning : file->warnings) {
      spdlog::warn("{}: {}", argument, warning);
    }
    loaded = std::move(file->scene);
  }
  if (const std::string broken = scene::firstContractViolation(loaded); !broken.empty()) {
    return std::unexpected(fmt::format("{}: {}", argument, broken));
  }
  if (scene::triangleCount(loaded) == 0) {
    return std::unexpected(fmt::format("{}: the scene holds no triangle", argument));
  }
  return loaded;
}

std::string defaultMapPath() { return std::string(VEM_SHARED_DATA_DIR) + "/hdri/esplanade.exr"; }

}  // namespace vem::view
