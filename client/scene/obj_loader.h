// The Wavefront OBJ loader (tinyobjloader 2.0): an .obj file and its .mtl materials as a Scene.
//
// Conventions:
// - Positions are taken as they are, in the world frame of scene/scene.h (+Y up, the file's
//   length unit); faces are counter-clockwise seen from the front, as the OBJ format specifies.
//   Polygons are triangulated by tinyobjloader (ear clipping); faces of more than
//   kMaxFaceVertices (256) vertices are refused (obj_text_check.h).
// - One Mesh per (OBJ shape, material) pair, named "shape" or "shape/material". Vertices are
//   deduplicated by (position index, normal index). When any face of a mesh lacks normals, the
//   whole mesh gets smooth area-weighted normals (scene/mesh_normals.h) and a warning says so
//   unless no face had any.
// - Materials (MTL), in the terms of scene/scene.h:
//     Kd            -> diffuseAlbedo (clamped to [0, 1], with a warning)
//     Ks > 0, Ns    -> Blinn lobe, specularAlbedo = Ks, exponent = Ns; with the vemcast key
//                      `vem_lobe phong` the normalised Phong lobe instead (`vem_lobe blinn`: the
//                      default); any other value, or vem_lobe beside Pr, is refused
//     Pr > 0 (the PBR extension's roughness; tinyobjloader cannot tell "Pr 0" from no Pr)
//                   -> GGX lobe, roughness = Pr clamped to [0.01, 1],
//                      specularAlbedo = Ks if Ks > 0, else mix(0.04, Kd, Pm),
//                      diffuseAlbedo = Kd (1 - Pm)   (Pm: the extension's metallic, default 0)
//     otherwise     -> Lambertian.
//   Faces with no material (or no .mtl at all) get the default: Lambertian, 0.8 grey.
// - `mtllib` files are read from the OBJ file's folder only (scene_folder.h,
//   obj_folder_materials.h): one that resolves outside it is refused, and not opened, unless
//   `outside` allows it. MTL texture maps are not read (vemcast draws no textures).
// - Refused (BadContents, one sentence naming the file and the element): the text check's
//   findings, each with its line (obj_text_check.h: coordinates that are not finite numbers, face
//   indices that are 0, malformed, too large or out of range, faces of fewer than 3 or more than
//   kMaxFaceVertices vertices), tinyobjloader's errors (with their line), an `mtllib` outside the
//   folder, zero-length normals, vertices whose smooth normal is undefined, no triangles at all.
//   Names from the file are escaped (util/printable.h) in messages and warnings.
#pragma once

#include <expected>
#include <filesystem>

#include "client/scene/scene_file_result.h"
#include "client/scene/scene_folder.h"

namespace vem::scene {

[[nodiscard]] std::expected<LoadedScene, SceneFileFailure> loadObj(
    const std::filesystem::path& path, const OutsideFolderPolicy& outside = {});

}  // namespace vem::scene
