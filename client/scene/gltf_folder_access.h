// GltfFolderAccess: tinygltf's file callbacks (FsCallbacks) confined to a SceneFolder, so that a
// glTF or GLB file's buffer and image URIs are read from the scene's folder only
// (scene_folder.h). tinygltf joins each URI (percent-decoded) to the base folder it is given and
// asks whether that file exists, then tries the URI in "." (the working directory); here the base
// folder is SceneFolder::path(), the URI is taken back from the joined path and resolved by the
// folder, "." is never searched, a file "exists" only when it is a regular file, and nothing is
// opened before its URI resolved inside the folder. The first refusal is kept for the loader to
// report. data: URIs never come here (tinygltf decodes them from the file itself). Internal to
// gltf_loader.cpp.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "client/scene/scene_folder.h"

namespace tinygltf {
class TinyGLTF;
}

namespace vem::scene {

class GltfFolderAccess {
 public:
  explicit GltfFolderAccess(SceneFolder folder);
  GltfFolderAccess(const GltfFolderAccess&) = delete;  // tinygltf keeps a pointer to it
  GltfFolderAccess& operator=(const GltfFolderAccess&) = delete;

  // Sets `gltf`'s file callbacks to this object's; it must outlive the loading.
  void install(tinygltf::TinyGLTF& gltf);
  // The base folder to pass to tinygltf's Load*FromString / Load*FromMemory.
  [[nodiscard]] const std::string& baseDir() const { return baseDir_; }
  // The first URI refused, as the "what" part of a sentence (SceneFolder::resolve).
  [[nodiscard]] const std::optional<std::string>& refusal() const { return refusal_; }

 private:
  static bool fileExists(const std::string& joined, void* self);
  static std::string expandFilePath(const std::string& path, void* self);
  static bool readWholeFile(std::vector<unsigned char>* out, std::string* error,
                            const std::string& joined, void* self);
  static bool writeWholeFile(std::string* error, const std::string& path,
                             const std::vector<unsigned char>& contents, void* self);
  // The file a joined path names, when it is a URI joined to baseDir_ that resolves inside the
  // folder (else the refusal is kept); nothing for "." lookups and refusals.
  std::optional<std::filesystem::path> resolve(const std::string& joined);

  SceneFolder folder_;
  std::string baseDir_;
  std::string prefix_;  // baseDir_ and the separator tinygltf joins with
  std::optional<std::string> refusal_;
};

}  // namespace vem::scene
