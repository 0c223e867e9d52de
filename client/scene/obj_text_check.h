// A pass over an OBJ file's text, before tinyobjloader reads it, for what tinyobjloader lets
// through silently or takes too long over:
// - coordinates: it reads one it cannot parse ("nan", "inf", "1.0x", a line cut short) as 0, so
//   every `v` and `vn` line must hold at least three finite numbers;
// - face indices: it reads them with atoi (so "99999999999999999999999" and "4294967297" become
//   whatever the conversion makes of them), so every index of an `f` line must be a whole number,
//   not 0, that names an element the file has: a positive index one of the file's vertices
//   (texture coordinates, normals), a negative (relative) one an element defined above the face;
//   corners are v, v/vt, v//vn or v/vt/vn;
// - face sizes: it triangulates polygons by ear clipping, quadratic or worse in their vertex count
//   (a 100,000-vertex polygon took 33 to 55 s here), so a face has 3 to kMaxFaceVertices vertices.
// Lines are numbered from 1, as editors do; "\n", "\r\n" and a lone "\r" each end a line, as in
// tinyobjloader.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string_view>

#include "client/scene/scene_file_result.h"

namespace vem::scene {

inline constexpr std::size_t kMaxFaceVertices = 256;

// The first line of `text` (the contents of `path`) with a problem above, as a BadContents
// failure naming the file, the line and what was expected; nothing when there is none.
[[nodiscard]] std::optional<SceneFileFailure> checkObjText(const std::filesystem::path& path,
                                                           std::string_view text);

}  // namespace vem::scene
