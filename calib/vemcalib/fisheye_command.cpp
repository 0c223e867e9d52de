// `vemcalib fisheye`: the lens (Kannala-Brandt, paper 004 section 5.1) from images of a
// checkerboard. Finds the board in each image, fits the lens and the boards' poses
// (calib/core/fisheye_fit.h), prints every view's error and the lens, and writes the lens into the
// camera file, or refuses and writes nothing.
#include <cmath>
#include <cstdlib>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include "board_argument.h"
#include "board_views.h"
#include "calib/core/fisheye_fit.h"
#include "calib/io/camera_file.h"
#include "camera_output.h"
#include "commands.h"
#include "util/cli_value_names.h"

namespace vem::calibtool {
namespace {

struct FisheyeOptions {
  BoardViewOptions views{calib::FisheyeFitOptions{}.maxRmsPx, calib::FisheyeFitOptions{}.minViews};
  double fovDeg = 0.0;
  std::string out;
};

struct FisheyeInputs {
  std::optional<calib::CameraCalibration> existing;  // the --out file, when there is one
  calib::CameraCalibration fresh;                    // else a new one for the images' sensor
  calib::Checkerboard board;
  std::vector<RawFrame> frames;  // every --image, in order
};

std::expected<FisheyeInputs, std::string> loadInputs(const FisheyeOptions& o) {
  FisheyeInputs in{{}, {}, boardOf(o.views.board.size, o.views.board.squareMm), {}};
  auto existing = loadCameraToMerge(o.out);
  if (!existing) return std::unexpected(existing.error());
  in.existing = std::move(*existing);
  std::optional<int> bits = o.views.bits;
  if (!bits && in.existing) bits = in.existing->camera.pixelFormat.bits;
  auto frames = loadBoardImages(o.views.images, bits);
  if (!frames) return std::unexpected(frames.error());
  in.frames = std::move(*frames);
  in.fresh = newCameraFor(in.frames.front());
  if (in.existing)
    if (auto mismatch = frameMismatch(in.existing->camera, o.out, in.frames.front()))
      return std::unexpected(*mismatch + " (--out merges into that file)");
  return in;
}

void printFit(const calib::FisheyeFit& fit, const BoardImages& views, double maxRmsPx) {
  printViewFit(fit.viewRmsPx, views, fit.quality, maxRmsPx);
  const calib::KannalaBrandtLens& lens = fit.lens;
  fmt::print("lens: k = [{:.6g}, {:.6g}, {:.6g}, {:.6g}, {:.6g}] px\n", lens.kPx[0], lens.kPx[1],
             lens.kPx[2], lens.kPx[3], lens.kPx[4]);
  fmt::print("lens: principal point ({:.3f}, {:.3f}) px, aspect {:.6f}\n", lens.principalPointPx.x,
             lens.principalPointPx.y, lens.aspect);
  fmt::print("lens: max theta {:g} deg, image circle radius r(max theta) = {:.1f} px\n",
             lens.maxThetaRad * 180.0 / std::numbers::pi, lens.radiusPx(lens.maxThetaRad));
}

int writeCalibration(const FisheyeOptions& o, const FisheyeInputs& in,
                     const calib::FisheyeFit& fit) {
  calib::CameraCalibration calibration = in.existing.value_or(in.fresh);
  calibration.lens = fit.lens;
  calibration.geometricQuality = fit.quality;
  calibration.geometricQuality.date = utcDateNow();
  if (!reportWritten(calib::io::saveCameraFile(calibration, o.out), o.out,
                     in.existing
                         ? "the geometric section (the rest of the file is kept)"
                         : "a new camera file (model and serial \"unknown\": edit them there)"))
    return cli::kExitFailure;
  return EXIT_SUCCESS;
}

int runFisheye(const FisheyeOptions& o) {
  auto inputs = loadInputs(o);
  if (!inputs) return reportFailure(inputs.error());
  const auto views =
      findBoards(std::move(inputs->frames), o.views.images, inputs->board, o.views.skipMissing);
  if (!views) return reportFailure(views.error() + " (nothing was written)");
  if (int(views->frames.size()) < o.views.minViews)
    return reportFailure(
        fmt::format("{} of the {} images show the {}x{} board; the fit needs at least {} "
                    "(--min-views) (nothing was written)",
                    views->frames.size(), o.views.images.size(), inputs->board.innerCols,
                    inputs->board.innerRows, o.views.minViews));
  spdlog::info("fitting the lens to {} views", views->frames.size());
  const calib::FisheyeFitOptions fitOptions{o.fovDeg, o.views.minViews, o.views.maxRmsPx};
  const auto fit =
      calib::fitFisheyeRefined(views->frames, views->corners, inputs->board, fitOptions);
  if (!fit) return reportFailure(viewRefusal(fit.error().view, fit.error().message, *views));
  printFit(*fit, *views, o.views.maxRmsPx);
  return writeCalibration(o, *inputs, *fit);
}

constexpr const char* kFisheyeFooter = R"(Example:
  vemcalib simulate boards --camera config/camera-example.toml --board 9x6 --square 60 --views 12 --out sim
  vemcalib fisheye --image sim/board-*.png --board 9x6 --square 60 --fov 190 --out sim/camera.toml
Each --image shows the whole board, printed side toward the camera, with a white margin of about
one square around it; 10 or more views whose boards together cover the image circle from its
centre to its edge give the best lens. --board counts inner corners (9x6 for 10 x 7 squares).
Prints each view's RMS reprojection error, the overall RMS (pixels) and the fitted lens.
Refuses, in one sentence, writing nothing: fewer views with a board than --min-views; an image
without the board (unless --skip-missing, which leaves it out with a warning); a fit that does not
converge; an RMS above --max-rms, overall or in any view; a lens whose r(theta) stops increasing
before half the --fov (it would fold the image). Otherwise it replaces the geometric section of
CAMERA_FILE (the rest is kept) or creates the file for the images' sensor.)";

}  // namespace

void addFisheyeCommand(CLI::App& app, int& exitCode) {
  auto o = std::make_shared<FisheyeOptions>();
  CLI::App* cmd = app.add_subcommand(
      "fisheye", "Fit the fisheye lens (Kannala-Brandt) to images of a checkerboard");
  cmd->footer(kFisheyeFooter);
  addBoardViewOptions(cmd, o->views);
  cmd->add_option("--fov", o->fovDeg, "The lens's full field of view, degrees (e.g. 190)")
      ->required()
      ->type_name(help::rangeName(1.0, 360.0))
      ->check(help::quiet(CLI::Range(1.0, 360.0)));
  cmd->add_option("--out", o->out, "Camera file to update or create (TOML)")->required();
  addBoardViewLimitOptions(cmd, o->views);
  cmd->callback([o, &exitCode] { exitCode = runFisheye(*o); });
}

}  // namespace vem::calibtool
