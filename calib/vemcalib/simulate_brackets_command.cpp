// `vemcalib simulate brackets`: the exposure bracket an LDR camera (the truth camera file) takes of
// an environment map, one 8-bit frame per exposure, for `vemcalib response` (paper 002's
// bracketing; calib/core/bracket_simulation.h). A truth camera without a tabulated response gets
// the built-in LDR curve.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include "calib/core/bracket_simulation.h"
#include "calib/io/camera_file.h"
#include "calib/io/raw_frame_file.h"
#include "camera_output.h"
#include "commands.h"
#include "core/color.h"
#include "mapio/map_file.h"

namespace vem::calibtool {
namespace {

namespace fs = std::filesystem;

struct SimulateBracketsOptions {
  std::string camera;
  std::string map;
  std::vector<double> exposuresUs;
  std::string out;
  std::uint64_t seed = 1;
};

// Median luminance of the map's upper half (the sky side a zenith-looking fisheye sees).
double upperMedianLuminance(const EnvMap& map) {
  std::vector<double> values;
  for (int y = 0; y < std::max(1, map.height / 2); ++y) {
    for (int x = 0; x < map.width; ++x) values.push_back(std::max(0.0, luminance(map.at(x, y))));
  }
  const auto middle = values.begin() + std::ptrdiff_t(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

double geometricMean(const std::vector<double>& values) {
  double sumLog = 0.0;
  for (const double v : values) sumLog += std::log(v);
  return std::exp(sumLog / double(values.size()));
}

// The truth camera ready for brackets: a lens (the file's, which it must have) and an 8-bit
// tabulated response (the file's, else the built-in curve placed so that the map's median reads
// mid-curve at the bracket's middle exposure).
std::expected<calib::CameraCalibration, std::string> bracketCamera(const SimulateBracketsOptions& o,
                                                                   const EnvMap& map) {
  auto truth = calib::io::loadCameraFile(o.camera);
  if (!truth) return std::unexpected(truth.error().message);
  if (!truth->lens) {
    return std::unexpected(o.camera +
                           ": the camera has no geometric section (a truth camera needs "
                           "its lens to look at the map)");
  }
  const bool tabulated = truth->photometric && std::holds_alternative<calib::TabulatedResponse>(
                                                   truth->photometric->response);
  if (tabulated) {
    if (truth->camera.pixelFormat.bits != 8) {
      return std::unexpected(
          fmt::format("{}: the camera's table is for {} codes; brackets for "
                      "`vemcalib response` need an 8-bit camera",
                      o.camera, pixelFormatName(truth->camera.pixelFormat)));
    }
    return std::move(*truth);
  }
  const double median = upperMedianLuminance(map);
  if (!(median > 0.0)) return std::unexpected(o.map + ": the map's upper half is black");
  const double scale = calib::scaleForCode(calib::ldrCameraResponse(), calib::kLdrMidCode, median,
                                           geometricMean(o.exposuresUs));
  truth->photometric = calib::ldrCameraPhotometric(scale);
  truth->camera.pixelFormat.bits = 8;
  spdlog::info(
      "{} has no tabulated response: using the built-in LDR curve, {} 8-bit, scale {:.4g} "
      "cd/m2 us (the map's median {:.3g} reads code {} at {:.4g} us)",
      o.camera, truth->camera.pixelFormat.channels == 1 ? "Mono" : "RGB", scale, median,
      calib::kLdrMidCode, geometricMean(o.exposuresUs));
  return std::move(*truth);
}

std::optional<std::string> exposureProblem(const std::vector<double>& exposuresUs) {
  std::set<double> seen;
  for (const double e : exposuresUs) {
    if (!(e > 0.0) || !std::isfinite(e)) {
      return fmt::format("--exposures: {} is not a positive number of microseconds", e);
    }
    if (!seen.insert(e).second) return fmt::format("--exposures: {:g} us is listed twice", e);
  }
  return std::nullopt;
}

int runSimulateBrackets(const SimulateBracketsOptions& o) {
  if (auto problem = exposureProblem(o.exposuresUs)) return reportFailure(*problem);
  const auto map = mapio::loadMap(o.map);
  if (!map) return reportFailure(map.error().message);
  const auto truth = bracketCamera(o, *map);
  if (!truth) return reportFailure(truth.error());
  std::error_code error;
  fs::create_directories(o.out, error);
  if (error) {
    return reportFailure(fmt::format("{}: cannot create the folder ({})", o.out, error.message()));
  }
  calib::SimulationOptions simulation;
  simulation.noise = calib::ldrSensorNoise(o.seed);
  const auto frames =
      calib::simulateBracket(calib::radianceFromMap(*map), *truth, o.exposuresUs, simulation);
  std::vector<std::string> tokens;
  for (const RawFrame& frame : frames) {
    const fs::path path = fs::path(o.out) / fmt::format("bracket-{:g}.png", frame.exposureUs);
    if (auto saved = calib::io::saveRawFrame(frame, path); !saved) {
      return reportFailure(saved.error().message);
    }
    tokens.push_back(fmt::format("{}@{:g}", path.string(), frame.exposureUs));
  }
  spdlog::info("wrote {} frames of {} x {} {} to {}", frames.size(), frames.front().width,
               frames.front().height, pixelFormatName(frames.front().format), o.out);
  fmt::print("{}\n", fmt::join(tokens, " "));
  return EXIT_SUCCESS;
}

constexpr const char* kSimulateBracketsFooter = R"(Example:
  vemcalib simulate brackets --camera config/camera-example.toml \
      --map ../shared/data/hdri/lobby.exr --exposures 250,1000,3000,16000 --seed 1 --out brackets
    (prints: brackets/bracket-250.png@250 brackets/bracket-1000.png@1000 ...)
  vemcalib response --bracket brackets/bracket-250.png@250 brackets/bracket-1000.png@1000 \
      brackets/bracket-3000.png@3000 brackets/bracket-16000.png@16000 --out camera.toml
Writes DIR/bracket-<EXPOSURE_US>.png, one 8-bit frame per exposure (at unit gain, with read and
shot noise, a different noise draw per frame), and prints their FILE@EXPOSURE_US list on one line,
ready for `vemcalib response --bracket`. The map's values are luminance in cd/m2 per channel.
TRUTH needs a lens (its geometric section). When its response is not a table, the built-in LDR
curve (sRGB-like, with toe and shoulder) replaces it, 8-bit, scaled so that the map's median reads
code 128 at the geometric mean of the exposures.)";

}  // namespace

void addSimulateBracketsCommand(CLI::App& simulate, int& exitCode) {
  auto o = std::make_shared<SimulateBracketsOptions>();
  CLI::App* cmd = simulate.add_subcommand(
      "brackets", "Write the exposure bracket an LDR truth camera takes of an environment map");
  cmd->footer(kSimulateBracketsFooter);
  cmd->add_option("--camera", o->camera, "Truth camera file (needs its geometric section)")
      ->required();
  cmd->add_option("--map", o->map, "Environment map (.exr, .hdr, .pfm)")->required();
  cmd->add_option("--exposures", o->exposuresUs, "Exposures in microseconds, e.g. 250,1000,4000")
      ->required()
      ->delimiter(',');
  cmd->add_option("--out", o->out, "Folder for bracket-<EXPOSURE_US>.png")->required();
  cmd->add_option("--seed", o->seed, "Random seed (the same seed gives the same frames)")
      ->capture_default_str();
  cmd->callback([o, &exitCode] { exitCode = runSimulateBrackets(*o); });
}

}  // namespace vem::calibtool
