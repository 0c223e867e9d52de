#include "client/scene/gltf_folder_access.h"

#include <tiny_gltf.h>
#include <fstream>
#include <iterator>
#include <system_error>
#include <utility>

namespace vem::scene {

GltfFolderAccess::GltfFolderAccess(SceneFolder folder)
    : folder_(std::move(folder)), baseDir_(folder_.path().string()) {
  prefix_ = baseDir_.ends_with('/') ? baseDir_ : baseDir_ + "/";
}

void GltfFolderAccess::install(tinygltf::TinyGLTF& gltf) {
  gltf.SetFsCallbacks(
      tinygltf::FsCallbacks{&fileExists, &expandFilePath, &readWholeFile, &writeWholeFile, this});
}

std::optional<std::filesystem::path> GltfFolderAccess::resolve(const std::string& joined) {
  if (!joined.starts_with(prefix_)) {
    return std::nullopt;  // the "." lookup: the working directory is not the scene's folder
  }
  auto file = folder_.resolve("URI", std::string_view(joined).substr(prefix_.size()));
  if (!file) {
    if (!refusal_) {
      refusal_ = std::move(file.error());
    }
    return std::nullopt;
  }
  return std::move(*file);
}

bool GltfFolderAccess::fileExists(const std::string& joined, void* self) {
  const auto file = static_cast<GltfFolderAccess*>(self)->resolve(joined);
  std::error_code ec;
  return file && std::filesystem::is_regular_file(*file, ec);
}

std::string GltfFolderAccess::expandFilePath(const std::string& path, void* /*self*/) {
  return path;  // no `~` or variable expansion
}

bool GltfFolderAccess::readWholeFile(std::vector<unsigned char>* out, std::string* error,
                                     const std::string& joined, void* self) {
  const auto file = static_cast<GltfFolderAccess*>(self)->resolve(joined);
  std::ifstream in;
  if (file) {
    in.open(*file, std::ios::binary);
  }
  if (!in) {
    if (error != nullptr) {
      *error += "it cannot be opened";
    }
    return false;
  }
  out->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return !in.bad();
}

bool GltfFolderAccess::writeWholeFile(std::string* error, const std::string& /*path*/,
                                      const std::vector<unsigned char>& /*contents*/,
                                      void* /*self*/) {
  if (error != nullptr) {
    *error += "scene files are only read";
  }
  return false;
}

}  // namespace vem::scene
