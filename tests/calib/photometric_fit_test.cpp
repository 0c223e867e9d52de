// Photometric calibration from grey patches (calib/core/photometric_fit.h): the fit recovers the
// response, reports honest residuals, and refuses every bad input with its reason.
#include "calib/core/photometric_fit.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "calib/core/camera_simulator.h"
#include "support/test_cameras.h"

namespace vem::calib {
namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 120;

struct Chart {
  CameraCalibration truth;
  std::vector<PatchSpec> patches;
  std::vector<RawFrame> frames;
};

Chart simulateChart(int channels, double readNoiseCode, int frameCount = 2) {
  Chart chart{testing::cameraTruth(kWidth, kHeight, channels), testing::greyChart(kWidth, kHeight),
              {}};
  for (int k = 0; k < frameCount; ++k) {
    SimulationOptions options;
    options.noise = {readNoiseCode, 0.0, std::uint64_t(100 + k)};
    chart.frames.push_back(simulatePatchFrame(chart.patches, 1.0, chart.truth, options));
  }
  return chart;
}

PhotometricFitOptions logOptions() {
  PhotometricFitOptions options;
  options.blackLevelCode = 64.0;
  options.saturationCode = 4095.0;
  return options;
}

std::vector<PatchMeasurement> measureAll(const Chart& chart, const PhotometricFitOptions& options) {
  std::vector<PatchMeasurement> measured;
  for (const PatchSpec& p : chart.patches) {
    measured.push_back(
        measurePatch(chart.frames, p, options.blackLevelCode, options.saturationCode));
  }
  return measured;
}

TEST(PhotometricFit, LogFitRecoversAAndBWithinOnePercentAtRealisticNoise) {
  const Chart chart = simulateChart(1, 3.0);
  const auto fit = fitPhotometric(measureAll(chart, logOptions()), logOptions());
  ASSERT_TRUE(fit.has_value()) << fit.error().message;
  const auto& truth = std::get<LogResponse>(chart.truth.photometric->response);
  const auto& got = std::get<LogResponse>(fit->calibration.response);
  EXPECT_NEAR(got.aCode[0] / truth.aCode[0], 1.0, 0.01);
  EXPECT_NEAR(got.bCodePerLn[0] / truth.bCodePerLn[0], 1.0, 0.01);
  EXPECT_LT(fit->quality.maxResidualPercent, 3.0);
  EXPECT_LT(fit->quality.maxCheckErrorPercent, 3.0);
  EXPECT_EQ(fit->quality.fitPatches, 6);
  EXPECT_EQ(fit->quality.checkPatches, 2);
}

TEST(PhotometricFit, EachChannelOfAColourSensorGetsItsOwnResponse) {
  const Chart chart = simulateChart(3, 3.0);
  const auto fit = fitPhotometric(measureAll(chart, logOptions()), logOptions());
  ASSERT_TRUE(fit.has_value()) << fit.error().message;
  const auto& truth = std::get<LogResponse>(chart.truth.photometric->response);
  const auto& got = std::get<LogResponse>(fit->calibration.response);
  for (std::size_t c = 0; c < 3; ++c) {
    EXPECT_NEAR(got.bCodePerLn[c] / truth.bCodePerLn[c], 1.0, 0.01) << "channel " << c;
    EXPECT_NEAR(got.aCode[c] / truth.aCode[c], 1.0, 0.01) << "channel " << c;
  }
}

TEST(PhotometricFit, ReportedResidualsMatchOnesRecomputedFromTheFittedResponse) {
  const Chart chart = simulateChart(1, 3.0);
  const auto measured = measureAll(chart, logOptions());
  const auto fit = fitPhotometric(measured, logOptions());
  ASSERT_TRUE(fit.has_value());
  double sumSq = 0.0;
  for (std::size_t i = 0; i < measured.size(); ++i) {
    const double fitted = luminanceFromCode(fit->calibration, 0, measured[i].meanCode[0], 1000.0, 1.0);
    const double error = 100.0 * (fitted / measured[i].spec.luminanceCdM2 - 1.0);
    EXPECT_NEAR(fit->patches[i].errorPercent[0], error, 1e-9) << measured[i].spec.name;
    if (!measured[i].spec.check) sumSq += error * error;
  }
  EXPECT_NEAR(fit->quality.rmsResidualPercent, std::sqrt(sumSq / 6.0), 1e-9);
}

TEST(PhotometricFit, CheckPatchesAreLeftOutOfTheFit) {
  const Chart chart = simulateChart(1, 0.0);
  auto measured = measureAll(chart, logOptions());
  const auto reference = fitPhotometric(measured, logOptions());
  ASSERT_TRUE(reference.has_value());
  for (PatchMeasurement& m : measured) {
    if (m.spec.check) m.spec.luminanceCdM2 *= 1.5;  // a wrong check value must not move the fit
  }
  PhotometricFitOptions lenient = logOptions();
  lenient.maxCheckErrorPercent = 100.0;
  const auto fit = fitPhotometric(measured, lenient);
  ASSERT_TRUE(fit.has_value());
  EXPECT_EQ(std::get<LogResponse>(fit->calibration.response).bCodePerLn[0],
            std::get<LogResponse>(reference->calibration.response).bCodePerLn[0]);
  EXPECT_NEAR(fit->quality.maxCheckErrorPercent, 100.0 / 3.0, 1.0);  // reads 1/1.5 of the label
}

TEST(PhotometricFit, LinearFitRecoversTheGainThroughTheBlackLevel) {
  Chart chart = simulateChart(1, 0.0, 1);
  PhotometricCalibration linear;
  linear.blackLevelCode = 64.0;
  linear.saturationCode = 65535.0;
  linear.response = LinearResponse{{0.002, 0.002, 0.002}};
  chart.truth.photometric = linear;
  chart.truth.camera.pixelFormat = {1, 16};
  for (PatchSpec& p : chart.patches) p.luminanceCdM2 = std::min(p.luminanceCdM2, 9000.0) + 20.0;
  SimulationOptions options;
  options.noise = {2.0, 0.5, 7};
  chart.frames = {simulatePatchFrame(chart.patches, 1.0, chart.truth, options)};
  PhotometricFitOptions fitOptions;
  fitOptions.model = FitModel::Linear;
  fitOptions.blackLevelCode = 64.0;
  fitOptions.saturationCode = 65535.0;
  const auto fit = fitPhotometric(measureAll(chart, fitOptions), fitOptions);
  ASSERT_TRUE(fit.has_value()) << fit.error().message;
  EXPECT_NEAR(std::get<LinearResponse>(fit->calibration.response).gainCodePerCdM2Us[0], 0.002,
              0.002 * 0.01);
}

// --- refusals -----------------------------------------------------------------------------------

PhotometricFitFailure refusalOf(std::vector<PatchMeasurement> measured,
                                PhotometricFitOptions options = logOptions()) {
  const auto fit = fitPhotometric(measured, options);
  EXPECT_FALSE(fit.has_value());
  return fit.has_value() ? PhotometricFitFailure{} : fit.error();
}

TEST(PhotometricFitRefusal, FewerThanThreeFitPatchesIsRefused) {
  const Chart chart = simulateChart(1, 3.0);
  auto measured = measureAll(chart, logOptions());
  for (std::size_t i = 2; i < 6; ++i) measured[i].spec.check = true;
  const auto failure = refusalOf(measured);
  EXPECT_EQ(failure.cause, PhotometricRefusal::TooFewPatches);
  EXPECT_NE(failure.message.find("at least 3"), std::string::npos) << failure.message;
}

TEST(PhotometricFitRefusal, ASaturatedPatchIsRefusedByName) {
  Chart chart = simulateChart(1, 3.0);
  chart.patches[5].luminanceCdM2 = 5e6;  // beyond the 1e5 cd/m^2 the sensor reaches
  chart.frames = {simulatePatchFrame(chart.patches, 1.0, chart.truth, {})};
  const auto failure = refusalOf(measureAll(chart, logOptions()));
  EXPECT_EQ(failure.cause, PhotometricRefusal::PatchClipped);
  EXPECT_NE(failure.message.find("'p6' is saturated"), std::string::npos) << failure.message;
}

TEST(PhotometricFitRefusal, APatchUnderTheBlackLevelIsRefusedByName) {
  Chart chart = simulateChart(1, 3.0);
  chart.patches[0].luminanceCdM2 = 1e-6;  // below the 1e-3 cd/m^2 the sensor reaches
  chart.frames = {simulatePatchFrame(chart.patches, 1.0, chart.truth, {})};
  const auto failure = refusalOf(measureAll(chart, logOptions()));
  EXPECT_EQ(failure.cause, PhotometricRefusal::PatchClipped);
  EXPECT_NE(failure.message.find("'p1' is under the black level"), std::string::npos)
      << failure.message;
}

TEST(PhotometricFitRefusal, CodesThatDoNotIncreaseWithLuminanceAreRefused) {
  const Chart chart = simulateChart(1, 3.0);
  auto measured = measureAll(chart, logOptions());
  std::swap(measured[2].spec.luminanceCdM2, measured[3].spec.luminanceCdM2);  // swapped labels
  const auto failure = refusalOf(measured);
  EXPECT_EQ(failure.cause, PhotometricRefusal::NotIncreasing);
  EXPECT_NE(failure.message.find("'p3'"), std::string::npos) << failure.message;
}

TEST(PhotometricFitRefusal, NearlyEqualPatchLuminancesAreRefusedNotFitted) {
  Chart chart = simulateChart(1, 3.0);
  for (std::size_t i = 0; i < 6; ++i) chart.patches[i].luminanceCdM2 = 100.0 * (1.0 + 0.01 * i);
  chart.frames = {simulatePatchFrame(chart.patches, 1.0, chart.truth, {})};
  const auto failure = refusalOf(measureAll(chart, logOptions()));
  EXPECT_EQ(failure.cause, PhotometricRefusal::LuminanceSpanTooSmall);
}

TEST(PhotometricFitRefusal, AResidualAboveTheLimitIsRefusedWithTheTable) {
  const Chart chart = simulateChart(1, 3.0);
  auto measured = measureAll(chart, logOptions());
  measured[3].spec.luminanceCdM2 *= 1.25;  // a mislabelled patch bends the fit
  const auto failure = refusalOf(measured);
  EXPECT_EQ(failure.cause, PhotometricRefusal::ResidualTooHigh);
  EXPECT_EQ(failure.patches.size(), measured.size());
}

TEST(PhotometricFitRefusal, ACheckErrorAboveTheLimitIsRefused) {
  const Chart chart = simulateChart(1, 3.0);
  auto measured = measureAll(chart, logOptions());
  measured[7].spec.luminanceCdM2 *= 1.2;
  const auto failure = refusalOf(measured);
  EXPECT_EQ(failure.cause, PhotometricRefusal::CheckErrorTooHigh);
}

}  // namespace
}  // namespace vem::calib
