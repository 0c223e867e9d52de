// `vemcalib simulate plate`: what a known ("truth") plate camera sees for its calibration
// (calib/core/plate_board_simulation.h): checkerboard views for `plate intrinsics`, the board on
// the floor for `plate pose`, a distant marker for `plate probe-yaw` and grey patches for
// `plate colour`, so the whole plate calibration runs without a camera.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <CLI/CLI.hpp>
#include <glm/matrix.hpp>

#include "board_argument.h"
#include "calib/core/plate_board_simulation.h"
#include "calib/core/plate_pose_fit.h"
#include "calib/core/plate_probe_yaw.h"
#include "calib/io/plate_camera_file.h"
#include "calib/io/plate_colour_file.h"
#include "calib/io/raw_frame_file.h"
#include "camera_output.h"
#include "commands.h"
#include "plate_output.h"
#include "util/cli_value_names.h"

namespace vem::calibtool {
namespace {

namespace fs = std::filesystem;

// The marker: the pixel 80 % across and 12 % down the plate image.
constexpr double kMarkerX = 0.8, kMarkerY = 0.12;
// Grey patches: the brightest reads 0.8 of full scale in the plate's strongest channel.
constexpr double kBrightestPlate = 0.8;
// The floor board may be seen at a grazing angle, up to this far off its normal.
constexpr double kMaxFloorObliquityDeg = 75.0;
constexpr std::array<double, 6> kPatchLevels{0.05, 0.1, 0.2, 0.35, 0.6, 1.0};

struct SimulatePlateOptions {
  std::string camera;
  BoardOptions board;
  std::string floorBoard;      // default: --board
  double floorSquareMm = 0.0;  // default: --square
  int views = 12;
  std::uint64_t seed = 1;
  double noiseCode = 1.0;
  std::string out;
};

struct Simulation {
  const calib::PlateCamera& truth;
  calib::SimulationOptions options;
  double whiteCode;
};

std::expected<std::string, std::string> writeView(const Simulation& sim,
                                                  const calib::Checkerboard& board,
                                                  const calib::BoardPose& pose, std::uint64_t seed,
                                                  const fs::path& file) {
  calib::SimulationOptions options = sim.options;
  options.noise.seed = seed;
  const RawFrame frame = calib::simulatePlateBoardView(
      board, pose, sim.truth, options, sim.whiteCode, sim.whiteCode / kBoardPrintContrast);
  if (auto saved = calib::io::saveRawFrame(frame, file); !saved)
    return std::unexpected(saved.error().message);
  return file.string();
}

// The grey patches of the truth's colour match, with a deterministic 0.2 % wobble.
std::vector<calib::ColourPatch> colourPatches(const calib::PlateColourMatch& match) {
  const double gainMax = std::max({match.gainRgb[0], match.gainRgb[1], match.gainRgb[2]});
  std::vector<calib::ColourPatch> patches;
  for (std::size_t i = 0; i < kPatchLevels.size(); ++i) {
    const double radiance = kPatchLevels[i] * kBrightestPlate / gainMax;
    calib::ColourPatch patch{fmt::format("g{}", i + 1), {}, {}};
    for (std::size_t c = 0; c < 3; ++c) {
      patch.probeRadianceCdM2[c] = radiance * (1.0 + 0.03 * double(c));  // a slightly blue grey
      const double wobble = 1.0 + 0.002 * std::sin(double(7 * i + 3 * c + 1));
      patch.plateLinear[c] = match.gainRgb[c] * patch.probeRadianceCdM2[c] * wobble;
    }
    patches.push_back(patch);
  }
  return patches;
}

int runSimulatePlate(const SimulatePlateOptions& o) {
  const auto truth = calib::io::loadPlateCameraFile(o.camera);
  if (!truth) return reportFailure(truth.error().message);
  if (!truth->pose)
    return reportFailure(o.camera +
                         ": the plate camera has no pose (a truth camera needs one to "
                         "film the floor board)");
  std::error_code error;
  fs::create_directories(o.out, error);
  if (error)
    return reportFailure(fmt::format("{}: cannot create the folder ({})", o.out, error.message()));
  const calib::Checkerboard board = boardOf(o.board.size, o.board.squareMm);
  const calib::Checkerboard floor =
      boardOf(o.floorBoard.empty() ? o.board.size : o.floorBoard,
              o.floorSquareMm > 0.0 ? o.floorSquareMm : o.board.squareMm);
  const calib::BoardPose floorPose = calib::floorBoardPose(*truth->pose);
  if (!calib::plateSeesWholeBoard(floor, floorPose, truth->intrinsics, kMaxFloorObliquityDeg))
    return reportFailure(
        fmt::format("{}: the truth camera does not see the whole {}x{} floor "
                    "board with its margin; change its pose or the board",
                    o.camera, floor.innerCols, floor.innerRows));
  Simulation sim{*truth, {}, kBoardWhiteCodeFraction * truth->camera.pixelFormat.maxCode()};
  sim.options.noise.readNoiseCode = o.noiseCode;
  std::vector<std::string> files;
  const auto poses = calib::plateBoardPoses(board, truth->intrinsics, o.views, o.seed);
  for (std::size_t i = 0; i < poses.size(); ++i) {
    auto file = writeView(sim, board, poses[i], o.seed + i,
                          fs::path(o.out) / fmt::format("plate-board-{:02}.png", i));
    if (!file) return reportFailure(file.error());
    files.push_back(*file);
  }
  const auto floorFile =
      writeView(sim, floor, floorPose, o.seed + 1000, fs::path(o.out) / "plate-floor.png");
  if (!floorFile) return reportFailure(floorFile.error());
  const calib::CameraIdentity& camera = truth->camera;
  fmt::print("wrote {} views of the board ({}): {} to {}, {} x {} {}, read noise {:g} codes\n",
             files.size(), describeBoard(board), files.front(), files.back(), camera.sensorWidthPx,
             camera.sensorHeightPx, pixelFormatName(camera.pixelFormat), o.noiseCode);
  fmt::print("wrote {}: the board on the floor ({}), first inner corner at the world's origin\n",
             *floorFile, describeBoard(floor));
  const fs::path plateFile = fs::path(o.out) / "plate.toml";
  fmt::print(
      "next: vemcalib plate intrinsics --image {} --board {}x{} --square {:g} --model {} "
      "--out {}\n",
      fmt::join(files, " "), board.innerCols, board.innerRows, board.squareMm,
      calib::plateLensModelName(truth->intrinsics.model), plateFile.string());
  fmt::print("next: vemcalib plate pose --image {} --board {}x{} --square {:g} --out {}\n",
             *floorFile, floor.innerCols, floor.innerRows, floor.squareMm, plateFile.string());
  // A distant marker: its pixel in the plate image and its direction in the probe's map.
  const calib::PlateIntrinsics& in = truth->intrinsics;
  const glm::dvec2 markerPx(std::round(kMarkerX * in.widthPx * 10.0) / 10.0,
                            std::round(kMarkerY * in.heightPx * 10.0) / 10.0);
  const glm::dvec3 markerPlate = calib::worldDirectionFromPlate(in, *truth->pose, markerPx);
  const glm::dvec3 markerProbe =
      glm::transpose(calib::plateWorldFromProbeWorld(truth->probeYawRad)) * markerPlate;
  fmt::print(
      "marker: a distant lamp at pixel ({:g}, {:g}) of the plate image, at azimuth {:.4f} "
      "deg, elevation {:.4f} deg in the probe's map (probe yaw {:g} deg)\n",
      markerPx.x, markerPx.y, calib::azimuthRad(markerProbe) * kDegPerRad,
      calib::elevationRad(markerProbe) * kDegPerRad, truth->probeYawRad * kDegPerRad);
  fmt::print(
      "next: vemcalib plate probe-yaw --pixel {:g},{:g} --probe-direction {:.4f},{:.4f} "
      "--out {}\n",
      markerPx.x, markerPx.y, calib::azimuthRad(markerProbe) * kDegPerRad,
      calib::elevationRad(markerProbe) * kDegPerRad, plateFile.string());
  if (truth->colour) {
    const fs::path patchFile = fs::path(o.out) / "plate-colour.toml";
    const std::vector<calib::ColourPatch> patches = colourPatches(*truth->colour);
    if (auto saved = calib::io::saveColourPatchFile(patches, patchFile); !saved)
      return reportFailure(saved.error().message);
    fmt::print(
        "wrote {}: {} grey patches, probe radiance and plate value through the truth's "
        "gains (0.2 % wobble)\n",
        patchFile.string(), patches.size());
    fmt::print("next: vemcalib plate colour --patches {} --out {}\n", patchFile.string(),
               plateFile.string());
  }
  return EXIT_SUCCESS;
}

constexpr const char* kSimulatePlateFooter = R"(Example:
  vemcalib simulate plate --camera config/plate-camera-example.toml --board 9x6 --square 60 --floor-square 100 --out sim
Writes DIR/plate-board-00.png, plate-board-01.png ...: the truth plate camera's views of a
checkerboard (--board counts inner corners), held at spread positions over the image and tilted
20 to 45 degrees, with a white margin one square wide; DIR/plate-floor.png: the board lying on the
floor at the world's origin (--floor-board and --floor-square, by default the same board), seen
from the truth's pose; and, when the truth has a colour section, DIR/plate-colour.toml: six grey
patches through its gains. The board's white reads 70 % up the code range and its black 16 times
darker, with Gaussian read noise of --noise codes. Then prints the marker a distant lamp makes in
both cameras and the `vemcalib plate` commands that calibrate from all of it.)";

}  // namespace

void addSimulatePlateCommand(CLI::App& simulate, int& exitCode) {
  auto o = std::make_shared<SimulatePlateOptions>();
  CLI::App* cmd = simulate.add_subcommand(
      "plate",
      "Write what the truth plate camera sees for vemcalib plate (boards, floor, marker, "
      "patches)");
  cmd->footer(kSimulatePlateFooter);
  cmd->add_option("--camera", o->camera, "Truth plate-camera file (needs a pose)")->required();
  addBoardOptions(cmd, o->board);
  addBoardSizeOption(cmd, "--floor-board", o->floorBoard,
                     "The floor board's inner corners (default: --board)");
  cmd->add_option("--floor-square", o->floorSquareMm,
                  "Side of a square of the floor board, mm (default: --square)")
      ->check(help::quiet(CLI::PositiveNumber));
  addSimulatedViewOptions(cmd, "Number of views for the intrinsics", o->views, o->seed,
                          o->noiseCode);
  cmd->add_option("--out", o->out, "Folder for the images and files")->required();
  cmd->callback([o, &exitCode] { exitCode = runSimulatePlate(*o); });
}

}  // namespace vem::calibtool
