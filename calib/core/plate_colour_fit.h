// The plate camera's colour match with the light probe (plate_camera.h, PlateColourMatch): grey
// patches that both cameras see, each with the probe's radiance (cd/m2 per channel, what the
// calibrated probe's map holds in the patch's direction) and the plate's linear value (per
// channel, 1 = the plate's full scale), give per channel the least-squares gain through the origin
//     gain_c = sum_i probe_ic plate_ic / sum_i probe_ic^2,   plate = gain x probe,
// and each patch's residual in percent of its plate value, 100 (gain probe / plate - 1).
//
// Refusals, one sentence each naming the patch: fewer than minPatches patches; a black patch (a
// channel of either value at or below 0: it carries no gain); a saturated patch (a plate channel
// at or above `saturation`: its value is clipped); a residual above maxResidualPercent (the
// patches do not follow one gain: not grey, or lit differently for the two cameras).
#pragma once

#include <array>
#include <expected>
#include <span>
#include <string>
#include <vector>

#include "calib/core/plate_camera.h"

namespace vem::calib {

struct ColourPatch {
  std::string name;
  std::array<double, 3> probeRadianceCdM2{};  // R, G, B
  std::array<double, 3> plateLinear{};        // R, G, B
};

struct PlateColourFitOptions {
  int minPatches = 2;
  double saturation = 1.0;          // plate linear values at or above are clipped
  double maxResidualPercent = 5.0;  // largest patch residual accepted, any channel
};

struct ColourPatchResult {
  std::string name;
  std::array<double, 3> fittedLinear{};     // gain x probe radiance
  std::array<double, 3> residualPercent{};  // 100 (fitted / plate - 1)
};

struct PlateColourFit {
  PlateColourMatch match;  // date left empty: the caller stamps it
  double maxResidualPercent = 0.0;
  std::vector<ColourPatchResult> patches;  // in the order given
};

enum class ColourRefusal { TooFewPatches, BlackPatch, SaturatedPatch, ResidualTooHigh };

struct PlateColourFitFailure {
  ColourRefusal cause;
  std::string message;
  std::vector<ColourPatchResult> patches;  // filled when the fit ran (a residual refusal)
};

[[nodiscard]] std::expected<PlateColourFit, PlateColourFitFailure> fitPlateColour(
    std::span<const ColourPatch> patches, const PlateColourFitOptions& options);

}  // namespace vem::calib
