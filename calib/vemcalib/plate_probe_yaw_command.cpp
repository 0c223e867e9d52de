// `vemcalib plate probe-yaw`: the light probe's yaw in the plate camera's world
// (calib/core/plate_probe_yaw.h) from one distant marker seen by both cameras: its pixel in the
// plate image and its direction in the probe's map. Written into the plate-camera file, or refused
// with nothing written.
#include <cmath>
#include <cstdlib>
#include <memory>
#include <numbers>
#include <string>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "calib/core/plate_probe_yaw.h"
#include "calib/io/plate_camera_file.h"
#include "camera_output.h"
#include "commands.h"
#include "number_pair_argument.h"
#include "plate_output.h"
#include "util/cli_value_names.h"

namespace vem::calibtool {
namespace {

struct PlateProbeYawOptions {
  std::string pixel;
  std::string probeDirection;
  std::string out;
  double maxElevationDifferenceDeg = 2.0;
};

int runPlateProbeYaw(const PlateProbeYawOptions& o) {
  auto plate = loadPlateToUpdate(o.out, "the probe yaw needs the plate camera's pose");
  if (!plate) return reportFailure(plate.error());
  if (!plate->pose)
    return reportFailure(o.out + ": the plate camera has no pose (run vemcalib plate pose first)");
  const auto [x, y] = *parseNumberPair(o.pixel);                   // validated by CLI11
  const auto [azDeg, elDeg] = *parseNumberPair(o.probeDirection);  // validated by CLI11
  const calib::PlateIntrinsics& in = plate->intrinsics;
  if (x < -0.5 || y < -0.5 || x > in.widthPx - 0.5 || y > in.heightPx - 0.5)
    return reportFailure(
        fmt::format("--pixel {}: expected a pixel on the {} x {} plate image "
                    "(nothing was written)",
                    o.pixel, in.widthPx, in.heightPx));
  const glm::dvec3 plateDir = calib::worldDirectionFromPlate(in, *plate->pose, {x, y});
  const glm::dvec3 probeDir =
      calib::directionFromAzimuthElevation(azDeg / kDegPerRad, elDeg / kDegPerRad);
  const double plateElevationDeg = calib::elevationRad(plateDir) * kDegPerRad;
  fmt::print(
      "marker: in the plate's world azimuth {:.3f} deg, elevation {:.3f} deg (pixel {:g}, "
      "{:g})\n",
      calib::azimuthRad(plateDir) * kDegPerRad, plateElevationDeg, x, y);
  fmt::print("marker: in the probe's world azimuth {:.3f} deg, elevation {:.3f} deg\n", azDeg,
             elDeg);
  if (std::abs(plateElevationDeg - elDeg) > o.maxElevationDifferenceDeg)
    return reportFailure(fmt::format(
        "the marker's elevation is {:.2f} deg through the plate camera but {:g} deg in the "
        "probe's map, {:.2f} deg apart (at most {:g} allowed, --max-elevation-difference): is it "
        "the same marker, far enough away, and the pose right? (nothing was written)",
        plateElevationDeg, elDeg, std::abs(plateElevationDeg - elDeg),
        o.maxElevationDifferenceDeg));
  const std::optional<double> yaw = calib::probeYawFromMarker(plateDir, probeDir);
  if (!yaw)
    return reportFailure(
        "the marker is within 1 deg of straight up or down, where azimuth is "
        "undefined; choose a marker nearer the horizon (nothing was written)");
  fmt::print("probe yaw: {:.3f} deg (dir_plate_world = RotY(yaw) dir_probe_world)\n",
             *yaw * kDegPerRad);
  plate->probeYawRad = *yaw;
  plate->probeYawDate = utcDateNow();
  if (!reportWritten(calib::io::savePlateCameraFile(*plate, o.out), o.out,
                     "the probe section (the rest of the file is kept)"))
    return cli::kExitFailure;
  return EXIT_SUCCESS;
}

constexpr const char* kPlateProbeYawFooter = R"(Example:
  vemcalib plate probe-yaw --pixel 1024,86.4 --probe-direction 168.9346,8.9944 --out sim/plate.toml
A marker both cameras see, far away compared with the distance between them (a lamp across a
large room, a light outdoors, the sun): --pixel is its pixel in the plate image (x column, y row,
pixel centres at integers, as the image shows it, distortion and all); --probe-direction is its
azimuth and elevation in the light probe's map, degrees (azimuth from +X toward +Z, elevation
above the horizon: docs/conventions.md). The pixel gives the marker's direction in the plate's
world through the intrinsics and pose in --out; yaw = azimuth in the probe's world minus azimuth in
the plate's (dir_plate_world = RotY(yaw) dir_probe_world). For cameras b metres apart and a marker
d metres away the yaw may be off by up to asin(b / d): 1.1 deg for 2 m and 100 m.
Refuses, in one sentence, writing nothing: no pose in --out; a pixel off the image; elevations more
than --max-elevation-difference apart (another marker, a near one, or a wrong pose); a marker
within 1 deg of the zenith or nadir. Otherwise it replaces the probe section of PLATE_FILE.)";

}  // namespace

void addPlateProbeYawCommand(CLI::App& plate, int& exitCode) {
  auto o = std::make_shared<PlateProbeYawOptions>();
  CLI::App* cmd = plate.add_subcommand(
      "probe-yaw", "Find the light probe's yaw in the plate's world from a distant marker");
  cmd->footer(kPlateProbeYawFooter);
  cmd->add_option("--pixel", o->pixel, "The marker's pixel in the plate image: X,Y")
      ->required()
      ->type_name("X,Y")
      ->check(help::quiet(numberPairValidator("X,Y")));
  cmd->add_option("--probe-direction", o->probeDirection,
                  "The marker's azimuth and elevation in the probe's map, degrees: AZ,EL")
      ->required()
      ->type_name("AZ,EL")
      ->check(help::quiet(numberPairValidator("AZ,EL")));
  cmd->add_option("--out", o->out, "Plate-camera file with intrinsics and pose, to update (TOML)")
      ->required();
  cmd->add_option("--max-elevation-difference", o->maxElevationDifferenceDeg,
                  "Largest difference accepted between the two elevations, degrees")
      ->capture_default_str()
      ->check(help::quiet(CLI::PositiveNumber));
  cmd->callback([o, &exitCode] { exitCode = runPlateProbeYaw(*o); });
}

}  // namespace vem::calibtool
