// Patch lists for `vemcalib photometric`: TOML, one [[patch]] table per grey patch:
//   [[patch]]
//   name = "p1"
//   region = { value = [x, y, width, height], unit = "px" }
//   luminance = { value = 12.5, unit = "cd/m2" }
//   check = false            # optional: true leaves the patch out of the fit, to check it
// Loading refuses, naming the file, the patch and the field: missing or mistyped fields, a wrong
// unit, a non-positive luminance or size, duplicate names.
#pragma once

#include <expected>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "calib/core/photometric_fit.h"
#include "calib/io/calib_file_failure.h"

namespace vem::calib::io {

[[nodiscard]] std::expected<std::vector<PatchSpec>, CalibFileFailure> loadPatchFile(
    const std::filesystem::path& path);

[[nodiscard]] std::string formatPatchFile(std::span<const PatchSpec> patches);

[[nodiscard]] std::expected<void, CalibFileFailure> savePatchFile(
    std::span<const PatchSpec> patches, const std::filesystem::path& path);

}  // namespace vem::calib::io
