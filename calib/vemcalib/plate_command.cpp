// `vemcalib plate`: the scene ("plate") camera of mixed reality (calib/core/plate_camera.h,
// docs/calibration.md "Plate camera"). This file holds the `plate` command itself; each step is a
// subcommand in its own file.
#include <CLI/CLI.hpp>

#include "commands.h"

namespace vem::calibtool {
namespace {

constexpr const char* kPlateFooter =
    R"(Example, a whole plate calibration on simulated views (no camera needed):
  vemcalib simulate plate --camera config/plate-camera-example.toml --board 9x6 --square 60 --floor-square 100 --out sim
  vemcalib plate intrinsics --image sim/plate-board-*.png --board 9x6 --square 60 --out sim/plate.toml
  vemcalib plate pose --image sim/plate-floor.png --board 9x6 --square 100 --out sim/plate.toml
  vemcalib plate probe-yaw --pixel 1024,86.4 --probe-direction 168.9346,8.9944 --out sim/plate.toml
  vemcalib plate colour --patches sim/plate-colour.toml --out sim/plate.toml
  vemcalib show sim/plate.toml --compare config/plate-camera-example.toml
(simulate plate prints the exact probe-yaw command for its marker.) Each step replaces its own
section of the plate-camera file and keeps the rest; a refused step writes nothing.)";

}  // namespace

void addPlateCommand(CLI::App& app, int& exitCode) {
  CLI::App* plate = app.add_subcommand(
      "plate",
      "Calibrate the scene (plate) camera for mixed reality: intrinsics, pose, probe "
      "yaw, colour");
  plate->footer(kPlateFooter);
  plate->require_subcommand(1);
  addPlateIntrinsicsCommand(*plate, exitCode);
  addPlatePoseCommand(*plate, exitCode);
  addPlateProbeYawCommand(*plate, exitCode);
  addPlateColourCommand(*plate, exitCode);
}

}  // namespace vem::calibtool
