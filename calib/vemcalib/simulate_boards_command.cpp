// `vemcalib simulate boards`: the views of a checkerboard a known ("truth") camera takes, for
// `vemcalib fisheye` (calib/core/checkerboard.h). The boards are placed to cover the lens's image
// circle from its centre to near its edge.
#include <algorithm>
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

#include "board_argument.h"
#include "calib/core/camera_simulator.h"
#include "calib/core/checkerboard.h"
#include "calib/io/camera_file.h"
#include "calib/io/raw_frame_file.h"
#include "camera_output.h"
#include "commands.h"

namespace vem::calibtool {
namespace {

namespace fs = std::filesystem;

struct SimulateBoardsOptions {
  std::string camera;
  BoardOptions board;
  int views = 12;
  std::uint64_t seed = 1;
  double noiseCode = 2.0;
  std::string out;
};

std::expected<calib::CameraCalibration, std::string> loadTruth(const std::string& path) {
  auto truth = calib::io::loadCameraFile(path);
  if (!truth) return std::unexpected(truth.error().message);
  if (!truth->photometric || !truth->lens)
    return std::unexpected(path +
                           ": the camera needs photometric and geometric sections (a truth camera "
                           "simulates codes through its response and rays through its lens)");
  return std::move(*truth);
}

// The white the board reflects, in cd/m2: kBoardWhiteCodeFraction up the code range on every
// channel.
double whiteLuminance(const calib::CameraCalibration& truth, const calib::SimulationOptions& sim) {
  const calib::PhotometricCalibration& p = *truth.photometric;
  const double code =
      p.blackLevelCode + kBoardWhiteCodeFraction * (p.saturationCode - p.blackLevelCode);
  double white = INFINITY;
  for (int c = 0; c < truth.camera.pixelFormat.channels; ++c)
    white = std::min(white, calib::luminanceFromCode(p, c, code, sim.exposureUs, sim.gain));
  return white;
}

// DIR/board-NN.png, one per pose, a noise draw each.
std::expected<std::vector<std::string>, std::string> writeViews(
    const SimulateBoardsOptions& o, const calib::CameraCalibration& truth,
    const calib::Checkerboard& board) {
  const calib::CameraIdentity& camera = truth.camera;
  const std::vector<calib::BoardPose> poses = calib::boardPosesCoveringLens(
      board, *truth.lens, camera.sensorWidthPx, camera.sensorHeightPx, o.views, o.seed);
  calib::SimulationOptions simulation;
  simulation.noise.readNoiseCode = o.noiseCode;
  const double white = whiteLuminance(truth, simulation);
  std::vector<std::string> files;
  for (std::size_t i = 0; i < poses.size(); ++i) {
    simulation.noise.seed = o.seed + i;
    const RawFrame frame = calib::simulateBoardView(board, poses[i], truth, simulation, white,
                                                    white / kBoardPrintContrast);
    files.push_back((fs::path(o.out) / fmt::format("board-{:02}.png", i)).string());
    if (auto saved = calib::io::saveRawFrame(frame, files.back()); !saved)
      return std::unexpected(saved.error().message);
  }
  return files;
}

int runSimulateBoards(const SimulateBoardsOptions& o) {
  const auto truth = loadTruth(o.camera);
  if (!truth) return reportFailure(truth.error());
  const calib::Checkerboard board = boardOf(o.board.size, o.board.squareMm);
  std::error_code error;
  fs::create_directories(o.out, error);
  if (error)
    return reportFailure(fmt::format("{}: cannot create the folder ({})", o.out, error.message()));
  const auto files = writeViews(o, *truth, board);
  if (!files) return reportFailure(files.error());
  const calib::CameraIdentity& camera = truth->camera;
  fmt::print("wrote {} views of the board ({}): {} to {}, {} x {} {}, read noise {:g} codes\n",
             files->size(), describeBoard(board), files->front(), files->back(),
             camera.sensorWidthPx, camera.sensorHeightPx, pixelFormatName(camera.pixelFormat),
             o.noiseCode);
  fmt::print("next: vemcalib fisheye --image {} --board {}x{} --square {:g} --fov {:g} --out {}\n",
             fmt::join(*files, " "), board.innerCols, board.innerRows, board.squareMm,
             2.0 * truth->lens->maxThetaRad * 180.0 / std::numbers::pi,
             (fs::path(o.out) / "camera.toml").string());
  return EXIT_SUCCESS;
}

constexpr const char* kSimulateBoardsFooter = R"(Example:
  vemcalib simulate boards --camera config/camera-example.toml --board 9x6 --square 60 --views 12 --out sim
  vemcalib fisheye --image sim/board-*.png --board 9x6 --square 60 --fov 190 --out sim/camera.toml
Writes DIR/board-00.png, board-01.png ...: the truth camera's views of the board (--board counts
inner corners), with a white margin of one square around it, in front of a grey background. The
first view faces the lens's centre; later ones move outward at spread azimuths, the last 40 %
along the image circle's rim, tilted 16 to 40 degrees; every board lies wholly inside the image
circle and the sensor. The board's white reads 70 % up the code range and its black 16 times
darker, through the camera's response, with Gaussian read noise of --noise codes. Then prints the
`vemcalib fisheye` command that calibrates from them.)";

}  // namespace

void addSimulateBoardsCommand(CLI::App& simulate, int& exitCode) {
  auto o = std::make_shared<SimulateBoardsOptions>();
  CLI::App* cmd = simulate.add_subcommand(
      "boards", "Write the views of a checkerboard the truth camera takes, for vemcalib fisheye");
  cmd->footer(kSimulateBoardsFooter);
  cmd->add_option("--camera", o->camera,
                  "Truth camera file (needs photometric and geometric sections)")
      ->required();
  addBoardOptions(cmd, o->board);
  addSimulatedViewOptions(cmd, "Number of views", o->views, o->seed, o->noiseCode);
  cmd->add_option("--out", o->out, "Folder for board-NN.png")->required();
  cmd->callback([o, &exitCode] { exitCode = runSimulateBoards(*o); });
}

}  // namespace vem::calibtool
