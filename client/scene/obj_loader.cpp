#include "client/scene/obj_loader.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <tiny_obj_loader.h>
#include <algorithm>
#include <cstdint>
#include <glm/glm.hpp>
#include <iterator>
#include <spanstream>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>

#include "client/scene/mesh_normals.h"
#include "client/scene/obj_folder_materials.h"
#include "client/scene/obj_text_check.h"
#include "client/scene/scene_folder.h"
#include "util/printable.h"

namespace vem::scene {
namespace {

namespace fs = std::filesystem;
using Warnings = std::vector<std::string>;
using util::printable;

// What tinyobjloader read.
struct ParsedObj {
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
};

constexpr float kMinRoughness = 0.01F;
constexpr float kDielectricF0 = 0.04F;

glm::vec3 vec3At(const std::vector<tinyobj::real_t>& values, std::size_t index) {
  return {static_cast<float>(values[3 * index]), static_cast<float>(values[3 * index + 1]),
          static_cast<float>(values[3 * index + 2])};
}

glm::vec3 vec3Of(const tinyobj::real_t* v) {
  return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
}

float maxComponent(glm::vec3 v) { return std::max({v.x, v.y, v.z}); }

glm::vec3 clampedColour(glm::vec3 colour, const char* field, const std::string& material,
                        Warnings& warnings) {
  const glm::vec3 clamped = glm::clamp(colour, 0.0F, 1.0F);
  if (clamped != colour) {
    warnings.push_back(
        fmt::format("material '{}': {} clamped to [0, 1]", printable(material), field));
  }
  return clamped;
}

// The lobe a material with Ks > 0 and no Pr asks for: MTL's own highlight is Blinn-Phong; the
// vemcast key `vem_lobe phong` asks for the normalised Phong lobe instead.
std::expected<Lobe, std::string> highlightLobe(const tinyobj::material_t& mtl) {
  const auto key = mtl.unknown_parameter.find("vem_lobe");
  if (key == mtl.unknown_parameter.end()) return Lobe::Blinn;
  std::string_view value = key->second;
  const std::size_t first = value.find_first_not_of(" \t\r");
  value = first == std::string_view::npos ? "" : value.substr(first);
  value = value.substr(0, value.find_last_not_of(" \t\r") + 1);
  if (value == "blinn") return Lobe::Blinn;
  if (value == "phong") return Lobe::Phong;
  return std::unexpected(
      fmt::format("material '{}' has vem_lobe '{}', where phong or blinn was "
                  "expected",
                  printable(mtl.name), printable(value)));
}

std::expected<Material, std::string> fromMtl(const tinyobj::material_t& mtl, Warnings& warnings) {
  Material m;
  m.name = mtl.name;
  const glm::vec3 kd = clampedColour(vec3Of(mtl.diffuse), "Kd", mtl.name, warnings);
  const glm::vec3 ks = clampedColour(vec3Of(mtl.specular), "Ks", mtl.name, warnings);
  const bool namesLobe = mtl.unknown_parameter.contains("vem_lobe");
  m.diffuseAlbedo = kd;
  if (mtl.roughness > 0) {
    if (namesLobe) {
      return std::unexpected(
          fmt::format("material '{}' has both Pr (a GGX lobe) and vem_lobe, "
                      "where one of them was expected",
                      printable(mtl.name)));
    }
    const float metallic = std::clamp(static_cast<float>(mtl.metallic), 0.0F, 1.0F);
    m.lobe = Lobe::Ggx;
    m.roughness = std::clamp(static_cast<float>(mtl.roughness), kMinRoughness, 1.0F);
    m.specularAlbedo =
        maxComponent(ks) > 0.0F ? ks : glm::mix(glm::vec3(kDielectricF0), kd, metallic);
    m.diffuseAlbedo = kd * (1.0F - metallic);
  } else if (maxComponent(ks) > 0.0F) {
    const auto lobe = highlightLobe(mtl);
    if (!lobe) return std::unexpected(lobe.error());
    m.lobe = *lobe;
    m.specularAlbedo = ks;
    m.exponent = std::max(static_cast<float>(mtl.shininess), 0.0F);
  } else if (namesLobe) {
    warnings.push_back(fmt::format("material '{}': vem_lobe is ignored without Ks > 0 (Lambertian)",
                                   printable(mtl.name)));
  }
  return m;
}

bool outOfRange(int index, std::size_t count) {
  return index < 0 || static_cast<std::size_t>(index) >= count;
}

// The first face that is not a triangle or refers to a missing vertex or normal.
std::optional<SceneFileFailure> checkFaces(const ParsedObj& obj, const fs::path& path) {
  const std::size_t positions = obj.attrib.vertices.size() / 3;
  const std::size_t normals = obj.attrib.normals.size() / 3;
  for (const tinyobj::shape_t& shape : obj.shapes) {
    const auto& counts = shape.mesh.num_face_vertices;
    if (const auto bad = std::ranges::find_if(counts, [](unsigned char n) { return n != 3; });
        bad != counts.end()) {
      return badContents(path, fmt::format("face {} of shape '{}' has {} vertices and could not be "
                                           "triangulated",
                                           bad - counts.begin() + 1, printable(shape.name), *bad));
    }
    for (std::size_t i = 0; i < shape.mesh.indices.size(); ++i) {
      const tinyobj::index_t& corner = shape.mesh.indices[i];
      const auto where = fmt::format("triangle {} of shape '{}'", i / 3 + 1, printable(shape.name));
      if (outOfRange(corner.vertex_index, positions)) {
        return badContents(path, fmt::format("{} refers to vertex {}, but the file has {} vertices",
                                             where, corner.vertex_index + 1, positions));
      }
      if (corner.normal_index != -1 && outOfRange(corner.normal_index, normals)) {
        return badContents(path, fmt::format("{} refers to normal {}, but the file has {} normals",
                                             where, corner.normal_index + 1, normals));
      }
    }
  }
  return std::nullopt;
}

// tinyobjloader reports some broken faces only as warnings, after dropping them.
std::optional<SceneFileFailure> fatalWarning(const Warnings& warnings, const fs::path& path) {
  for (const std::string& warning : warnings) {
    if (warning.find("Degenerated face") != std::string::npos) {
      return badContents(path, "a face has fewer than three vertices and cannot be triangulated");
    }
    if (warning.find("invalid vertex index") != std::string::npos ||
        warning.find("indices out of bounds") != std::string::npos) {
      return badContents(path, fmt::format("a face index is out of range (tinyobjloader: \"{}\")",
                                           printable(warning)));
    }
  }
  return std::nullopt;
}

// Gathers one (shape, material) pair's triangles into a Mesh with deduplicated vertices.
class MeshBuilder {
 public:
  MeshBuilder(const tinyobj::attrib_t& attrib, const fs::path& path)
      : attrib_(attrib), path_(path) {}

  std::expected<Mesh, SceneFileFailure> build(const tinyobj::shape_t& shape,
                                              const std::vector<std::uint32_t>& faceMaterials,
                                              std::uint32_t material, Warnings& warnings) {
    mesh_ = Mesh{};
    mesh_.material = material;
    vertexOf_.clear();
    firstSourceVertex_.clear();
    const bool fileNormals = allCornersHaveNormals(shape, faceMaterials, material, warnings);
    for (std::size_t f = 0; f < faceMaterials.size(); ++f) {
      if (faceMaterials[f] != material) {
        continue;
      }
      for (std::size_t k = 0; k < 3; ++k) {
        if (auto failure = addCorner(shape.mesh.indices[3 * f + k], fileNormals)) {
          return std::unexpected(*failure);
        }
      }
    }
    if (!fileNormals) {
      if (auto failure = computeNormals(shape)) {
        return std::unexpected(*failure);
      }
    }
    return std::move(mesh_);
  }

 private:
  bool allCornersHaveNormals(const tinyobj::shape_t& shape,
                             const std::vector<std::uint32_t>& faceMaterials,
                             std::uint32_t material, Warnings& warnings) const {
    std::size_t with = 0;
    std::size_t without = 0;
    for (std::size_t f = 0; f < faceMaterials.size(); ++f) {
      for (std::size_t k = 0; faceMaterials[f] == material && k < 3; ++k) {
        ++(shape.mesh.indices[3 * f + k].normal_index >= 0 ? with : without);
      }
    }
    if (with > 0 && without > 0) {
      warnings.push_back(
          fmt::format("shape '{}': {} of {} face corners have no normal; smooth "
                      "normals computed for all",
                      printable(shape.name), without, with + without));
    }
    return without == 0;
  }

  std::optional<SceneFileFailure> addCorner(const tinyobj::index_t& corner, bool fileNormals) {
    const int normalIndex = fileNormals ? corner.normal_index : -1;
    const std::uint64_t key =
        (std::uint64_t{static_cast<std::uint32_t>(corner.vertex_index)} << 32U) |
        static_cast<std::uint32_t>(normalIndex);
    const auto [it, inserted] =
        vertexOf_.try_emplace(key, static_cast<std::uint32_t>(mesh_.positions.size()));
    mesh_.indices.push_back(it->second);
    if (!inserted) {
      return std::nullopt;
    }
    mesh_.positions.push_back(
        vec3At(attrib_.vertices, static_cast<std::size_t>(corner.vertex_index)));
    firstSourceVertex_.push_back(corner.vertex_index);
    if (!fileNormals) {
      return std::nullopt;
    }
    const glm::vec3 normal = vec3At(attrib_.normals, static_cast<std::size_t>(normalIndex));
    if (!(glm::length(normal) > 0.0F)) {
      return badContents(path_, fmt::format("normal {} has zero length", normalIndex + 1));
    }
    mesh_.normals.push_back(glm::normalize(normal));
    return std::nullopt;
  }

  std::optional<SceneFileFailure> computeNormals(const tinyobj::shape_t& shape) {
    auto normals = smoothNormals(mesh_.positions, mesh_.indices);
    if (!normals) {
      return badContents(
          path_, fmt::format("vertex {} of shape '{}' lies only on zero-area "
                             "triangles, so its normal is undefined",
                             firstSourceVertex_[normals.error()] + 1, printable(shape.name)));
    }
    mesh_.normals = std::move(*normals);
    return std::nullopt;
  }

  const tinyobj::attrib_t& attrib_;
  const fs::path& path_;
  Mesh mesh_;
  std::unordered_map<std::uint64_t, std::uint32_t> vertexOf_;
  std::vector<int> firstSourceVertex_;  // per mesh vertex: its OBJ position index
};

// Each face's scene material: its MTL material, or the default one appended after them.
std::vector<std::uint32_t> faceMaterials(const tinyobj::shape_t& shape, std::size_t mtlCount) {
  std::vector<std::uint32_t> out;
  out.reserve(shape.mesh.material_ids.size());
  for (const int id : shape.mesh.material_ids) {
    out.push_back(static_cast<std::uint32_t>(
        outOfRange(id, mtlCount) ? mtlCount : static_cast<std::size_t>(id)));
  }
  return out;
}

std::optional<SceneFileFailure> addShape(const tinyobj::shape_t& shape, MeshBuilder& builder,
                                         Scene& scene, std::size_t mtlCount, Warnings& warnings) {
  const auto materials = faceMaterials(shape, mtlCount);
  std::vector<std::uint32_t> distinct;
  for (const std::uint32_t m : materials) {
    if (std::ranges::find(distinct, m) == distinct.end()) {
      distinct.push_back(m);
    }
  }
  for (const std::uint32_t m : distinct) {
    auto mesh = builder.build(shape, materials, m, warnings);
    if (!mesh) {
      return mesh.error();
    }
    if (m == mtlCount && scene.materials.size() == mtlCount) {
      scene.materials.push_back(defaultFileMaterial());
    }
    mesh->name = distinct.size() > 1 ? shape.name + "/" + scene.materials[m].name : shape.name;
    scene.meshes.push_back(std::move(*mesh));
  }
  return std::nullopt;
}

std::expected<Scene, SceneFileFailure> buildScene(const ParsedObj& obj, const fs::path& path,
                                                  Warnings& warnings) {
  Scene scene;
  scene.name = path.string();
  for (const tinyobj::material_t& mtl : obj.materials) {
    auto material = fromMtl(mtl, warnings);
    if (!material) return std::unexpected(badContents(path, material.error()));
    scene.materials.push_back(std::move(*material));
  }
  MeshBuilder builder(obj.attrib, path);
  for (const tinyobj::shape_t& shape : obj.shapes) {
    if (auto failure = addShape(shape, builder, scene, obj.materials.size(), warnings)) {
      return std::unexpected(*failure);
    }
  }
  if (triangleCount(scene) == 0) {
    return std::unexpected(badContents(path,
                                       "the file has no faces, where at least one triangle "
                                       "was expected"));
  }
  if (auto violation = firstContractViolation(scene); !violation.empty()) {
    return std::unexpected(badContents(path, violation));
  }
  return scene;
}

std::string joined(const Warnings& messages) {
  return fmt::format("{}", fmt::join(messages, "; "));
}

// tinyobjloader's remarks, each escaped (they quote names from the file).
Warnings printableMessages(std::string_view text) {
  Warnings messages = splitMessages(text);
  for (std::string& message : messages) {
    message = printable(message);
  }
  return messages;
}

// Parses the checked text; `mtllib` files are read through the folder's reader.
std::expected<ParsedObj, SceneFileFailure> parse(const fs::path& path, const std::string& text,
                                                 const OutsideFolderPolicy& outside,
                                                 Warnings& warnings) {
  ParsedObj obj;
  FolderMaterialReader materials(SceneFolder(path, outside));
  std::ispanstream in(std::span<const char>(text.data(), text.size()));
  std::string warning;
  std::string error;
  const bool ok = tinyobj::LoadObj(&obj.attrib, &obj.shapes, &obj.materials, &warning, &error, &in,
                                   &materials, /*triangulate=*/true,
                                   /*default_vcols_fallback=*/false);
  if (materials.refusal()) {
    return std::unexpected(badContents(path, *materials.refusal()));
  }
  if (!ok) {
    return std::unexpected(
        badContents(path, fmt::format("not a valid OBJ file (tinyobjloader: \"{}\")",
                                      joined(printableMessages(error)))));
  }
  warnings = printableMessages(warning);
  std::ranges::copy(printableMessages(error), std::back_inserter(warnings));
  return obj;
}

}  // namespace

std::expected<LoadedScene, SceneFileFailure> loadObj(const fs::path& path,
                                                     const OutsideFolderPolicy& outside) {
  const auto text = readSceneFile(path);
  if (!text) {
    return std::unexpected(text.error());
  }
  if (auto failure = checkObjText(path, *text)) {
    return std::unexpected(*failure);
  }
  LoadedScene loaded;
  const auto obj = parse(path, *text, outside, loaded.warnings);
  if (!obj) {
    return std::unexpected(obj.error());
  }
  if (auto failure = checkFaces(*obj, path)) {
    return std::unexpected(*failure);
  }
  if (auto failure = fatalWarning(loaded.warnings, path)) {
    return std::unexpected(*failure);
  }
  auto scene = buildScene(*obj, path, loaded.warnings);
  if (!scene) {
    return std::unexpected(scene.error());
  }
  loaded.scene = std::move(*scene);
  return loaded;
}

}  // namespace vem::scene
