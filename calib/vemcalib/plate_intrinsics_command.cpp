// `vemcalib plate intrinsics`: the plate camera's intrinsics (calib/core/plate_intrinsics_fit.h)
// from images of a checkerboard, written into the plate-camera file, or refused with nothing
// written.
#include <cstdlib>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include "board_argument.h"
#include "board_views.h"
#include "calib/core/plate_intrinsics_fit.h"
#include "calib/io/plate_camera_file.h"
#include "camera_output.h"
#include "commands.h"
#include "plate_output.h"

namespace vem::calibtool {
namespace {

struct PlateIntrinsicsOptions {
  BoardViewOptions views{calib::PlateIntrinsicsFitOptions{}.maxRmsPx,
                         calib::PlateIntrinsicsFitOptions{}.minViews};
  calib::PlateLensModel model = calib::PlateLensModel::BrownConrady;
  std::string out;
};

void printFit(const calib::PlateIntrinsicsFit& fit, const BoardImages& views, double maxRmsPx) {
  printViewFit(fit.viewRmsPx, views, fit.quality, maxRmsPx);
  const calib::PlateIntrinsics& in = fit.intrinsics;
  fmt::print(
      "intrinsics: {} lens, fx {:.3f} px, fy {:.3f} px, principal point ({:.3f}, {:.3f}) px\n",
      calib::plateLensModelName(in.model), in.fxPx, in.fyPx, in.cxPx, in.cyPx);
  const int n = calib::distortionCount(in.model);
  fmt::print("intrinsics: distortion {} = [{:.6g}]\n",
             in.model == calib::PlateLensModel::BrownConrady ? "k1, k2, p1, p2, k3" : "k1..k4",
             fmt::join(std::span(in.distortion).first(std::size_t(n)), ", "));
}

int writePlate(const PlateIntrinsicsOptions& o, const std::optional<calib::PlateCamera>& existing,
               const BoardImages& views, const calib::PlateIntrinsicsFit& fit) {
  calib::PlateCamera plate;
  if (existing)
    plate = *existing;
  else
    plate.camera = newCameraFor(views.frames.front()).camera;
  plate.intrinsics = fit.intrinsics;
  plate.intrinsicsQuality = fit.quality;
  plate.intrinsicsQuality.date = utcDateNow();
  if (!reportWritten(
          calib::io::savePlateCameraFile(plate, o.out), o.out,
          existing ? "the intrinsics section (the rest of the file is kept)"
                   : "a new plate camera file (model and serial \"unknown\": edit them there)"))
    return cli::kExitFailure;
  if (existing && existing->pose)
    spdlog::warn(
        "{}: the pose was found through the old intrinsics; run vemcalib plate pose "
        "again",
        o.out);
  return EXIT_SUCCESS;
}

int runPlateIntrinsics(const PlateIntrinsicsOptions& o) {
  const auto existing = loadPlateToMerge(o.out);
  if (!existing) return reportFailure(existing.error());
  const calib::Checkerboard board = boardOf(o.views.board.size, o.views.board.squareMm);
  std::optional<int> bits = o.views.bits;
  if (!bits && *existing) bits = (*existing)->camera.pixelFormat.bits;
  const auto views = findBoardsInImages(o.views.images, board, bits, o.views.skipMissing);
  if (!views) return reportFailure(views.error() + " (nothing was written)");
  if (views->frames.empty()) return reportFailure("no image shows the board (nothing was written)");
  if (*existing)
    if (auto mismatch = frameMismatch((*existing)->camera, o.out, views->frames.front()))
      return reportFailure(*mismatch + " (--out merges into that file; nothing was written)");
  spdlog::info("fitting the {} lens to {} views", calib::plateLensModelName(o.model),
               views->frames.size());
  const RawFrame& frame = views->frames.front();
  const auto fit = calib::fitPlateIntrinsics(views->corners, board, frame.width, frame.height,
                                             {o.model, o.views.minViews, o.views.maxRmsPx});
  if (!fit) return reportFailure(viewRefusal(fit.error().view, fit.error().message, *views));
  printFit(*fit, *views, o.views.maxRmsPx);
  return writePlate(o, *existing, *views, *fit);
}

constexpr const char* kPlateIntrinsicsFooter = R"(Example:
  vemcalib simulate plate --camera config/plate-camera-example.toml --board 9x6 --square 60 --floor-square 100 --out sim
  vemcalib plate intrinsics --image sim/plate-board-*.png --board 9x6 --square 60 --out sim/plate.toml
Each --image shows the whole board (--board counts inner corners: 9x6 for 10 x 7 squares) with a
white margin; 10 or more views, tilted 20 to 45 degrees in different directions and together
covering the image to its edges, give the best intrinsics. --model brown-conrady (OpenCV's
cv::calibrateCamera: fx, fy, cx, cy, k1, k2, p1, p2, k3) or kannala-brandt (cv::fisheye: k1..k4).
Prints each view's RMS reprojection error and the intrinsics. Refuses, in one sentence, writing
nothing: fewer views than --min-views; an image without the board (unless --skip-missing); a fit
that fails; an RMS above --max-rms, overall or in any view; images of another size or format than
the camera already in --out. Otherwise it replaces the intrinsics section of PLATE_FILE (the rest
is kept; re-run `plate pose` then) or creates the file for the images' sensor.)";

}  // namespace

void addPlateIntrinsicsCommand(CLI::App& plate, int& exitCode) {
  auto o = std::make_shared<PlateIntrinsicsOptions>();
  CLI::App* cmd = plate.add_subcommand(
      "intrinsics", "Fit the plate camera's intrinsics to images of a checkerboard (OpenCV)");
  cmd->footer(kPlateIntrinsicsFooter);
  addBoardViewOptions(cmd, o->views);
  const std::map<std::string, calib::PlateLensModel> models{
      {"brown-conrady", calib::PlateLensModel::BrownConrady},
      {"kannala-brandt", calib::PlateLensModel::KannalaBrandt}};
  cmd->add_option("--model", o->model, "Lens model: brown-conrady | kannala-brandt")
      ->transform(CLI::CheckedTransformer(models, CLI::ignore_case))
      ->default_str("brown-conrady");
  cmd->add_option("--out", o->out, "Plate-camera file to update or create (TOML)")->required();
  addBoardViewLimitOptions(cmd, o->views);
  cmd->callback([o, &exitCode] { exitCode = runPlateIntrinsics(*o); });
}

}  // namespace vem::calibtool
