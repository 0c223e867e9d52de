// `vemcalib simulate`: frames a known ("truth") camera would deliver, to try the calibration
// without a camera and to test it. This file holds the `simulate` command itself and two of its
// subcommands: `patches` (a grey-patch chart for `vemcalib photometric`) and `frame` (the camera
// in front of an environment map, for `vemcalib apply`).
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "calib/core/camera_simulator.h"
#include "calib/io/camera_file.h"
#include "calib/io/patch_file.h"
#include "calib/io/raw_frame_file.h"
#include "camera_output.h"
#include "commands.h"
#include "util/cli_value_names.h"
#include "mapio/map_file.h"

namespace vem::calibtool {
namespace {

namespace fs = std::filesystem;

constexpr int kFitPatches = 6;
constexpr double kChartLowCdM2 = 1.0;     // a chart's patches lie in 1 .. 1e4 cd/m2 when the
constexpr double kChartHighCdM2 = 1.0e4;  // camera reads that range comfortably

struct SimulatePatchesOptions {
  std::string camera;
  std::string out;
  int frames = 3;
  double noiseCode = 2.0;
  std::uint64_t seed = 1;
};

struct SimulateFrameOptions {
  std::string camera;
  std::string map;
  std::string out;
  std::optional<MapLayout> layout;
  double scale = 1.0;
  double noiseCode = 2.0;
  std::uint64_t seed = 1;
};

// The truth camera, refused without the sections the simulation needs.
std::expected<calib::CameraCalibration, std::string> loadTruth(const std::string& path,
                                                               bool needsLens) {
  auto truth = calib::io::loadCameraFile(path);
  if (!truth) return std::unexpected(truth.error().message);
  if (!truth->photometric)
    return std::unexpected(path +
                           ": the camera has no photometric section (a truth camera needs "
                           "its response to simulate codes)");
  if (needsLens && !truth->lens)
    return std::unexpected(path +
                           ": the camera has no geometric section (a truth camera needs its "
                           "lens to simulate a frame)");
  return std::move(*truth);
}

// The luminances every channel reads well, 10 % of the code range in from black and saturation.
std::pair<double, double> comfortableRange(const calib::CameraCalibration& truth,
                                           double exposureUs) {
  const calib::PhotometricCalibration& p = *truth.photometric;
  const double span = p.saturationCode - p.blackLevelCode;
  double low = 0.0, high = INFINITY;
  for (int c = 0; c < truth.camera.pixelFormat.channels; ++c) {
    low = std::max(low,
                   calib::luminanceFromCode(p, c, p.blackLevelCode + 0.1 * span, exposureUs, 1.0));
    high = std::min(high,
                    calib::luminanceFromCode(p, c, p.saturationCode - 0.1 * span, exposureUs, 1.0));
  }
  return {low, high};
}

// Six fit patches spaced evenly in log luminance, two check patches between them, on a 4 x 2 grid.
std::vector<calib::PatchSpec> patchChart(const calib::CameraCalibration& truth, double exposureUs) {
  const auto [readLow, readHigh] = comfortableRange(truth, exposureUs);
  double low = std::max(kChartLowCdM2, readLow), high = std::min(kChartHighCdM2, readHigh);
  if (!(high >= 100.0 * low)) std::tie(low, high) = std::pair{readLow, readHigh};
  const auto luminance = [&](double step) {
    return low * std::pow(high / low, step / (kFitPatches - 1));
  };
  std::vector<calib::PatchSpec> chart;
  for (int i = 0; i < kFitPatches; ++i)
    chart.push_back({fmt::format("p{}", i + 1), 0, 0, 0, 0, luminance(i), false});
  chart.push_back({"c1", 0, 0, 0, 0, luminance(1.5), true});
  chart.push_back({"c2", 0, 0, 0, 0, luminance(3.5), true});
  const int cellWidth = truth.camera.sensorWidthPx / 4,
            cellHeight = truth.camera.sensorHeightPx / 2;
  const int side = std::max(1, std::min(cellWidth, cellHeight) / 2);
  for (std::size_t i = 0; i < chart.size(); ++i) {
    chart[i].x = int(i % 4) * cellWidth + (cellWidth - side) / 2;
    chart[i].y = int(i / 4) * cellHeight + (cellHeight - side) / 2;
    chart[i].width = chart[i].height = side;
  }
  return chart;
}

std::string nextPhotometricCommand(const SimulatePatchesOptions& o,
                                   const calib::CameraCalibration& truth,
                                   const std::vector<std::string>& frames) {
  const calib::PhotometricCalibration& p = *truth.photometric;
  const std::string model = calib::responseModelName(p.response);
  return fmt::format(
      "vemcalib photometric --frame {} --patches {} --bits {} --black-level {:g} --saturation "
      "{:g}{} "
      "--out {}",
      fmt::join(frames, " "), (fs::path(o.out) / "patches.toml").string(),
      truth.camera.pixelFormat.bits, p.blackLevelCode, p.saturationCode,
      model == "linear" ? " --model linear" : "", (fs::path(o.out) / "camera.toml").string());
}

// DIR/patches-K.png, K = 1 .. frames: the chart through the truth camera, a noise draw each.
std::expected<std::vector<std::string>, std::string> writeChartFrames(
    const SimulatePatchesOptions& o, const calib::CameraCalibration& truth,
    const std::vector<calib::PatchSpec>& chart, calib::SimulationOptions simulation) {
  const double background =
      std::sqrt(chart.front().luminanceCdM2 * chart[kFitPatches - 1].luminanceCdM2);
  std::vector<std::string> frames;
  for (int k = 1; k <= o.frames; ++k) {
    simulation.noise.seed = o.seed + std::uint64_t(k - 1);
    const RawFrame frame = calib::simulatePatchFrame(chart, background, truth, simulation);
    frames.push_back((fs::path(o.out) / fmt::format("patches-{}.png", k)).string());
    if (auto saved = calib::io::saveRawFrame(frame, frames.back()); !saved)
      return std::unexpected(saved.error().message);
  }
  return frames;
}

int runSimulatePatches(const SimulatePatchesOptions& o) {
  const auto truth = loadTruth(o.camera, false);
  if (!truth) return reportFailure(truth.error());
  std::error_code error;
  fs::create_directories(o.out, error);
  if (error)
    return reportFailure(fmt::format("{}: cannot create the folder ({})", o.out, error.message()));
  calib::SimulationOptions simulation;
  simulation.noise.readNoiseCode = o.noiseCode;
  const std::vector<calib::PatchSpec> chart = patchChart(*truth, simulation.exposureUs);
  const fs::path patchesPath = fs::path(o.out) / "patches.toml";
  if (auto saved = calib::io::savePatchFile(chart, patchesPath); !saved)
    return reportFailure(saved.error().message);
  const auto frames = writeChartFrames(o, *truth, chart, simulation);
  if (!frames) return reportFailure(frames.error());
  fmt::print("wrote {}: {} fit patches from {:.3g} to {:.3g} cd/m2 and 2 check patches\n",
             patchesPath.string(), kFitPatches, chart.front().luminanceCdM2,
             chart[kFitPatches - 1].luminanceCdM2);
  fmt::print("wrote {}: {} x {} {}, read noise {:g} codes\n", fmt::join(*frames, ", "),
             truth->camera.sensorWidthPx, truth->camera.sensorHeightPx,
             pixelFormatName(truth->camera.pixelFormat), o.noiseCode);
  fmt::print("next: {}\n", nextPhotometricCommand(o, *truth, *frames));
  return EXIT_SUCCESS;
}

// The walk-through's next step (docs/calibration.md): the camera fitted in the earlier steps, not
// the truth, turns the frame just written into a map. The fitting steps write DIR/camera.toml
// beside their frames; when that file is there (and is not the truth) it is named, else the hint
// says which file it means.
std::string nextApplyCommand(const SimulateFrameOptions& o) {
  namespace fs = std::filesystem;
  const fs::path folder = fs::path(o.out).parent_path();
  const fs::path fitted = folder / "camera.toml";
  const auto applyWith = [&](const std::string& camera) {
    return fmt::format("vemcalib apply --camera {} --frame {} --out {}", camera, o.out,
                       (folder / "polar.exr").string());
  };
  std::error_code ec;
  if (fs::is_regular_file(fitted, ec) && !fs::equivalent(fitted, o.camera, ec)) {
    return applyWith(fitted.string());
  }
  return applyWith("CAMERA") +
         fmt::format(", CAMERA being the camera file you fitted (e.g. {}; {} is the truth)",
                     fitted.string(), o.camera);
}

int runSimulateFrame(const SimulateFrameOptions& o) {
  const auto truth = loadTruth(o.camera, true);
  if (!truth) return reportFailure(truth.error());
  const auto map = mapio::loadMap(o.map, o.layout);
  if (!map) return reportFailure(map.error().message);
  calib::SimulationOptions simulation;
  simulation.radianceScale = o.scale;
  simulation.noise.readNoiseCode = o.noiseCode;
  simulation.noise.seed = o.seed;
  const RawFrame frame = calib::simulateFrame(calib::radianceFromMap(*map), *truth, simulation);
  if (auto saved = calib::io::saveRawFrame(frame, o.out); !saved)
    return reportFailure(saved.error().message);
  fmt::print(
      "wrote {}: {} x {} {}, the camera in front of {} (x {:g} cd/m2 per map unit), {:g} us\n",
      o.out, frame.width, frame.height, pixelFormatName(frame.format), o.map, o.scale,
      frame.exposureUs);
  fmt::print("next: {}\n", nextApplyCommand(o));
  return EXIT_SUCCESS;
}

constexpr const char* kSimulateFooter = R"(Example:
  vemcalib simulate patches --camera config/camera-example.toml --out sim
  vemcalib simulate frame --camera config/camera-example.toml --map ../shared/data/hdri/park.exr --out sim/sky.png
TRUTH is a camera file that describes the simulated camera (config/camera-example.toml is one);
calibrating from its frames should give it back.)";

constexpr const char* kPatchesFooter = R"(Example:
  vemcalib simulate patches --camera config/camera-example.toml --out sim --frames 3 --noise 2
Writes DIR/patches.toml (6 fit patches spread evenly in log luminance over what the camera reads
well, within 1 to 1e4 cd/m2 when it can, and 2 check patches between them) and DIR/patches-K.png,
the frames the truth camera takes of that chart at 1000 us (16-bit PNG for more than 8 bits), then
prints the `vemcalib photometric` command that calibrates from them.)";

constexpr const char* kFrameFooter = R"(Example:
  vemcalib simulate frame --camera config/camera-example.toml --map ../shared/data/hdri/park.exr \
      --scale 1 --out sim/raw.png
  vemcalib apply --camera sim/camera.toml --frame sim/raw.png --out sim/polar.exr
The map's values times --scale are luminance in cd/m2 per channel; the camera looks at it through
its lens and orientation, at 1000 us and gain 1, with Gaussian read noise of --noise codes.
The next step applies the camera you fitted (the earlier steps' DIR/camera.toml) to the frame.)";

}  // namespace

void addSimulatePatchesCommand(CLI::App& simulate, int& exitCode) {
  auto o = std::make_shared<SimulatePatchesOptions>();
  CLI::App* cmd = simulate.add_subcommand(
      "patches", "Write a grey-patch chart and the frames the truth camera takes of it");
  cmd->footer(kPatchesFooter);
  cmd->add_option("--camera", o->camera, "Truth camera file (needs its photometric section)")
      ->required();
  cmd->add_option("--out", o->out, "Folder for patches.toml and patches-K.png")->required();
  cmd->add_option("--frames", o->frames, "Number of frames")
      ->capture_default_str()
      ->type_name(help::rangeName(1, 100))
      ->check(help::quiet(CLI::Range(1, 100)));
  cmd->add_option("--noise", o->noiseCode, "Read noise, codes (standard deviation)")
      ->capture_default_str()
      ->check(help::quiet(CLI::NonNegativeNumber));
  cmd->add_option("--seed", o->seed, "Random seed (the same seed gives the same frames)")
      ->capture_default_str();
  cmd->callback([o, &exitCode] { exitCode = runSimulatePatches(*o); });
}

void addSimulateFrameCommand(CLI::App& simulate, int& exitCode) {
  auto o = std::make_shared<SimulateFrameOptions>();
  CLI::App* cmd = simulate.add_subcommand(
      "frame", "Write the raw frame the truth camera takes of an environment map");
  cmd->footer(kFrameFooter);
  cmd->add_option("--camera", o->camera,
                  "Truth camera file (needs photometric and geometric sections)")
      ->required();
  cmd->add_option("--map", o->map, "Environment map (.exr, .hdr, .pfm)")->required();
  cmd->add_option("--out", o->out, "Raw frame to write (.png, .tif, .pgm/.ppm)")->required();
  const std::map<std::string, MapLayout> layouts{{"sphere", MapLayout::Sphere},
                                                 {"hemisphere", MapLayout::Hemisphere}};
  cmd->add_option("--layout", o->layout, "sphere | hemisphere (default: from the map's shape)")
      ->transform(CLI::CheckedTransformer(layouts, CLI::ignore_case));
  cmd->add_option("--scale", o->scale, "Luminance in cd/m2 of one map unit")
      ->capture_default_str()
      ->check(help::quiet(CLI::PositiveNumber));
  cmd->add_option("--noise", o->noiseCode, "Read noise, codes (standard deviation)")
      ->capture_default_str()
      ->check(help::quiet(CLI::NonNegativeNumber));
  cmd->add_option("--seed", o->seed, "Random seed")->capture_default_str();
  cmd->callback([o, &exitCode] { exitCode = runSimulateFrame(*o); });
}

void addSimulateCommand(CLI::App& app, int& exitCode) {
  CLI::App* simulate = app.add_subcommand(
      "simulate", "Simulate calibration frames and raw frames from a known (truth) camera file");
  simulate->footer(kSimulateFooter);
  simulate->require_subcommand(1);
  addSimulatePatchesCommand(*simulate, exitCode);
  addSimulateFrameCommand(*simulate, exitCode);
  addSimulateBoardsCommand(*simulate, exitCode);
  addSimulateBracketsCommand(*simulate, exitCode);
  addSimulatePlateCommand(*simulate, exitCode);
}

}  // namespace vem::calibtool
