// The plate's colour match with the probe (calib/core/plate_colour_fit.h): per-channel gains
// recovered from grey patches, and the patches that would bias them refused in one sentence.
#include "calib/core/plate_colour_fit.h"

#include <vector>

#include <gtest/gtest.h>

namespace vem::calib {
namespace {

constexpr std::array<double, 3> kTruthGain{0.0021, 0.0019, 0.0024};

std::vector<ColourPatch> greyPatches() {
  std::vector<ColourPatch> patches;
  const std::pair<const char*, double> named[] = {
      {"g20", 20.0}, {"g45", 45.0}, {"g90", 90.0}, {"g160", 160.0}, {"g280", 280.0}};
  for (const auto& [name, radiance] : named) {
    ColourPatch p{name, {radiance, radiance * 1.02, radiance * 0.97}, {}};
    for (std::size_t c = 0; c < 3; ++c) p.plateLinear[c] = kTruthGain[c] * p.probeRadianceCdM2[c];
    patches.push_back(p);
  }
  return patches;
}

TEST(PlateColourFit, GreyPatchesGiveTheTruthsGains) {
  const auto fit = fitPlateColour(greyPatches(), {});
  ASSERT_TRUE(fit.has_value()) << fit.error().message;
  for (std::size_t c = 0; c < 3; ++c) EXPECT_NEAR(fit->match.gainRgb[c], kTruthGain[c], 1e-15);
  EXPECT_NEAR(fit->match.rmsResidualPercent, 0.0, 1e-9);
  EXPECT_EQ(fit->match.patches, 5);
  EXPECT_EQ(fit->patches.size(), 5u);
}

TEST(PlateColourFit, NoisyPatchesGiveTheLeastSquaresGainAndTheirResiduals) {
  std::vector<ColourPatch> patches = greyPatches();
  patches[1].plateLinear[0] *= 1.02;  // 2 % brighter in red
  const auto fit = fitPlateColour(patches, {});
  ASSERT_TRUE(fit.has_value()) << fit.error().message;
  EXPECT_GT(fit->match.gainRgb[0], kTruthGain[0]);
  EXPECT_NEAR(fit->match.gainRgb[1], kTruthGain[1], 1e-15);
  EXPECT_LT(fit->patches[1].residualPercent[0], 0.0);
  EXPECT_GT(fit->match.rmsResidualPercent, 0.0);
  EXPECT_LT(fit->maxResidualPercent, 2.0);
}

TEST(PlateColourFit, ASaturatedPatchIsRefusedNamingIt) {
  std::vector<ColourPatch> patches = greyPatches();
  patches[4].plateLinear[1] = 1.0;
  const auto fit = fitPlateColour(patches, {});
  ASSERT_FALSE(fit.has_value());
  EXPECT_EQ(fit.error().cause, ColourRefusal::SaturatedPatch);
  EXPECT_EQ(fit.error().message,
            "patch 'g280' is saturated in G: its plate value 1 is at or above the saturation 1 "
            "(--saturation); lower the plate's exposure or drop it");
}

TEST(PlateColourFit, ABlackPatchIsRefusedNamingIt) {
  std::vector<ColourPatch> patches = greyPatches();
  patches[0].probeRadianceCdM2[2] = 0.0;
  const auto fit = fitPlateColour(patches, {});
  ASSERT_FALSE(fit.has_value());
  EXPECT_EQ(fit.error().cause, ColourRefusal::BlackPatch);
  EXPECT_NE(fit.error().message.find("patch 'g20' is black in B"), std::string::npos);
}

TEST(PlateColourFit, PatchesThatFollowNoSingleGainAreRefused) {
  std::vector<ColourPatch> patches = greyPatches();
  patches[2].plateLinear[0] *= 1.5;  // a coloured patch, or lit differently for the plate
  const auto fit = fitPlateColour(patches, {});
  ASSERT_FALSE(fit.has_value());
  EXPECT_EQ(fit.error().cause, ColourRefusal::ResidualTooHigh);
  EXPECT_EQ(fit.error().patches.size(), 5u);
}

TEST(PlateColourFit, TooFewPatchesAreRefused) {
  const std::vector<ColourPatch> one{greyPatches().front()};
  const auto fit = fitPlateColour(one, {});
  ASSERT_FALSE(fit.has_value());
  EXPECT_EQ(fit.error().cause, ColourRefusal::TooFewPatches);
}

}  // namespace
}  // namespace vem::calib
