#include "calib/io/plate_colour_file.h"

#include "calib/io/file_access.h"
#include "calib/io/patch_label.h"
#include "calib/io/toml_writer.h"
#include "util/toml_reader.h"

namespace vem::calib::io {
namespace {

using FieldReader = util::TomlReader;

constexpr std::string_view kUnitRadiance = "cd/m2";
constexpr std::string_view kUnitLinear = "linear";

std::array<double, 3> rgb(const std::vector<double>& values) {
  std::array<double, 3> out{};
  for (std::size_t c = 0; c < values.size() && c < 3; ++c) out[c] = values[c];
  return out;
}

ColourPatch readPatch(FieldReader r) {
  r.onlyKeys({"name", "probe_radiance", "plate_linear"});
  ColourPatch patch;
  patch.name = r.string("name");
  r.require(!patch.name.empty(), "name", "expected a name, found an empty string");
  patch.probeRadianceCdM2 = rgb(r.quantityArray("probe_radiance", kUnitRadiance, {3, "R, G, B"}));
  patch.plateLinear = rgb(r.quantityArray("plate_linear", kUnitLinear, {3, "R, G, B"}));
  return patch;
}

std::expected<std::vector<ColourPatch>, CalibFileFailure> parseColourPatchFile(
    const std::string& text, const std::string& source) {
  return detail::parseTomlText(text, source, [](FieldReader& root, util::TomlStatus& status) {
    return detail::readPatchTables(root, status, readPatch);
  });
}

}  // namespace

std::expected<std::vector<ColourPatch>, CalibFileFailure> loadColourPatchFile(
    const std::filesystem::path& path) {
  return detail::loadTextFile(path, "colour patch file", parseColourPatchFile);
}

std::string formatColourPatchFile(std::span<const ColourPatch> patches) {
  detail::TomlWriter w;
  w.comment("Grey patches for `vemcalib plate colour` (docs/calibration.md): each patch's");
  w.comment("radiance in the light probe's map and its linear value in the plate image.");
  for (const ColourPatch& patch : patches) {
    w.arrayTable("patch");
    w.string("name", patch.name);
    w.quantity("probe_radiance", patch.probeRadianceCdM2, kUnitRadiance, "R, G, B");
    w.quantity("plate_linear", patch.plateLinear, kUnitLinear, "R, G, B; 1 = full scale");
  }
  return w.text();
}

std::expected<void, CalibFileFailure> saveColourPatchFile(std::span<const ColourPatch> patches,
                                                          const std::filesystem::path& path) {
  return detail::saveCheckedTextFile(path, formatColourPatchFile(patches), "colour patch file",
                                     parseColourPatchFile);
}

}  // namespace vem::calib::io
