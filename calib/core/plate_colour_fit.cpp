#include "calib/core/plate_colour_fit.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "util/contract.h"

namespace vem::calib {
namespace {

constexpr std::array<const char*, 3> kChannelNames{"R", "G", "B"};

std::optional<PlateColourFitFailure> unusablePatch(const ColourPatch& patch, double saturation) {
  for (std::size_t c = 0; c < 3; ++c) {
    if (!(patch.probeRadianceCdM2[c] > 0.0) || !(patch.plateLinear[c] > 0.0))
      return PlateColourFitFailure{
          ColourRefusal::BlackPatch,
          fmt::format("patch '{}' is black in {}: probe radiance {:g} cd/m2, plate value {:g} "
                      "(expected both above 0); light it or drop it",
                      patch.name, kChannelNames[c], patch.probeRadianceCdM2[c],
                      patch.plateLinear[c]),
          {}};
    if (patch.plateLinear[c] >= saturation)
      return PlateColourFitFailure{
          ColourRefusal::SaturatedPatch,
          fmt::format("patch '{}' is saturated in {}: its plate value {:g} is at or above the "
                      "saturation {:g} (--saturation); lower the plate's exposure or drop it",
                      patch.name, kChannelNames[c], patch.plateLinear[c], saturation),
          {}};
  }
  return std::nullopt;
}

}  // namespace

std::expected<PlateColourFit, PlateColourFitFailure> fitPlateColour(
    std::span<const ColourPatch> patches, const PlateColourFitOptions& options) {
  VEM_EXPECTS(options.minPatches >= 1 && options.saturation > 0.0);
  if (int(patches.size()) < options.minPatches)
    return std::unexpected(
        PlateColourFitFailure{ColourRefusal::TooFewPatches,
                              fmt::format("{} patch(es) given; the colour match needs at least {}",
                                          patches.size(), options.minPatches),
                              {}});
  for (const ColourPatch& patch : patches)
    if (auto failure = unusablePatch(patch, options.saturation)) return std::unexpected(*failure);
  PlateColourFit fit;
  for (std::size_t c = 0; c < 3; ++c) {
    double probePlate = 0.0, probeProbe = 0.0;
    for (const ColourPatch& p : patches) {
      probePlate += p.probeRadianceCdM2[c] * p.plateLinear[c];
      probeProbe += p.probeRadianceCdM2[c] * p.probeRadianceCdM2[c];
    }
    fit.match.gainRgb[c] = probePlate / probeProbe;
  }
  double sumSquares = 0.0;
  for (const ColourPatch& p : patches) {
    ColourPatchResult result{p.name, {}, {}};
    for (std::size_t c = 0; c < 3; ++c) {
      result.fittedLinear[c] = fit.match.gainRgb[c] * p.probeRadianceCdM2[c];
      result.residualPercent[c] = 100.0 * (result.fittedLinear[c] / p.plateLinear[c] - 1.0);
      sumSquares += result.residualPercent[c] * result.residualPercent[c];
      fit.maxResidualPercent =
          std::max(fit.maxResidualPercent, std::abs(result.residualPercent[c]));
    }
    fit.patches.push_back(result);
  }
  fit.match.patches = int(patches.size());
  fit.match.rmsResidualPercent = std::sqrt(sumSquares / double(3 * patches.size()));
  if (fit.maxResidualPercent > options.maxResidualPercent)
    return std::unexpected(PlateColourFitFailure{
        ColourRefusal::ResidualTooHigh,
        fmt::format("the largest patch residual is {:.2f}%, above the limit of {:g}% "
                    "(--max-residual): the patches do not follow one gain per channel (are they "
                    "grey, and lit alike for both cameras?)",
                    fit.maxResidualPercent, options.maxResidualPercent),
        fit.patches});
  return fit;
}

}  // namespace vem::calib
