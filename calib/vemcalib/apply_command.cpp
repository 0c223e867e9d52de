// `vemcalib apply`: one raw frame through a camera's calibration into an environment map, the
// polar map vemd would compute (radiance in cd/m2), ready for `vemtool lights`.
#include <algorithm>
#include <cstdlib>
#include <map>
#include <memory>
#include <numeric>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "calib/core/polar_remap.h"
#include "calib/io/camera_file.h"
#include "calib/io/raw_frame_file.h"
#include "camera_output.h"
#include "commands.h"
#include "util/cli_value_names.h"
#include "frame_arguments.h"
#include "mapio/map_file.h"

namespace vem::calibtool {
namespace {

struct ApplyOptions {
  std::string camera;
  std::string frame;
  std::string out;
  int width = 1024;
  std::optional<int> height;  // default: width / 4 (hemisphere) or width / 2 (sphere)
  MapLayout layout = MapLayout::Hemisphere;
  std::optional<std::string> maskOut;
  double gain = 1.0;
};

// The calibration, refused unless it has both the response and the lens.
std::expected<calib::CameraCalibration, std::string> loadCalibrated(const std::string& path) {
  auto calibration = calib::io::loadCameraFile(path);
  if (!calibration) return std::unexpected(calibration.error().message);
  if (!calibration->photometric)
    return std::unexpected(path +
                           ": the camera has no photometric section (run vemcalib "
                           "photometric or vemcalib response first)");
  if (!calibration->lens)
    return std::unexpected(path +
                           ": the camera has no geometric section (run vemcalib fisheye first)");
  return std::move(*calibration);
}

std::expected<RawFrame, std::string> loadMatchingFrame(const ApplyOptions& o,
                                                       const calib::CameraCalibration& c) {
  auto frame = loadFrameArgument(o.frame, c.camera.pixelFormat.bits, o.gain);
  if (!frame) return std::unexpected(frame.error());
  if (auto mismatch = frameMismatch(c.camera, o.camera, *frame))
    return std::unexpected(parseFrameArgument(o.frame)->path.string() + ": " + *mismatch);
  return std::move(*frame);
}

std::expected<void, std::string> saveMask(const calib::PolarRemap& remap, const std::string& path) {
  RawFrame mask = RawFrame::blank(remap.mapWidth, remap.mapHeight, {1, 8});
  const std::vector<std::uint8_t> valid = remap.validMask();
  std::ranges::transform(valid, mask.codes.begin(),
                         [](std::uint8_t v) { return std::uint16_t(v != 0 ? 255 : 0); });
  auto saved = calib::io::saveRawFrame(mask, path);
  if (!saved) return std::unexpected(saved.error().message);
  return {};
}

void printResult(const ApplyOptions& o, const EnvMap& map, const calib::PolarRemap& remap) {
  const float brightest = map.rgb.empty() ? 0.0F : *std::ranges::max_element(map.rgb);
  fmt::print(
      "wrote {}: {} x {} {} map of radiance in cd/m2; {:.1f} % of its pixels are seen by the "
      "lens (the rest are 0); brightest channel value {:.4g} cd/m2\n",
      o.out, map.width, map.height, layoutName(map.layout), 100.0 * remap.validFraction(),
      double(brightest));
  if (o.maskOut)
    fmt::print("wrote {}: 255 where the lens sees the map pixel, 0 elsewhere\n", *o.maskOut);
  const bool shapeSaysLayout = mapio::defaultLayout(map.width, map.height) == map.layout;
  fmt::print("next: vemtool lights --in {} --count 64{}\n", o.out,
             shapeSaysLayout ? "" : fmt::format(" --layout {}", layoutName(map.layout)));
}

int runApply(const ApplyOptions& o) {
  const auto calibration = loadCalibrated(o.camera);
  if (!calibration) return reportFailure(calibration.error());
  const auto frame = loadMatchingFrame(o, *calibration);
  if (!frame) return reportFailure(frame.error());
  const int height =
      o.height.value_or(o.layout == MapLayout::Hemisphere ? o.width / 4 : o.width / 2);
  if (height < 1)
    return reportFailure(fmt::format("--width {} leaves no rows for the map", o.width));
  const calib::PolarRemap remap =
      calib::buildPolarRemap(*calibration->lens, calibration->orientation, frame->width,
                             frame->height, o.layout, o.width, height);
  const calib::CodeToLuminanceLut lut = calib::buildCodeToLuminanceLut(
      *calibration->photometric, frame->format, frame->exposureUs, frame->gain);
  EnvMap map;
  calib::applyPolarRemap(remap, *frame, lut, map);
  if (auto saved = mapio::saveMap(map, o.out); !saved)
    return reportFailure(saved.error().message);
  if (o.maskOut)
    if (auto saved = saveMask(remap, *o.maskOut); !saved)
      return reportFailure(saved.error());
  printResult(o, map, remap);
  return EXIT_SUCCESS;
}

constexpr const char* kApplyFooter = R"(Example:
  vemcalib simulate frame --camera config/camera-example.toml --map ../shared/data/hdri/park.exr \
      --out sky.png
  vemcalib apply --camera config/camera-example.toml --frame sky.png --out sky.exr --mask-out sky-mask.png
  vemtool lights --in sky.exr --count 64
Turns each code into luminance (the photometric section, with the frame's exposure and gain) and
resamples the fisheye image into a polar map (the geometric and orientation sections): a
hemisphere map has W columns over the azimuth and H rows from the zenith to the horizon
(docs/conventions.md). Map pixels the lens does not see are 0 (and 0 in the mask).
Refuses a camera file without photometric or geometric section, and a frame whose size or
format differs from the camera's.)";

}  // namespace

void addApplyCommand(CLI::App& app, int& exitCode) {
  auto o = std::make_shared<ApplyOptions>();
  CLI::App* cmd = app.add_subcommand(
      "apply", "Turn a raw frame into an environment map (cd/m2) with a camera's calibration");
  cmd->footer(kApplyFooter);
  cmd->add_option("--camera", o->camera, "Camera file with photometric and geometric sections")
      ->required();
  cmd->add_option("--frame", o->frame, "Raw frame: FILE[@EXPOSURE_US] (default 1000 us)")
      ->required();
  cmd->add_option("--out", o->out, "Map file to write (.exr, .hdr or .pfm)")->required();
  cmd->add_option("--width", o->width, "Map width in pixels (columns over the azimuth)")
      ->capture_default_str()
      ->type_name(help::rangeName(1, mapio::kMaxMapWidth))
      ->check(help::quiet(CLI::Range(1, mapio::kMaxMapWidth)));
  cmd->add_option(
         "--height", o->height,
         "Map height in pixels (default: width / 4 for a hemisphere, width / 2 for a sphere)")
      ->type_name(help::rangeName(1, mapio::kMaxMapHeight))
      ->check(help::quiet(CLI::Range(1, mapio::kMaxMapHeight)));
  const std::map<std::string, MapLayout> layouts{{"sphere", MapLayout::Sphere},
                                                 {"hemisphere", MapLayout::Hemisphere}};
  cmd->add_option("--layout", o->layout, "hemisphere (default: the camera's polar map) | sphere")
      ->transform(CLI::CheckedTransformer(layouts, CLI::ignore_case));
  cmd->add_option("--mask-out", o->maskOut, "Also write the valid-pixel mask (8-bit .png)");
  cmd->add_option("--gain", o->gain, "Linear gain the frame was taken with")
      ->capture_default_str()
      ->check(help::quiet(CLI::PositiveNumber));
  cmd->callback([o, &exitCode] { exitCode = runApply(*o); });
}

}  // namespace vem::calibtool
