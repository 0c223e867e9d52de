// FolderMaterialReader: tinyobjloader's reader of the MTL files an OBJ file names with `mtllib`,
// confined to the OBJ file's folder (scene_folder.h). tinyobjloader hands it each file name as
// written; one that resolves outside the folder is not opened, and the first refusal is kept for
// the loader to report (tinyobjloader itself only goes on without the materials). A file inside
// the folder that cannot be opened is a warning, as in tinyobjloader. Internal to obj_loader.cpp.
#pragma once

#include <tiny_obj_loader.h>

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "client/scene/scene_folder.h"

namespace vem::scene {

class FolderMaterialReader final : public tinyobj::MaterialReader {
 public:
  explicit FolderMaterialReader(SceneFolder folder);

  bool operator()(const std::string& reference, std::vector<tinyobj::material_t>* materials,
                  std::map<std::string, int>* materialMap, std::string* warning,
                  std::string* error) override;

  // The first `mtllib` refused, as the "what" part of a sentence (SceneFolder::resolve).
  [[nodiscard]] const std::optional<std::string>& refusal() const { return refusal_; }

 private:
  SceneFolder folder_;
  std::optional<std::string> refusal_;
};

}  // namespace vem::scene
