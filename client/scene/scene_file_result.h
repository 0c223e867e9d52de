// What a scene-file loader returns: the scene and the loader's warnings, or a typed failure with
// one sentence naming the file, the element at fault and what was expected (STYLE.md, Errors).
// Shared by obj_loader.h, gltf_loader.h and scene_file.h; no units involved.
#pragma once

#include <expected>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "client/scene/scene.h"

namespace vem::scene {

enum class SceneFileError {
  NotFound,           // no file at the path
  Unreadable,         // a directory, or it cannot be opened
  UnsupportedFormat,  // an extension no loader handles
  BadContents,        // the loader refused what it read
};

[[nodiscard]] const char* sceneFileErrorName(SceneFileError error);

struct SceneFileFailure {
  SceneFileError error = SceneFileError::BadContents;
  std::string message;  // one sentence, naming the file
};

struct LoadedScene {
  Scene scene;
  std::vector<std::string> warnings;  // the parser's non-fatal remarks, one per entry
};

// The material of faces a file gives none: Lambertian, albedo 0.8, named "default".
[[nodiscard]] Material defaultFileMaterial();

// NotFound or Unreadable for `path`, or nothing when it is a regular file that opens.
[[nodiscard]] std::optional<SceneFileFailure> checkReadableFile(const std::filesystem::path& path);

// The whole of `path` as bytes, or checkReadableFile's failure (Unreadable when reading fails).
[[nodiscard]] std::expected<std::string, SceneFileFailure> readSceneFile(
    const std::filesystem::path& path);

// A BadContents failure: "<path>: <what>." (`what` without the final full stop).
[[nodiscard]] SceneFileFailure badContents(const std::filesystem::path& path,
                                           std::string_view what);

// `text` split into trimmed, non-empty lines (tinyobjloader and tinygltf report several remarks
// in one string).
[[nodiscard]] std::vector<std::string> splitMessages(std::string_view text);

}  // namespace vem::scene
