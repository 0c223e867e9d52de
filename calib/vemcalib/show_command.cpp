// `vemcalib show`: checks a camera file as vemd would load it (or a plate-camera file as the
// renderer would) and prints it in words.
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>

#include <CLI/CLI.hpp>

#include "calib/io/calib_file_kind.h"
#include "calib/io/camera_file.h"
#include "calib/io/plate_camera_file.h"
#include "calibration_compare.h"
#include "calibration_summary.h"
#include "camera_output.h"
#include "commands.h"
#include "plate_summary.h"

namespace vem::calibtool {
namespace {

struct ShowOptions {
  std::string path;
  std::string truthPath;  // --compare
};

// Loads the file at --path with `load` and prints it, or with --compare loads the truth the same
// way and prints the two side by side; either file failing to load is its one error line.
template <typename Load, typename Print, typename PrintComparison>
int showFile(const ShowOptions& o, Load load, Print print, PrintComparison printComparison) {
  const auto fitted = load(o.path);
  if (!fitted) return reportFailure(fitted.error().message);
  if (o.truthPath.empty()) {
    print(std::cout, *fitted, o.path);
  } else {
    const auto truth = load(o.truthPath);
    if (!truth) return reportFailure("--compare: " + truth.error().message);
    printComparison(std::cout, *fitted, o.path, *truth, o.truthPath);
  }
  return std::cout.good() ? EXIT_SUCCESS : EXIT_FAILURE;
}

int runShow(const ShowOptions& o) {
  if (calib::io::calibFileKind(o.path) == calib::io::CalibFileKind::PlateCamera)
    return showFile(o, calib::io::loadPlateCameraFile, printPlateCamera, printPlateComparison);
  return showFile(o, calib::io::loadCameraFile, printCalibration, printComparison);
}

constexpr const char* kShowFooter = R"(Example:
  vemcalib show config/camera-example.toml
Prints the camera, its photometric response (model, parameters, the luminance range it reads,
the fit's residuals and date), its lens (field of view, parameters, the fit's reprojection error
and date) and its orientation.
  vemcalib show sim/camera.toml --compare config/camera-example.toml
Prints each fitted value beside the truth's and their difference, then how far apart the two are
where it matters: the luminance the codes read (per cent, max and rms over the code range), the
sensor positions of the same directions (pixels) and the directions of the same pixels (degrees).
  vemcalib show sim/plate.toml --compare config/plate-camera-example.toml
A plate-camera file (vemcalib plate) is shown the same way: intrinsics, pose, probe yaw and
colour, and with --compare (a truth plate-camera file) each value beside the truth's and where
world points seen by the truth land in the fitted image (pixels).)";

}  // namespace

void addShowCommand(CLI::App& app, int& exitCode) {
  auto o = std::make_shared<ShowOptions>();
  CLI::App* cmd =
      app.add_subcommand("show", "Check a camera or plate-camera file and print what it holds");
  cmd->footer(kShowFooter);
  cmd->add_option("CAMERA_FILE", o->path, "Camera file (TOML)")->required();
  cmd->add_option("--compare", o->truthPath,
                  "Print the file beside this truth camera file, with the differences")
      ->type_name("TRUTH_FILE");
  cmd->callback([o, &exitCode] { exitCode = runShow(*o); });
}

}  // namespace vem::calibtool
