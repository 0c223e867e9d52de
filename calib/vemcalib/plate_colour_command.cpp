// `vemcalib plate colour`: the plate camera's colour match with the light probe
// (calib/core/plate_colour_fit.h) from grey patches both cameras see; written into the
// plate-camera file, or refused with nothing written.
#include <cstdlib>
#include <memory>
#include <span>
#include <string>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "calib/core/plate_colour_fit.h"
#include "calib/io/plate_camera_file.h"
#include "calib/io/plate_colour_file.h"
#include "camera_output.h"
#include "commands.h"
#include "plate_output.h"
#include "util/cli_value_names.h"

namespace vem::calibtool {
namespace {

struct PlateColourOptions {
  std::string patches;
  std::string out;
  double saturation = calib::PlateColourFitOptions{}.saturation;
  double maxResidualPercent = calib::PlateColourFitOptions{}.maxResidualPercent;
};

void printPatches(std::span<const calib::ColourPatch> patches,
                  std::span<const calib::ColourPatchResult> results) {
  if (results.empty()) return;  // refused before the fit ran
  fmt::print("patch     channel  probe        plate      fitted     error\n");
  fmt::print("                   cd/m2        linear     linear     %\n");
  constexpr const char* kChannels[] = {"R", "G", "B"};
  for (std::size_t i = 0; i < results.size() && i < patches.size(); ++i)
    for (std::size_t c = 0; c < 3; ++c)
      fmt::print("{:<9} {:<8} {:<12.6g} {:<10.6g} {:<10.6g} {:+.3f}\n", patches[i].name,
                 kChannels[c], patches[i].probeRadianceCdM2[c], patches[i].plateLinear[c],
                 results[i].fittedLinear[c], results[i].residualPercent[c]);
}

int runPlateColour(const PlateColourOptions& o) {
  auto plate = loadPlateToUpdate(o.out, "the colour match is stored with the intrinsics");
  if (!plate) return reportFailure(plate.error());
  const auto patches = calib::io::loadColourPatchFile(o.patches);
  if (!patches) return reportFailure(patches.error().message + " (nothing was written)");
  const auto fit = calib::fitPlateColour(*patches, {2, o.saturation, o.maxResidualPercent});
  if (!fit) {
    printPatches(*patches, fit.error().patches);
    return reportFailure(o.patches + ": " + fit.error().message + " (nothing was written)");
  }
  printPatches(*patches, fit->patches);
  const calib::PlateColourMatch& match = fit->match;
  fmt::print("fit: {} patches: rms residual {:.3f} %, largest {:.3f} % (limit {:g} %)\n",
             match.patches, match.rmsResidualPercent, fit->maxResidualPercent,
             o.maxResidualPercent);
  fmt::print(
      "colour: plate linear = gain x probe radiance, gain R {:.6g}, G {:.6g}, B {:.6g} "
      "per cd/m2\n",
      match.gainRgb[0], match.gainRgb[1], match.gainRgb[2]);
  plate->colour = match;
  plate->colour->date = utcDateNow();
  if (!reportWritten(calib::io::savePlateCameraFile(*plate, o.out), o.out,
                     "the colour section (the rest of the file is kept)"))
    return cli::kExitFailure;
  return EXIT_SUCCESS;
}

constexpr const char* kPlateColourFooter = R"(Example:
  vemcalib plate colour --patches sim/plate-colour.toml --out sim/plate.toml
--patches lists grey patches (a grey card, a colour chart's neutral row) seen by both cameras:
each with its radiance in the light probe's map in its direction (cd/m2 per channel, the probe's
calibrated units) and its mean linear value in the plate image (per channel, 1 = full scale; a
linear EXR, or a gamma-decoded frame), as TOML:
  [[patch]]
  name = "g1"
  probe_radiance = { value = [52.1, 50.3, 47.9], unit = "cd/m2" }
  plate_linear = { value = [0.109, 0.096, 0.115], unit = "linear" }
Fits per channel the least-squares gain through the origin, plate = gain x probe, and prints
every patch's residual. Refuses, in one sentence, writing nothing: fewer than 2 patches; a black
patch (a channel at or below 0); a saturated patch (a plate value at or above --saturation); a
residual above --max-residual. Otherwise it replaces the colour section of PLATE_FILE.)";

}  // namespace

void addPlateColourCommand(CLI::App& plate, int& exitCode) {
  auto o = std::make_shared<PlateColourOptions>();
  CLI::App* cmd = plate.add_subcommand(
      "colour", "Match the plate camera's colour to the light probe's from grey patches");
  cmd->footer(kPlateColourFooter);
  cmd->add_option("--patches", o->patches, "Colour-patch file (TOML)")->required();
  cmd->add_option("--out", o->out, "Plate-camera file to update (TOML)")->required();
  cmd->add_option("--saturation", o->saturation,
                  "Plate linear value at or above which a channel is clipped")
      ->capture_default_str()
      ->check(help::quiet(CLI::PositiveNumber));
  cmd->add_option("--max-residual", o->maxResidualPercent,
                  "Largest patch residual accepted, per cent")
      ->capture_default_str()
      ->check(help::quiet(CLI::PositiveNumber));
  cmd->callback([o, &exitCode] { exitCode = runPlateColour(*o); });
}

}  // namespace vem::calibtool
