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
#include "calib/core/board_detection.h"
#include "calib/core/fisheye_fit.h"
#include "calib/io/camera_file.h"
#include "calib/io/raw_frame_file.h"
#include "camera_output.h"
#include "commands.h"
#include "util/cli_value_names.h"
#include "frame_arguments.h"

namespace vem::calibtool {
namespace {

struct FisheyeOptions {
  std::vector<std::string> images;
  std::string board;
  double squareMm = 0.0;
  double fovDeg = 0.0;
  std::string out;
  double maxRmsPx = calib::FisheyeFitOptions{}.maxRmsPx;
  int minViews = calib::FisheyeFitOptions{}.minViews;
  std::optional<int> bits;
  bool skipMissing = false;
};

// The images that show the board, with their corners and names.
struct BoardViews {
  std::vector<RawFrame> frames;
  std::vector<std::vector<glm::dvec2>> corners;
  std::vector<std::string> names;
};

struct FisheyeInputs {
  std::optional<calib::CameraCalibration> existing;  // the --out file, when there is one
  calib::CameraCalibration fresh;                    // else a new one for the images' sensor
  calib::Checkerboard board;
  std::vector<RawFrame> frames;  // every --image, in order
};

calib::Checkerboard boardFrom(const FisheyeOptions& o) {
  const auto [cols, rows] = *parseBoardSize(o.board);  // validated by CLI11
  return {cols, rows, o.squareMm};
}

std::expected<FisheyeInputs, std::string> loadInputs(const FisheyeOptions& o) {
  FisheyeInputs in{{}, {}, boardFrom(o), {}};
  auto existing = loadCameraToMerge(o.out);
  if (!existing) return std::unexpected(existing.error());
  in.existing = std::move(*existing);
  std::optional<int> bits = o.bits;
  if (!bits && in.existing) bits = in.existing->camera.pixelFormat.bits;
  for (const std::string& image : o.images) {
    auto frame = calib::io::loadRawFrame(image, bits);
    if (!frame) return std::unexpected(frame.error().message);
    const RawFrame& first = in.frames.empty() ? *frame : in.frames.front();
    if (frame->width != first.width || frame->height != first.height ||
        frame->format != first.format)
      return std::unexpected(
          fmt::format("{}: the image is {} but {} is {} (every --image must share "
                      "size and format)",
                      image, describeFrame(*frame), o.images.front(), describeFrame(first)));
    in.frames.push_back(std::move(*frame));
  }
  in.fresh = newCameraFor(in.frames.front());
  if (in.existing)
    if (auto mismatch = frameMismatch(in.existing->camera, o.out, in.frames.front()))
      return std::unexpected(*mismatch + " (--out merges into that file)");
  return in;
}

// Finds the board in every image, moving the images that show it out of `in`; an image without
// it is refused, or skipped with a warning.
std::expected<BoardViews, std::string> findBoards(const FisheyeOptions& o, FisheyeInputs& in) {
  BoardViews views;
  for (std::size_t i = 0; i < in.frames.size(); ++i) {
    std::optional<std::vector<glm::dvec2>> corners =
        calib::detectCheckerboard(in.frames[i], in.board);
    if (!corners) {
      const std::string what = fmt::format("{}: no {}x{} checkerboard was found", o.images[i],
                                           in.board.innerCols, in.board.innerRows);
      if (!o.skipMissing) return std::unexpected(what + " (--skip-missing leaves such images out)");
      spdlog::warn("{}; skipped (--skip-missing)", what);
      continue;
    }
    spdlog::info("{}: found the board", o.images[i]);
    views.frames.push_back(std::move(in.frames[i]));
    views.corners.push_back(std::move(*corners));
    views.names.push_back(o.images[i]);
  }
  return views;
}

void printFit(const calib::FisheyeFit& fit, const BoardViews& views, double maxRmsPx) {
  fmt::print("view  rms px  image\n");
  for (std::size_t v = 0; v < fit.viewRmsPx.size(); ++v)
    fmt::print("{:>4}  {:>6.3f}  {}\n", v, fit.viewRmsPx[v], views.names[v]);
  const calib::KannalaBrandtLens& lens = fit.lens;
  fmt::print("fit: {} views, {} corners: rms reprojection {:.3f} px (limit {:g} px)\n",
             fit.quality.views, fit.quality.corners, fit.quality.rmsReprojectionPx, maxRmsPx);
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
  if (auto saved = calib::io::saveCameraFile(calibration, o.out); !saved)
    return reportFailure(saved.error().message);
  fmt::print("wrote {}: {}\n", o.out,
             in.existing ? "the geometric section (the rest of the file is kept)"
                         : "a new camera file (model and serial \"unknown\": edit them there)");
  return EXIT_SUCCESS;
}

// The fit's refusal as one sentence, naming the image at fault when there is one.
std::string refusalSentence(const calib::FisheyeFitFailure& failure, const BoardViews& views) {
  const std::string sentence =
      failure.view >= 0 && std::size_t(failure.view) < views.names.size()
          ? fmt::format("{}: {}", views.names[std::size_t(failure.view)], failure.message)
          : failure.message;
  return sentence + " (nothing was written)";
}

int runFisheye(const FisheyeOptions& o) {
  auto inputs = loadInputs(o);
  if (!inputs) return reportFailure(inputs.error());
  const auto views = findBoards(o, *inputs);
  if (!views) return reportFailure(views.error() + " (nothing was written)");
  if (int(views->frames.size()) < o.minViews)
    return reportFailure(
        fmt::format("{} of the {} images show the {}x{} board; the fit needs at least {} "
                    "(--min-views) (nothing was written)",
                    views->frames.size(), o.images.size(), inputs->board.innerCols,
                    inputs->board.innerRows, o.minViews));
  spdlog::info("fitting the lens to {} views", views->frames.size());
  const calib::FisheyeFitOptions fitOptions{o.fovDeg, o.minViews, o.maxRmsPx};
  const auto fit =
      calib::fitFisheyeRefined(views->frames, views->corners, inputs->board, fitOptions);
  if (!fit) return reportFailure(refusalSentence(fit.error(), *views));
  printFit(*fit, *views, o.maxRmsPx);
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
  cmd->add_option("--image", o->images, "Images of the checkerboard: FILE ...")->required();
  cmd->add_option("--board", o->board, "Inner corners per row and column: COLSxROWS, e.g. 9x6")
      ->required()
      ->type_name("COLSxROWS")
      ->check(help::quiet(boardSizeValidator()));
  cmd->add_option("--square", o->squareMm, "Side of a square, mm")
      ->required()
      ->check(help::quiet(CLI::PositiveNumber));
  cmd->add_option("--fov", o->fovDeg, "The lens's full field of view, degrees (e.g. 190)")
      ->required()
      ->type_name(help::rangeName(1.0, 360.0))
      ->check(help::quiet(CLI::Range(1.0, 360.0)));
  cmd->add_option("--out", o->out, "Camera file to update or create (TOML)")->required();
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
  cmd->callback([o, &exitCode] { exitCode = runFisheye(*o); });
}

}  // namespace vem::calibtool
