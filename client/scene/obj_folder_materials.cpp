#include "client/scene/obj_folder_materials.h"

#include <fmt/format.h>
#include <fstream>
#include <utility>

namespace vem::scene {

FolderMaterialReader::FolderMaterialReader(SceneFolder folder) : folder_(std::move(folder)) {}

bool FolderMaterialReader::operator()(const std::string& reference,
                                      std::vector<tinyobj::material_t>* materials,
                                      std::map<std::string, int>* materialMap, std::string* warning,
                                      std::string* error) {
  auto file = folder_.resolve("mtllib", reference);
  if (!file) {
    if (!refusal_) {
      refusal_ = std::move(file.error());
    }
    return false;
  }
  std::ifstream in(*file);
  if (!in) {
    *warning +=
        fmt::format("material file '{}' not found in {}\n", reference, folder_.path().string());
    return false;
  }
  tinyobj::LoadMtl(materialMap, materials, &in, warning, error);
  return true;
}

}  // namespace vem::scene
