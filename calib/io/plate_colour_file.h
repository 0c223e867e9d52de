// Colour-patch lists for `vemcalib plate colour` (calib/core/plate_colour_fit.h): TOML, one
// [[patch]] table per grey patch that both the light probe and the plate camera see, after the
// grey-patch files of patch_file.h:
//   [[patch]]
//   name = "g1"
//   probe_radiance = { value = [r, g, b], unit = "cd/m2" }  # the probe map's, patch direction
//   plate_linear = { value = [r, g, b], unit = "linear" }   # the plate's, 1 = full scale
// Loading refuses, naming the file, the patch and the field: missing or mistyped fields, a wrong
// unit, duplicate names, no patch at all. Black or saturated patches are the fit's to refuse.
#pragma once

#include <expected>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "calib/core/plate_colour_fit.h"
#include "calib/io/calib_file_failure.h"

namespace vem::calib::io {

[[nodiscard]] std::expected<std::vector<ColourPatch>, CalibFileFailure> loadColourPatchFile(
    const std::filesystem::path& path);

[[nodiscard]] std::string formatColourPatchFile(std::span<const ColourPatch> patches);

[[nodiscard]] std::expected<void, CalibFileFailure> saveColourPatchFile(
    std::span<const ColourPatch> patches, const std::filesystem::path& path);

}  // namespace vem::calib::io
