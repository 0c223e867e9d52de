// `vemcalib show`: checks a camera file as vemd would load it and prints it in words.
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>

#include <CLI/CLI.hpp>

#include "calib/io/camera_file.h"
#include "calibration_summary.h"
#include "camera_output.h"
#include "commands.h"

namespace vem::calibtool {
namespace {

int runShow(const std::string& path) {
  const auto calibration = calib::io::loadCameraFile(path);
  if (!calibration) return reportFailure(calibration.error().message);
  printCalibration(std::cout, *calibration, path);
  return std::cout.good() ? EXIT_SUCCESS : EXIT_FAILURE;
}

constexpr const char* kFooter = R"(Example:
  vemcalib show config/camera-example.toml
Prints the camera, its photometric response (model, parameters, the luminance range it reads,
the fit's residuals and date), its lens (field of view, parameters, the fit's reprojection error
and date) and its orientation.)";

}  // namespace

void addShowCommand(CLI::App& app, int& exitCode) {
  auto path = std::make_shared<std::string>();
  CLI::App* cmd = app.add_subcommand("show", "Check a camera file and print what it holds");
  cmd->footer(kFooter);
  cmd->add_option("CAMERA_FILE", *path, "Camera file (TOML)")->required();
  cmd->callback([path, &exitCode] { exitCode = runShow(*path); });
}

}  // namespace vem::calibtool
