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
#include "calib/core/plate_intrinsics_fit.h"
#include "calib/io/plate_camera_file.h"
#include "camera_output.h"
#include "commands.h"
#include "plate_output.h"
#include "util/cli_value_names.h"

namespace vem::calibtool {
namespace {

struct PlateIntrinsicsOptions {
  std::vector<std::string> images;
  std::string board;
  double squareMm = 0.0;
  calib::PlateLensModel model = calib::PlateLensModel::BrownConrady;
  std::string out;
  double maxRmsPx = calib::PlateIntrinsicsFitOptions{}.maxRmsPx;
  int minViews = calib::PlateIntrinsicsFitOptions{}.minViews;
  std::optional<int> bits;
  bool skipMissing = false;
};

void printFit(const calib::PlateIntrinsicsFit& fit, const BoardImages& views, double maxRmsPx) {
  fmt::print("view  rms px  image\n");
  for (std::size_t v = 0; v < fit.viewRmsPx.size(); ++v)
    fmt::print("{:>4}  {:>6.3f}  {}\n", v, fit.viewRmsPx[v], views.names[v]);
  const calib::PlateIntrinsics& in = fit.intrinsics;
  fmt::print("fit: {} views, {} corners: rms reprojection {:.3f} px (limit {:g} px)\n",
             fit.quality.views, fit.quality.corners, fit.quality.rmsReprojectionPx, maxRmsPx);
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
  if (existing) {
    plate = *existing;
  } else {
    plate.camera.sensorWidthPx = views.frames.front().width;
    plate.camera.sensorHeightPx = views.frames.front().height;
    plate.camera.pixelFormat = views.frames.front().format;
  }
  plate.intrinsics = fit.intrinsics;
  plate.intrinsicsQuality = fit.quality;
  plate.intrinsicsQuality.date = utcDateNow();
  if (auto saved = calib::io::savePlateCameraFile(plate, o.out); !saved)
    return reportFailure(saved.error().message);
  fmt::print("wrote {}: {}\n", o.out,
             existing ? "the intrinsics section (the rest of the file is kept)"
                      : "a new plate camera file (model and serial \"unknown\": edit them there)");
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
  const auto [cols, rows] = *parseBoardSize(o.board);  // validated by CLI11
  const calib::Checkerboard board{cols, rows, o.squareMm};
  std::optional<int> bits = o.bits;
  if (!bits && *existing) bits = (*existing)->camera.pixelFormat.bits;
  const auto views = findBoardsInImages(o.images, board, bits, o.skipMissing);
  if (!views) return reportFailure(views.error() + " (nothing was written)");
  if (views->frames.empty()) return reportFailure("no image shows the board (nothing was written)");
  if (*existing)
    if (auto mismatch = frameMismatch((*existing)->camera, o.out, views->frames.front()))
      return reportFailure(*mismatch + " (--out merges into that file; nothing was written)");
  spdlog::info("fitting the {} lens to {} views", calib::plateLensModelName(o.model),
               views->frames.size());
  const RawFrame& frame = views->frames.front();
  const auto fit = calib::fitPlateIntrinsics(views->corners, board, frame.width, frame.height,
                                             {o.model, o.minViews, o.maxRmsPx});
  if (!fit) {
    const calib::PlateFitFailure& f = fit.error();
    const std::string where =
        f.view >= 0 ? views->names[std::size_t(f.view)] + ": " : std::string();
    return reportFailure(where + f.message + " (nothing was written)");
  }
  printFit(*fit, *views, o.maxRmsPx);
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
  cmd->add_option("--image", o->images, "Images of the checkerboard: FILE ...")->required();
  cmd->add_option("--board", o->board, "Inner corners per row and column: COLSxROWS, e.g. 9x6")
      ->required()
      ->type_name("COLSxROWS")
      ->check(help::quiet(boardSizeValidator()));
  cmd->add_option("--square", o->squareMm, "Side of a square, mm")
      ->required()
      ->check(help::quiet(CLI::PositiveNumber));
  const std::map<std::string, calib::PlateLensModel> models{
      {"brown-conrady", calib::PlateLensModel::BrownConrady},
      {"kannala-brandt", calib::PlateLensModel::KannalaBrandt}};
  cmd->add_option("--model", o->model, "Lens model: brown-conrady | kannala-brandt")
      ->transform(CLI::CheckedTransformer(models, CLI::ignore_case))
      ->default_str("brown-conrady");
  cmd->add_option("--out", o->out, "Plate-camera file to update or create (TOML)")->required();
  cmd->add_option("--max-rms", o->maxRmsPx, "Largest RMS reprojection error accepted, pixels")
      ->capture_default_str()
      ->check(help::quiet(CLI::PositiveNumber));
  cmd->add_option("--min-views", o->minViews, "Fewest views with a board accepted")
      ->capture_default_str()
      ->type_name(help::rangeName(1, 1000))
      ->check(help::quiet(CLI::Range(1, 1000)));
  cmd->add_option("--bits", o->bits,
                  "Bits per code in 16-bit images, e.g. 12 (default: the --out file's, else the "
                  "image's depth)")
      ->check(CLI::IsMember({8, 10, 12, 16}));
  cmd->add_flag("--skip-missing", o->skipMissing,
                "Leave out images without the board (with a warning) instead of refusing");
  cmd->callback([o, &exitCode] { exitCode = runPlateIntrinsics(*o); });
}

}  // namespace vem::calibtool
