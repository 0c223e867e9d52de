// What the `vemcalib plate ...` commands share: the plate-camera file they merge into (an existing
// file is loaded first and only the command's own section is replaced; commands.h) and the plate's
// pose in words. The board images they read are board_views.h's.
#pragma once

#include <expected>
#include <filesystem>
#include <numbers>
#include <optional>
#include <string>

#include "calib/core/plate_camera.h"

namespace vem::calibtool {

inline constexpr double kDegPerRad = 180.0 / std::numbers::pi;

// The plate camera already at `path` (nullopt when there is no file), or the loader's sentence: a
// file that does not load is never overwritten.
[[nodiscard]] std::expected<std::optional<calib::PlateCamera>, std::string> loadPlateToMerge(
    const std::filesystem::path& path);

// The plate camera at `path`, which the command needs (`what` says for what, e.g. "the pose needs
// the intrinsics"), or one sentence.
[[nodiscard]] std::expected<calib::PlateCamera, std::string> loadPlateToUpdate(
    const std::filesystem::path& path, const std::string& what);

// "(0.900, 1.400, -1.650) m, heading 195.0 deg, looking 36.7 deg down, roll 0.0 deg"
[[nodiscard]] std::string describePose(const calib::PlatePose& pose);

}  // namespace vem::calibtool
