#include "calib/io/patch_file.h"

#include "calib/io/file_access.h"
#include "calib/io/patch_label.h"
#include "calib/io/toml_writer.h"
#include "util/toml_reader.h"

namespace vem::calib::io {
namespace {

using FieldReader = util::TomlReader;

constexpr std::string_view kUnitPx = "px";
constexpr std::string_view kUnitLuminance = "cd/m2";
constexpr std::int64_t kMaxCoordinatePx = 1 << 16;

// The region's x, y, width and height, whole pixels.
void readRegion(FieldReader& r, PatchSpec& patch) {
  const std::vector<std::int64_t> region =
      r.integerQuantityArray("region", kUnitPx, {4, "x, y, width and height"});
  r.require(region[0] >= 0 && region[1] >= 0 && region[0] < kMaxCoordinatePx &&
                region[1] < kMaxCoordinatePx,
            "region",
            "expected x and y from 0 to 65535, found " + std::to_string(region[0]) + ", " +
                std::to_string(region[1]));
  r.require(region[2] > 0 && region[3] > 0 && region[2] <= kMaxCoordinatePx &&
                region[3] <= kMaxCoordinatePx,
            "region",
            "expected a width and height from 1 to 65536, found " + std::to_string(region[2]) +
                " x " + std::to_string(region[3]));
  patch.x = int(region[0]);
  patch.y = int(region[1]);
  patch.width = int(region[2]);
  patch.height = int(region[3]);
}

PatchSpec readPatch(FieldReader r) {
  r.onlyKeys({"name", "region", "luminance", "check"});
  PatchSpec patch;
  patch.name = r.string("name");
  r.require(!patch.name.empty(), "name", "expected a name, found an empty string");
  readRegion(r, patch);
  patch.luminanceCdM2 = r.quantity("luminance", kUnitLuminance);
  r.require(patch.luminanceCdM2 > 0.0, "luminance",
            "expected a luminance above 0, found " + util::shortestText(patch.luminanceCdM2));
  patch.check = r.boolean("check", false);
  return patch;
}

std::expected<std::vector<PatchSpec>, CalibFileFailure> parsePatchFile(const std::string& text,
                                                                       const std::string& source) {
  return detail::parseTomlText(text, source, [](FieldReader& root, util::TomlStatus& status) {
    return detail::readPatchTables(root, status, readPatch);
  });
}

}  // namespace

std::expected<std::vector<PatchSpec>, CalibFileFailure> loadPatchFile(
    const std::filesystem::path& path) {
  return detail::loadTextFile(path, "patch file", parsePatchFile);
}

std::string formatPatchFile(std::span<const PatchSpec> patches) {
  detail::TomlWriter w;
  w.comment(
      "Grey patches for `vemcalib photometric` (docs/calibration.md): each patch's region on");
  w.comment(
      "the sensor and its known luminance; check = true leaves it out of the fit to test it.");
  for (const PatchSpec& patch : patches) {
    w.arrayTable("patch");
    w.string("name", patch.name);
    const std::array<std::int64_t, 4> region{patch.x, patch.y, patch.width, patch.height};
    w.quantity("region", region, kUnitPx, "x, y, width, height");
    w.quantity("luminance", patch.luminanceCdM2, kUnitLuminance);
    w.boolean("check", patch.check, patch.check ? "left out of the fit" : "");
  }
  return w.text();
}

std::expected<void, CalibFileFailure> savePatchFile(std::span<const PatchSpec> patches,
                                                    const std::filesystem::path& path) {
  return detail::saveCheckedTextFile(path, formatPatchFile(patches), "patch file", parsePatchFile);
}

}  // namespace vem::calib::io
