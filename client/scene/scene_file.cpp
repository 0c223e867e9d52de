#include "client/scene/scene_file.h"

#include <fmt/format.h>
#include <algorithm>
#include <cctype>
#include <exception>
#include <string>

#include "client/scene/gltf_loader.h"
#include "client/scene/obj_loader.h"

namespace vem::scene {
namespace {

std::string lowerExtension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::ranges::transform(extension, extension.begin(),
                         [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

std::expected<LoadedScene, SceneFileFailure> dispatch(const std::filesystem::path& path,
                                                      const OutsideFolderPolicy& outside) {
  const std::string extension = lowerExtension(path);
  if (extension == ".obj") {
    return loadObj(path, outside);
  }
  if (extension == ".gltf" || extension == ".glb") {
    return loadGltf(path, outside);
  }
  return std::unexpected(SceneFileFailure{
      SceneFileError::UnsupportedFormat,
      fmt::format("scene file {} has the extension '{}', where .obj, .gltf or .glb was expected.",
                  path.string(), extension)});
}

}  // namespace

std::expected<LoadedScene, SceneFileFailure> loadSceneWithWarnings(
    const std::filesystem::path& path, const OutsideFolderPolicy& outside) {
  try {
    return dispatch(path, outside);
  } catch (const std::exception& e) {  // std::bad_alloc, or a throw inside a parser
    return std::unexpected(SceneFileFailure{
        SceneFileError::BadContents,
        fmt::format("scene file {} could not be loaded ({}).", path.string(), e.what())});
  }
}

std::expected<Scene, SceneFileFailure> loadScene(const std::filesystem::path& path,
                                                 const OutsideFolderPolicy& outside) {
  auto loaded = loadSceneWithWarnings(path, outside);
  if (!loaded) {
    return std::unexpected(std::move(loaded.error()));
  }
  return std::move(loaded->scene);
}

}  // namespace vem::scene
