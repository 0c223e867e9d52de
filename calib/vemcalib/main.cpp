// vemcalib: calibrates a camera for vemcast (docs/calibration.md). A thin shell over vem_calib:
// each subcommand (commands.h) reads its inputs, calls the library and writes a camera file.
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include "commands.h"
#include "util/cli_conventions.h"

int main(int argc, char** argv) {
  // Diagnostics go to stderr, one line each; stdout carries the results (residual tables).
  auto logger = spdlog::stderr_color_st("vemcalib");
  logger->set_pattern("vemcalib: %^%l%$: %v");
  spdlog::set_default_logger(logger);

  CLI::App app{"vemcalib: calibrates an HDR fisheye camera for vemcast: photometric response from grey "
               "patches, fisheye lens from checkerboards, LDR response from exposure brackets"};
  app.require_subcommand(1);
  app.footer(
      "Example, a whole calibration on simulated frames (no camera needed):\n"
      "  vemcalib simulate patches --camera config/camera-example.toml --out sim\n"
      "  vemcalib photometric --frame sim/patches-1.png sim/patches-2.png --patches sim/patches.toml \\\n"
      "      --bits 12 --black-level 64 --saturation 4095 --out sim/camera.toml\n"
      "  vemcalib simulate boards --camera config/camera-example.toml --board 9x6 --square 60 --out sim\n"
      "  vemcalib fisheye --image sim/board-*.png --board 9x6 --square 60 --fov 190 --out sim/camera.toml\n"
      "  vemcalib simulate frame --camera config/camera-example.toml --map sky.exr --out raw.png\n"
      "  vemcalib apply --camera sim/camera.toml --frame raw.png --out polar.exr\n"
      "  vemtool lights --in polar.exr --count 64\n"
      "The scene (plate) camera of mixed reality: vemcalib plate --help.\n"
      "docs/calibration.md explains each step and the camera file.");
  int exitCode = vem::cli::kExitSuccess;
  vem::calibtool::addPhotometricCommand(app, exitCode);
  vem::calibtool::addFisheyeCommand(app, exitCode);
  vem::calibtool::addResponseCommand(app, exitCode);
  vem::calibtool::addSimulateCommand(app, exitCode);
  vem::calibtool::addApplyCommand(app, exitCode);
  vem::calibtool::addShowCommand(app, exitCode);
  vem::calibtool::addPlateCommand(app, exitCode);
  vem::cli::applyConventions(app, "vemcalib");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return vem::cli::exitStatusFor(app, e);
  }
  return exitCode;
}
