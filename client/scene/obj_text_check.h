// A pass over an OBJ file's text for what tinyobjloader lets through silently: it reads a
// coordinate it cannot parse ("nan", "inf", "1.0x", a line cut short) as 0. Checks every `v` and
// `vn` line for at least three finite numbers. Lines are numbered from 1, as editors do.
#pragma once

#include <filesystem>
#include <optional>

#include "client/scene/scene_file_result.h"

namespace vem::scene {

// The first `v` / `vn` line with a missing, unparsable or non-finite number, as a BadContents
// failure naming the file, the line and the token; nothing when all are finite.
[[nodiscard]] std::optional<SceneFileFailure> findBadObjCoordinate(
    const std::filesystem::path& path);

}  // namespace vem::scene
