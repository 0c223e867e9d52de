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

int runPlateShow(const ShowOptions& o) {
  const auto plate = calib::io::loadPlateCameraFile(o.path);
  if (!plate) return reportFailure(plate.error().message);
  if (o.truthPath.empty()) {
    printPlateCamera(std::cout, *plate, o.path);
  } else {
    const auto truth = calib::io::loadPlateCameraFile(o.truthPath);
    if (!truth) return reportFailure("--compare: " + truth.error().message);
    printPlateComparison(std::cout, *plate, o.path, *truth, o.truthPath);
  }
  return std::cout.good() ? EXIT_SUCCESS : EXIT_FAILURE;
}

int runShow(const ShowOptions& o) {
  if (calib::io::calibFileKind(o.path) == calib::io::CalibFileKind::PlateCamera)
    return runPlateShow(o);
  const auto calibration = calib::io::loadCameraFile(o.path);
  if (!calibration) return reportFailure(calibration.error().message);
  if (o.truthPath.empty()) {
    printCalibration(std::cout, *calibration, o.path);
  } else {
    const auto truth = calib::io::loadCameraFile(o.truthPath);
    if (!truth) return reportFailure("--compare: " + truth.error().message);
    printComparison(std::cout, *calibration, o.path, *truth, o.truthPath);
  }
  return std::cout.good() ? EXIT_SUCCESS : EXIT_FAILURE;
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
  CLI::App* cmd = app.add_subcommand("show", "Check a camera or plate-camera file and print what it holds");
  cmd->footer(kShowFooter);
  cmd->add_option("CAMERA_FILE", o->path, "Camera file (TOML)")->required();
  cmd->add_option("--compare", o->truthPath,
                  "Print the file beside this truth camera file, with the differences")
      ->type_name("TRUTH_FILE");
  cmd->callback([o, &exitCode] { exitCode = runShow(*o); });
}

}  // namespace vem::calibtool
