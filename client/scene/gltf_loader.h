// The glTF 2.0 loader (tinygltf 2.7): a .gltf (JSON, external or data-URI buffers) or .glb file
// as a Scene. Textures are not used (images are not even decoded).
//
// Conventions:
// - glTF's frame is the world frame of scene/scene.h already (right-handed, +Y up, metres).
//   The scene drawn is the file's default scene, else scene 0, else every root node.
// - Node transforms (a matrix, or translation * rotation * scale) compose down the hierarchy:
//   worldFromNode = worldFromParent * parentFromNode. Positions take worldFromNode, normals its
//   inverse transpose (then renormalised). A node whose transform mirrors (negative determinant)
//   has its triangles' winding reversed so fronts stay counter-clockwise; a node that scales to
//   zero is skipped with a warning.
// - One Mesh per (node, triangle primitive), named "mesh/primitive". Normals are the file's
//   NORMAL, or smooth area-weighted ones (scene/mesh_normals.h) when it has none.
// - Materials: pbrMetallicRoughness maps, with base = baseColorFactor.rgb, m = metallicFactor,
//   r = roughnessFactor (all clamped to [0, 1]), to
//     diffuseAlbedo  = base (1 - m)
//     lobe           = GGX when m > 0 or r < 0.9, else Lambertian
//     roughness      = max(r, 0.01)              (GGX only)
//     specularAlbedo = mix(0.04, base, m) = F0    (GGX only; zero for Lambertian)
//   A primitive with no material gets vemcast's default (Lambertian, 0.8 grey), not glTF's
//   default (a rough white metal), which would light very differently.
// - Buffer and image URIs are read from the file's folder only (scene_folder.h,
//   gltf_folder_access.h): one that resolves outside it (`..`, a symbolic link, an absolute path,
//   a file: URI) is refused, and not opened, unless `outside` allows it; the working directory is
//   never searched. data: URIs are decoded from the file itself, so they are bounded by its size.
// - A scene from one file holds at most kMaxSceneVertices vertices and kMaxSceneTriangles
//   triangles over all its nodes' drawings (GltfLimits): many nodes can draw one large mesh, so a
//   small file could otherwise claim any size. Each drawing is read (bounded by the file's size)
//   and then counted, so at most one drawing past the limits is read.
// - Refused (BadContents, one sentence naming the file, the mesh / primitive / accessor and what
//   was expected): tinygltf's parse errors (among them a buffer whose byteLength differs from
//   what its URI or the GLB BIN chunk holds, said plainly for data: URIs), a GLB BIN chunk that
//   runs past the end of the file (gltf_buffer_check.h), a URI outside the folder, a node
//   hierarchy that is not a forest (gltf_node_tree.h), primitives of a mode other than 4
//   (triangles), missing POSITION, accessors or buffer views past the end of their buffer
//   (gltf_accessor.h), indices >= the vertex count, a scene past the limits above, non-finite
//   positions or normals, zero-length normals, no triangles. Names and URIs from the file are
//   escaped (util/printable.h) in messages and warnings.
#pragma once

#include <cstddef>
#include <expected>
#include <filesystem>

#include "client/scene/scene_file_result.h"
#include "client/scene/scene_folder.h"

namespace vem::scene {

inline constexpr std::size_t kMaxSceneVertices = std::size_t{1} << 24U;   // 16,777,216
inline constexpr std::size_t kMaxSceneTriangles = std::size_t{1} << 24U;  // 16,777,216

struct GltfLimits {
  std::size_t maxVertices = kMaxSceneVertices;
  std::size_t maxTriangles = kMaxSceneTriangles;
};

// `.glb` files are read as binary glTF, anything else as JSON glTF.
[[nodiscard]] std::expected<LoadedScene, SceneFileFailure> loadGltf(
    const std::filesystem::path& path, const OutsideFolderPolicy& outside = {},
    GltfLimits limits = {});

}  // namespace vem::scene
