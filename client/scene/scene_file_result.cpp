#include "client/scene/scene_file_result.h"

#include <fmt/format.h>
#include <fstream>
#include <iterator>
#include <system_error>

namespace vem::scene {

const char* sceneFileErrorName(SceneFileError error) {
  switch (error) {
    case SceneFileError::NotFound: return "not found";
    case SceneFileError::Unreadable: return "unreadable";
    case SceneFileError::UnsupportedFormat: return "unsupported format";
    case SceneFileError::BadContents: return "bad contents";
  }
  return "?";
}

Material defaultFileMaterial() {
  Material material;
  material.name = "default";
  material.diffuseAlbedo = glm::vec3(0.8F);
  return material;
}

std::optional<SceneFileFailure> checkReadableFile(const std::filesystem::path& path) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status)) {
    return SceneFileFailure{SceneFileError::NotFound,
                            fmt::format("scene file {} does not exist.", path.string())};
  }
  if (!std::filesystem::is_regular_file(status)) {
    return SceneFileFailure{SceneFileError::Unreadable,
                            fmt::format("scene file {} is not a regular file.", path.string())};
  }
  if (!std::ifstream(path, std::ios::binary).is_open()) {
    return SceneFileFailure{
        SceneFileError::Unreadable,
        fmt::format("scene file {} cannot be opened for reading.", path.string())};
  }
  return std::nullopt;
}

std::expected<std::string, SceneFileFailure> readSceneFile(const std::filesystem::path& path) {
  if (auto failure = checkReadableFile(path)) {
    return std::unexpected(*failure);
  }
  std::ifstream in(path, std::ios::binary);
  std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) {
    return std::unexpected(
        SceneFileFailure{SceneFileError::Unreadable,
                         fmt::format("scene file {} could not be read.", path.string())});
  }
  return bytes;
}

SceneFileFailure badContents(const std::filesystem::path& path, std::string_view what) {
  return {SceneFileError::BadContents, fmt::format("{}: {}.", path.string(), what)};
}

std::vector<std::string> splitMessages(std::string_view text) {
  std::vector<std::string> lines;
  while (!text.empty()) {
    const auto end = text.find('\n');
    std::string_view line = text.substr(0, end);
    text = end == std::string_view::npos ? std::string_view{} : text.substr(end + 1);
    const auto first = line.find_first_not_of(" \t\r.");
    const auto last = line.find_last_not_of(" \t\r");
    if (first != std::string_view::npos) {
      lines.emplace_back(line.substr(first, last - first + 1));
    }
  }
  return lines;
}

}  // namespace vem::scene
