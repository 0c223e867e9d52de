#include "client/scene/gltf_loader.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <tiny_gltf.h>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <limits>
#include <utility>

#include "client/scene/gltf_accessor.h"
#include "client/scene/gltf_buffer_check.h"
#include "client/scene/gltf_folder_access.h"
#include "client/scene/gltf_node_tree.h"
#include "client/scene/mesh_normals.h"
#include "util/printable.h"

namespace vem::scene {
namespace {

namespace fs = std::filesystem;
using Failure = std::optional<SceneFileFailure>;

constexpr float kGlossyRoughnessBelow = 0.9F;
constexpr float kMinRoughness = 0.01F;
constexpr float kDielectricF0 = 0.04F;

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

float unit(double value) { return std::clamp(static_cast<float>(value), 0.0F, 1.0F); }

Material fromPbr(const tinygltf::Material& source, std::size_t index) {
  const tinygltf::PbrMetallicRoughness& pbr = source.pbrMetallicRoughness;
  const auto& factor = pbr.baseColorFactor;
  const glm::vec3 base = factor.size() >= 3
                             ? glm::vec3(unit(factor[0]), unit(factor[1]), unit(factor[2]))
                             : glm::vec3(1.0F);
  const float metallic = unit(pbr.metallicFactor);
  const float roughness = unit(pbr.roughnessFactor);
  Material m;
  m.name = source.name.empty() ? fmt::format("material {}", index) : source.name;
  m.diffuseAlbedo = base * (1.0F - metallic);
  if (metallic > 0.0F || roughness < kGlossyRoughnessBelow) {
    m.lobe = Lobe::Ggx;
    m.roughness = std::max(roughness, kMinRoughness);
    m.specularAlbedo = glm::mix(glm::vec3(kDielectricF0), base, metallic);
  }
  return m;
}

glm::mat4 parentFromNode(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) {
    glm::dmat4 matrix;
    std::copy(node.matrix.begin(), node.matrix.end(), glm::value_ptr(matrix));  // column-major
    return glm::mat4(matrix);
  }
  glm::dvec3 t(0.0);
  glm::dquat r(1.0, 0.0, 0.0, 0.0);
  glm::dvec3 s(1.0);
  if (node.translation.size() == 3) {
    t = {node.translation[0], node.translation[1], node.translation[2]};
  }
  if (node.rotation.size() == 4) {  // glTF order x, y, z, w
    r = glm::normalize(
        glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]));
  }
  if (node.scale.size() == 3) {
    s = {node.scale[0], node.scale[1], node.scale[2]};
  }
  const glm::dmat4 m =
      glm::translate(glm::dmat4(1.0), t) * glm::mat4_cast(r) * glm::scale(glm::dmat4(1.0), s);
  return glm::mat4(m);
}

// The triangles of one primitive in its mesh's frame.
struct Triangles {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;  // empty when the file has none
  std::vector<std::uint32_t> indices;
};

class GltfSceneBuilder {
 public:
  GltfSceneBuilder(const tinygltf::Model& model, const fs::path& path, GltfLimits limits,
                   std::vector<std::string>& warnings)
      : model_(model),
        path_(path),
        warnings_(warnings),
        limits_(limits),
        sceneMaterial_(model.materials.size()) {
    scene_.name = path.string();
  }

  Failure addRoots() {
    const auto visits = nodesToDraw(model_);
    if (!visits) {
      return badContents(path_, visits.error());
    }
    std::vector<glm::mat4> worldFromNode(model_.nodes.size(), glm::mat4(1.0F));
    for (const NodeVisit& visit : *visits) {
      const auto n = static_cast<std::size_t>(visit.node);
      const glm::mat4 worldFromParent = visit.parent < 0
                                            ? glm::mat4(1.0F)
                                            : worldFromNode[static_cast<std::size_t>(visit.parent)];
      worldFromNode[n] = worldFromParent * parentFromNode(model_.nodes[n]);
      if (auto failure = addNodeMesh(model_.nodes[n], visit.node, worldFromNode[n])) {
        return failure;
      }
    }
    return std::nullopt;
  }

  Scene take() { return std::move(scene_); }

 private:
  Failure addNodeMesh(const tinygltf::Node& node, int index, const glm::mat4& worldFromNode) {
    if (node.mesh < 0) {
      return std::nullopt;
    }
    if (static_cast<std::size_t>(node.mesh) >= model_.meshes.size()) {
      return badContents(
          path_, fmt::format("node {} refers to mesh {}, which does not exist", index, node.mesh));
    }
    const float det = glm::determinant(glm::mat3(worldFromNode));
    if (!(std::abs(det) > 0.0F)) {
      warnings_.push_back(
          fmt::format("node {} scales its mesh {} to zero; skipped", index, node.mesh));
      return std::nullopt;
    }
    const tinygltf::Mesh& mesh = model_.meshes[static_cast<std::size_t>(node.mesh)];
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
      const auto where =
          fmt::format("mesh {} ('{}') primitive {}", node.mesh, util::printable(mesh.name), p);
      auto triangles = readPrimitive(mesh.primitives[p]);
      if (!triangles) {
        return badContents(path_, where + ": " + triangles.error());
      }
      if (auto failure = countInstance(*triangles, index, where)) {
        return failure;
      }
      if (auto failure = addMesh(std::move(*triangles), worldFromNode, det < 0.0F, where)) {
        return failure;
      }
      scene_.meshes.back().material = materialFor(mesh.primitives[p].material);
      scene_.meshes.back().name =
          fmt::format("{}/{}", mesh.name.empty() ? std::to_string(node.mesh) : mesh.name, p);
    }
    return std::nullopt;
  }

  // Adds one drawing of a primitive (by node `node`) to the scene's totals, refusing it when they
  // would pass the limits: many nodes drawing one large mesh make a small file claim a huge scene.
  // Each primitive is bounded by the file (its accessors lie in its buffers), so at most one
  // drawing past the limits is ever read.
  Failure countInstance(const Triangles& t, int node, const std::string& where) {
    const std::size_t vertices = t.positions.size();
    const std::size_t triangles = t.indices.size() / 3;
    if (vertices > limits_.maxVertices - std::min(vertexTotal_, limits_.maxVertices) ||
        triangles > limits_.maxTriangles - std::min(triangleTotal_, limits_.maxTriangles)) {
      return badContents(
          path_, fmt::format("{}, drawn by node {}, adds {} vertices and {} triangles to the {} "
                             "and {} drawn before it, where a scene of at most {} vertices and "
                             "{} triangles was expected",
                             where, node, vertices, triangles, vertexTotal_, triangleTotal_,
                             limits_.maxVertices, limits_.maxTriangles));
    }
    vertexTotal_ += vertices;
    triangleTotal_ += triangles;
    return std::nullopt;
  }

  std::expected<Triangles, std::string> readPrimitive(const tinygltf::Primitive& primitive) const {
    if (primitive.mode != TINYGLTF_MODE_TRIANGLES) {
      return std::unexpected(fmt::format(
          "mode {} is not supported, where 4 (triangles) was expected", primitive.mode));
    }
    const auto position = primitive.attributes.find("POSITION");
    if (position == primitive.attributes.end()) {
      return std::unexpected(std::string("it has no POSITION attribute"));
    }
    Triangles t;
    auto positions = readVec3Accessor(model_, position->second);
    if (!positions) {
      return std::unexpected("POSITION " + positions.error());
    }
    t.positions = std::move(*positions);
    if (const auto normal = primitive.attributes.find("NORMAL");
        normal != primitive.attributes.end()) {
      auto normals = readVec3Accessor(model_, normal->second);
      if (!normals || normals->size() != t.positions.size()) {
        return std::unexpected(
            normals ? fmt::format("NORMAL has {} elements, where {} (one per position) were "
                                  "expected",
                                  normals->size(), t.positions.size())
                    : "NORMAL " + normals.error());
      }
      t.normals = std::move(*normals);
    }
    auto indices = readIndices(primitive, t.positions.size());
    if (!indices) {
      return std::unexpected(indices.error());
    }
    t.indices = std::move(*indices);
    return t;
  }

  std::expected<std::vector<std::uint32_t>, std::string> readIndices(
      const tinygltf::Primitive& primitive, std::size_t vertexCount) const {
    std::vector<std::uint32_t> indices;
    if (primitive.indices < 0) {
      indices.resize(vertexCount);
      for (std::size_t i = 0; i < vertexCount; ++i) {
        indices[i] = static_cast<std::uint32_t>(i);
      }
    } else {
      auto read = readIndexAccessor(model_, primitive.indices);
      if (!read) {
        return std::unexpected(read.error());
      }
      indices = std::move(*read);
    }
    if (indices.size() % 3 != 0) {
      return std::unexpected(
          fmt::format("it has {} indices, where a multiple of three was expected", indices.size()));
    }
    for (std::size_t i = 0; i < indices.size(); ++i) {
      if (indices[i] >= vertexCount) {
        return std::unexpected(fmt::format("index {} is {}, but there are only {} vertices", i,
                                           indices[i], vertexCount));
      }
    }
    return indices;
  }

  Failure addMesh(Triangles t, const glm::mat4& worldFromNode, bool mirrored,
                  const std::string& where) {
    const glm::mat3 normalFromNode = glm::transpose(glm::inverse(glm::mat3(worldFromNode)));
    Mesh mesh;
    for (std::size_t i = 0; i < t.positions.size(); ++i) {
      if (!finite(t.positions[i])) {
        return badContents(path_, fmt::format("{}: position {} is not finite", where, i));
      }
      mesh.positions.push_back(glm::vec3(worldFromNode * glm::vec4(t.positions[i], 1.0F)));
    }
    for (std::size_t i = 0; i < t.normals.size(); ++i) {
      const glm::vec3 n = normalFromNode * t.normals[i];
      if (!finite(n) || !(glm::length(n) > 0.0F)) {
        return badContents(path_,
                           fmt::format("{}: normal {} is not a finite non-zero vector", where, i));
      }
      mesh.normals.push_back(glm::normalize(n));
    }
    mesh.indices = std::move(t.indices);
    for (std::size_t i = 0; mirrored && i + 2 < mesh.indices.size(); i += 3) {
      std::swap(mesh.indices[i + 1], mesh.indices[i + 2]);
    }
    if (mesh.normals.empty()) {
      auto normals = smoothNormals(mesh.positions, mesh.indices);
      if (!normals) {
        return badContents(
            path_, fmt::format("{}: vertex {} lies only on zero-area triangles, so its normal is "
                               "undefined",
                               where, normals.error()));
      }
      mesh.normals = std::move(*normals);
    }
    scene_.meshes.push_back(std::move(mesh));
    return std::nullopt;
  }

  std::uint32_t materialFor(int index) {
    if (index < 0 || static_cast<std::size_t>(index) >= model_.materials.size()) {
      if (!defaultMaterial_) {
        defaultMaterial_ = static_cast<std::uint32_t>(scene_.materials.size());
        scene_.materials.push_back(defaultFileMaterial());
      }
      return *defaultMaterial_;
    }
    auto& slot = sceneMaterial_[static_cast<std::size_t>(index)];
    if (!slot) {
      slot = static_cast<std::uint32_t>(scene_.materials.size());
      scene_.materials.push_back(fromPbr(model_.materials[static_cast<std::size_t>(index)],
                                         static_cast<std::size_t>(index)));
    }
    return *slot;
  }

  const tinygltf::Model& model_;
  const fs::path& path_;
  std::vector<std::string>& warnings_;
  Scene scene_;
  GltfLimits limits_;
  std::size_t vertexTotal_ = 0;  // over every drawing of every primitive so far
  std::size_t triangleTotal_ = 0;
  std::vector<std::optional<std::uint32_t>> sceneMaterial_;  // per glTF material
  std::optional<std::uint32_t> defaultMaterial_;
};

bool ignoreImage(tinygltf::Image*, const int, std::string*, std::string*, int, int,
                 const unsigned char*, int, void*) {
  return true;  // vemcast draws no textures
}

bool isGlb(const fs::path& path) {
  std::string extension = path.extension().string();
  std::ranges::transform(extension, extension.begin(),
                         [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == ".glb";
}

// tinygltf's remarks, each escaped (they quote names and URIs from the file).
std::vector<std::string> printableMessages(std::string_view text) {
  std::vector<std::string> messages = splitMessages(text);
  for (std::string& message : messages) {
    message = util::printable(message);
  }
  return messages;
}

std::expected<tinygltf::Model, SceneFileFailure> parse(const fs::path& path,
                                                       const std::string& bytes,
                                                       const OutsideFolderPolicy& outside,
                                                       std::vector<std::string>& warnings) {
  if (bytes.size() > std::numeric_limits<unsigned int>::max()) {
    return std::unexpected(badContents(
        path,
        fmt::format("the file has {} bytes, where at most 4 GiB was expected", bytes.size())));
  }
  const bool glb = isGlb(path);
  if (auto problem = glb ? binChunkProblem(bytes) : std::string(); !problem.empty()) {
    return std::unexpected(badContents(path, problem));
  }
  tinygltf::TinyGLTF gltf;
  gltf.SetImageLoader(ignoreImage, nullptr);
  GltfFolderAccess access(SceneFolder(path, outside));
  access.install(gltf);
  tinygltf::Model model;
  std::string error;
  std::string warning;
  const auto size = static_cast<unsigned int>(bytes.size());
  const bool ok =
      glb ? gltf.LoadBinaryFromMemory(&model, &error, &warning,
                                      reinterpret_cast<const unsigned char*>(bytes.data()), size,
                                      access.baseDir())
          : gltf.LoadASCIIFromString(&model, &error, &warning, bytes.data(), size,
                                     access.baseDir());
  if (access.refusal()) {
    return std::unexpected(badContents(path, *access.refusal()));
  }
  warnings = printableMessages(warning);
  if (!ok) {
    if (error.find("Failed to decode 'uri'") != std::string::npos) {
      if (auto problem = dataUriProblem(bytes, glb); !problem.empty()) {
        return std::unexpected(badContents(path, problem));
      }
    }
    return std::unexpected(
        badContents(path, fmt::format("not a valid glTF 2.0 file (tinygltf: \"{}\")",
                                      fmt::join(printableMessages(error), "; "))));
  }
  return model;
}

}  // namespace

std::expected<LoadedScene, SceneFileFailure> loadGltf(const fs::path& path,
                                                      const OutsideFolderPolicy& outside,
                                                      GltfLimits limits) {
  const auto bytes = readSceneFile(path);
  if (!bytes) {
    return std::unexpected(bytes.error());
  }
  LoadedScene loaded;
  const auto model = parse(path, *bytes, outside, loaded.warnings);
  if (!model) {
    return std::unexpected(model.error());
  }
  GltfSceneBuilder builder(*model, path, limits, loaded.warnings);
  if (auto failure = builder.addRoots()) {
    return std::unexpected(*failure);
  }
  loaded.scene = builder.take();
  if (triangleCount(loaded.scene) == 0) {
    return std::unexpected(
        badContents(path, "the scene has no triangles, where at least one was expected"));
  }
  if (auto violation = firstContractViolation(loaded.scene); !violation.empty()) {
    return std::unexpected(badContents(path, violation));
  }
  return loaded;
}

}  // namespace vem::scene
