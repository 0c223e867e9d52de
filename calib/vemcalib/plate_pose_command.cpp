// `vemcalib plate pose`: the plate camera's pose in the world (calib/core/plate_pose_fit.h) from
// one image of a checkerboard lying on the floor, through the intrinsics already in the
// plate-camera file; written into that file, or refused with nothing written.
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include "board_argument.h"
#include "board_views.h"
#include "calib/core/plate_pose_fit.h"
#include "calib/io/plate_camera_file.h"
#include "camera_output.h"
#include "commands.h"
#include "plate_output.h"

namespace vem::calibtool {
namespace {

struct PlatePoseOptions {
  std::string image;
  BoardOptions board;
  std::string out;
  double maxRmsPx = 1.0;
  std::optional<int> bits;
};

int runPlatePose(const PlatePoseOptions& o) {
  auto plate = loadPlateToUpdate(o.out, "the pose needs the plate camera's intrinsics");
  if (!plate) return reportFailure(plate.error());
  const calib::Checkerboard board = boardOf(o.board.size, o.board.squareMm);
  const auto views =
      findBoardsInImages({o.image}, board, o.bits.value_or(plate->camera.pixelFormat.bits), false);
  if (!views) return reportFailure(views.error() + " (nothing was written)");
  if (auto mismatch = frameMismatch(plate->camera, o.out, views->frames.front()))
    return reportFailure(*mismatch + " (nothing was written)");
  const auto fit =
      calib::fitPlatePose(views->corners.front(), board, plate->intrinsics, o.maxRmsPx);
  if (!fit) return reportFailure(o.image + ": " + fit.error().message + " (nothing was written)");
  if (fit->boardTurned)
    spdlog::warn(
        "{}: the corners came in mirrored order; the board frame was turned so that the "
        "camera is above the floor (world Z runs toward the corners listed first)",
        o.image);
  fmt::print("floor board: {} corners: rms reprojection {:.3f} px (limit {:g} px)\n",
             fit->quality.corners, fit->quality.rmsReprojectionPx, o.maxRmsPx);
  fmt::print("pose: camera at {}\n", describePose(fit->pose));
  plate->pose = fit->pose;
  plate->poseQuality = fit->quality;
  plate->poseQuality.date = utcDateNow();
  if (!reportWritten(calib::io::savePlateCameraFile(*plate, o.out), o.out,
                     "the pose section (the rest of the file is kept)"))
    return cli::kExitFailure;
  if (!plate->probeYawDate.empty())
    spdlog::warn(
        "{}: the probe yaw was measured in the old world; run vemcalib plate probe-yaw "
        "again",
        o.out);
  return EXIT_SUCCESS;
}

constexpr const char* kPlatePoseFooter = R"(Example:
  vemcalib plate pose --image sim/plate-floor.png --board 9x6 --square 100 --out sim/plate.toml
--image shows the whole board lying printed side up on the floor where the synthetic objects will
stand, seen by the plate camera at its shooting position, zoom and focus (those of the intrinsics
in --out). The board fixes the world: its first inner corner is the origin, world X runs along
its rows (board X), world Z along its columns (board Y), +Y up; the camera is above the floor.
Prints the floor board's RMS reprojection error and the camera's position and direction.
Refuses, in one sentence, writing nothing: no plate-camera file at --out (run `plate intrinsics`
first); an image without the board, or of another size than the camera; an RMS above --max-rms.
Otherwise it replaces the pose section of PLATE_FILE (the rest is kept).)";

}  // namespace

void addPlatePoseCommand(CLI::App& plate, int& exitCode) {
  auto o = std::make_shared<PlatePoseOptions>();
  CLI::App* cmd = plate.add_subcommand(
      "pose", "Find the plate camera's pose from one image of a checkerboard on the floor");
  cmd->footer(kPlatePoseFooter);
  cmd->add_option("--image", o->image, "Image of the board on the floor")->required();
  addBoardOptions(cmd, o->board);
  cmd->add_option("--out", o->out, "Plate-camera file with the intrinsics, to update (TOML)")
      ->required();
  addMaxRmsOption(cmd, o->maxRmsPx);
  addBitsOption(cmd, o->bits, "Bits per code in 16-bit images (default: the camera's)");
  cmd->callback([o, &exitCode] { exitCode = runPlatePose(*o); });
}

}  // namespace vem::calibtool
