// Tests of HDR from exposure brackets (paper 002; Debevec & Malik 1997): the response recovered
// from simulated brackets of a real HDRI against the known ("truth") LDR curve, the merged
// luminance against the luminance the simulated sensor integrated, the weighting that must ignore
// clipped and noise-floor codes, and the refusals. Each test is named after the bug it catches.
//
// The recovery never sees the truth curve: only the frames and their exposure times.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <optional>
#include <vector>

#include <glm/mat3x3.hpp>

#include "calib/core/bracket_merge.h"
#include "calib/core/bracket_simulation.h"
#include "calib/core/camera_orientation.h"
#include "calib/core/kannala_brandt.h"
#include "calib/core/response_recovery.h"
#include "mapio/map_file.h"
#include "support/test_maps.h"

namespace vem::calib {
namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 240;
constexpr PixelFormat kRgb8{3, 8};
// Uneven ratios (4, 3, 5.3): equal ones leave the curve a periodic ambiguity (response_recovery.h).
constexpr std::array<double, 4> kExposuresUs{250.0, 1000.0, 3000.0, 16000.0};
constexpr double kMidExposureUs = 1861.0;  // geometric mean of the bracket
constexpr int kSupersamples = 2;
constexpr double kMergeTolerance = 0.03;  // median relative error of merged luminance
// In shadows the frames that see a sample see it at low codes, where 0.8 code of noise is 2-16 %.
constexpr double kShadowTolerance = 0.06;

CameraCalibration ldrTruthCamera(double scaleCdM2, PixelFormat format, int width = kWidth,
                                 int height = kHeight) {
  CameraCalibration truth;
  truth.camera = CameraIdentity{"simulated-ldr", "0", width, height, format};
  truth.photometric = ldrCameraPhotometric(scaleCdM2);
  truth.lens = equidistantLens(width, height, 190.0, 0.48 * height);
  return truth;
}

double medianOf(std::vector<double> values) {
  const auto middle = values.begin() + std::ptrdiff_t(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

// A bracket of the shared "lobby" HDRI (bright lamps up to 1500 x its median), taken by the truth
// camera, with the luminance each sensor pixel integrated (the same supersamples as the
// simulator's, before response and noise).
struct Scene {
  CameraCalibration truth;
  std::vector<RawFrame> frames;          // in kExposuresUs order
  std::vector<double> trueLuminance;     // width * height * 3, cd/m^2
  std::vector<std::uint8_t> insideLens;  // per pixel: every supersample inside the lens circle
};

double upperMedianLuminance(const EnvMap& map) {
  std::vector<double> values;
  for (int y = 0; y < map.height / 2; ++y) {
    for (int x = 0; x < map.width; ++x) {
      const glm::vec3 rgb = map.at(x, y);
      values.push_back(0.2126 * double(rgb.x) + 0.7152 * double(rgb.y) + 0.0722 * double(rgb.z));
    }
  }
  return medianOf(values);
}

void integrateTruth(const RadianceFunction& radiance, Scene& scene) {
  const KannalaBrandtLens& lens = *scene.truth.lens;
  const glm::dmat3 worldFromCam = worldFromCamera(scene.truth.orientation);
  const int width = scene.truth.camera.sensorWidthPx;
  const int height = scene.truth.camera.sensorHeightPx;
  scene.trueLuminance.assign(std::size_t(width * height * 3), 0.0);
  scene.insideLens.assign(std::size_t(width * height), 1);
  const int s = kSupersamples;
  for (int v = 0; v < height; ++v) {
    for (int u = 0; u < width; ++u) {
      glm::dvec3 sum(0.0);
      const std::size_t p = std::size_t(v * width + u);
      for (int j = 0; j < s; ++j) {
        for (int i = 0; i < s; ++i) {
          const glm::dvec2 at(u - 0.5 + (i + 0.5) / s, v - 0.5 + (j + 0.5) / s);
          const auto dir = lens.cameraFromSensor(at);
          if (!dir) scene.insideLens[p] = 0;
          if (dir) sum += radiance(worldFromCam * *dir);
        }
      }
      for (int c = 0; c < 3; ++c) scene.trueLuminance[p * 3 + std::size_t(c)] = sum[c] / (s * s);
    }
  }
}

Scene simulateScene(const RadianceFunction& radiance, CameraCalibration truth) {
  Scene scene;
  scene.truth = std::move(truth);
  SimulationOptions options;
  options.supersamples = kSupersamples;
  options.noise = ldrSensorNoise(7);
  scene.frames = simulateBracket(radiance, scene.truth, kExposuresUs, options);
  integrateTruth(radiance, scene);
  return scene;
}

const Scene* lobbyScene() {
  static const std::optional<Scene> scene = []() -> std::optional<Scene> {
    const auto paths = testing::sharedHdriPaths();
    const auto it = std::find_if(paths.begin(), paths.end(),
                                 [](const auto& p) { return p.filename() == "lobby.exr"; });
    if (it == paths.end()) return std::nullopt;
    const auto map = mapio::loadMap(*it);
    if (!map) return std::nullopt;
    // The map's median luminance reads mid-curve at the bracket's middle exposure.
    const double scale =
        scaleForCode(ldrCameraResponse(), kLdrMidCode, upperMedianLuminance(*map), kMidExposureUs);
    return simulateScene(radianceFromMap(*map), ldrTruthCamera(scale, kRgb8));
  }();
  return scene ? &*scene : nullptr;
}

// Grey shadows: luminance falls by 12 stops around the azimuth, from 1 cd/m^2 (code 200 in the
// longest exposure) down; the short exposures leave most of it in the noise floor.
const Scene& darkRampScene() {
  static const Scene scene = [] {
    const RadianceFunction ramp = [](const glm::dvec3& dir) {
      const double turn = (std::atan2(dir.z, dir.x) + std::numbers::pi) / (2.0 * std::numbers::pi);
      return glm::dvec3(std::exp2(-12.0 * turn));
    };
    const double scale = scaleForCode(ldrCameraResponse(), 200, 1.0, kExposuresUs.back());
    return simulateScene(ramp, ldrTruthCamera(scale, kRgb8, 160, 120));
  }();
  return scene;
}

#define REQUIRE_LOBBY_SCENE(scene)   \
  const Scene* scene = lobbyScene(); \
  if (scene == nullptr)              \
  GTEST_SKIP() << "shared HDRI lobby.exr not found in " << VEM_SHARED_DATA_DIR "/hdri/"

const RecoveredResponse& recoveredFromLobby() {
  static const RecoveredResponse recovered = [] {
    auto result = recoverResponseWithReport(lobbyScene()->frames, ResponseRecoveryOptions{});
    EXPECT_TRUE(result.has_value()) << result.error().message;
    return result.value_or(RecoveredResponse{});
  }();
  return recovered;
}

bool clippedInEveryFrame(const Scene& scene, std::size_t sample, double clippedFrom) {
  return std::all_of(scene.frames.begin(), scene.frames.end(),
                     [&](const RawFrame& f) { return f.codes[sample] >= clippedFrom; });
}

// Median of |merged / (scale truth) - 1| over `samples`, with `scale` the median ratio (one scale
// for every channel).
double medianRelativeError(const MergedBracket& merged, const Scene& scene,
                           const std::vector<std::size_t>& samples, double* scaleOut = nullptr) {
  std::vector<double> ratios;
  for (const std::size_t i : samples) {
    ratios.push_back(double(merged.luminanceCdM2[i]) / scene.trueLuminance[i]);
  }
  const double scale = medianOf(ratios);
  for (double& r : ratios) r = std::abs(r / scale - 1.0);
  if (scaleOut != nullptr) *scaleOut = scale;
  return medianOf(ratios);
}

// Samples inside the lens, with some light, that pass `keep`.
template <class Keep>
std::vector<std::size_t> samplesWhere(const Scene& scene, Keep keep) {
  std::vector<std::size_t> samples;
  for (std::size_t i = 0; i < scene.trueLuminance.size(); ++i) {
    if (scene.insideLens[i / 3] != 0 && scene.trueLuminance[i] > 0.0 && keep(i)) {
      samples.push_back(i);
    }
  }
  return samples;
}

// --- The simulated LDR camera ----------------------------------------------------------------

TEST(BracketSimulation, LdrCurveIncreasesStrictlyWithToeAndShoulder) {
  const TabulatedResponse curve = ldrCameraResponse();
  const std::vector<double>& x = curve.exposureByCode[0];
  ASSERT_EQ(x.size(), 256u);
  EXPECT_DOUBLE_EQ(x[kLdrMidCode], 1.0);
  for (std::size_t z = 1; z < x.size(); ++z) ASSERT_GT(x[z], x[z - 1]) << "code " << z;
  const double stops = std::log2(x[245] / x[10]);
  EXPECT_GT(stops, 8.0);
  EXPECT_LT(stops, 11.0);
  // Shoulder: the top codes cover more exposure per code than a pure 2.4 gamma would.
  EXPECT_GT(x[255] / x[245], std::pow(255.0 / 245.0, 2.4) * 1.5);
}

TEST(BracketSimulation, FramesOfOneBracketDoNotShareTheirNoise) {
  CameraCalibration truth = ldrTruthCamera(1000.0, PixelFormat{1, 8});
  truth.camera.sensorWidthPx = 40;
  truth.camera.sensorHeightPx = 30;
  truth.lens = equidistantLens(40, 30, 190.0, 40.0);  // the whole sensor inside the circle
  SimulationOptions options;
  options.noise = ldrSensorNoise(3);
  const std::array<double, 2> sameExposure{1000.0, 1000.0};
  const auto frames = simulateBracket([](const glm::dvec3&) { return glm::dvec3(1.0); }, truth,
                                      sameExposure, options);
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[1].exposureUs, 1000.0);
  EXPECT_NE(frames[0].codes, frames[1].codes);
}

// --- Response recovery -------------------------------------------------------------------------

TEST(ResponseRecovery, RecoveredCurveMatchesTruthUpToScale) {
  REQUIRE_LOBBY_SCENE(scene);
  const RecoveredResponse& recovered = recoveredFromLobby();
  ASSERT_EQ(recovered.channels, 3);
  const std::vector<double> truth = ldrCameraResponse().exposureByCode[0];
  for (std::size_t c = 0; c < 3; ++c) {
    const std::vector<double>& curve = recovered.response.exposureByCode[c];
    ASSERT_EQ(curve.size(), 256u);
    std::vector<double> ratios;
    for (std::size_t z = 10; z <= 245; ++z) ratios.push_back(curve[z] / truth[z]);
    const double scale = medianOf(ratios);
    double worst = 0.0;
    for (const double r : ratios) worst = std::max(worst, std::abs(r / scale - 1.0));
    EXPECT_LT(worst, 0.05) << "channel " << c;
    std::printf(
        "[ response ] channel %zu: codes %d..%d, %.2f stops, %d fixed, max error %.2f%% "
        "over codes 10..245\n",
        c, recovered.perChannel[c].firstCode, recovered.perChannel[c].lastCode,
        recovered.perChannel[c].rangeStops, recovered.perChannel[c].fixedCodes, 100.0 * worst);
  }
}

TEST(ResponseRecovery, MonoFramesFillChannelZeroFromTheirOwnCodes) {
  // A mono frame has one code per pixel: reading it with an RGB stride, or fitting a replicated
  // channel other than the frame's, gives a wrong or empty curve.
  const PhotometricCalibration truth = ldrCameraPhotometric(1.0);
  std::vector<RawFrame> frames;
  for (const double exposureUs : {1.0, 4.0, 16.0}) {
    RawFrame frame = RawFrame::blank(64, 64, PixelFormat{1, 8});
    frame.exposureUs = exposureUs;
    for (std::size_t p = 0; p < frame.codes.size(); ++p) {
      const double luminance = 0.01 * std::pow(2.0, 12.0 * double(p) / double(frame.codes.size()));
      frame.codes[p] =
          std::uint16_t(std::lround(codeFromLuminance(truth, 0, luminance, exposureUs, 1.0)));
    }
    frames.push_back(std::move(frame));
  }
  const auto recovered = recoverResponseWithReport(frames, ResponseRecoveryOptions{});
  ASSERT_TRUE(recovered.has_value()) << recovered.error().message;
  EXPECT_EQ(recovered->channels, 1);
  EXPECT_TRUE(recovered->response.exposureByCode[1].empty());
  EXPECT_TRUE(recovered->response.exposureByCode[2].empty());
  const std::vector<double>& curve = recovered->response.exposureByCode[0];
  const std::vector<double> expected = ldrCameraResponse().exposureByCode[0];
  ASSERT_EQ(curve.size(), 256u);
  for (std::size_t z = 20; z <= 240; z += 10) {
    EXPECT_NEAR(curve[z] / expected[z], 1.0, 0.05) << "code " << z;
  }
}

TEST(ResponseRecovery, RefusesASingleFrame) {
  REQUIRE_LOBBY_SCENE(scene);
  const auto result = recoverResponse(std::span(scene->frames).first(1), ResponseRecoveryOptions{});
  ASSERT_FALSE(result.has_value());
  EXPECT_EQ(result.error().cause, ResponseRefusal::TooFewExposures);
  EXPECT_NE(result.error().message.find("2 or more exposures"), std::string::npos);
}

TEST(ResponseRecovery, RefusesTwoEqualExposures) {
  REQUIRE_LOBBY_SCENE(scene);
  std::vector<RawFrame> frames = scene->frames;
  frames[2].exposureUs = frames[0].exposureUs;
  const auto result = recoverResponse(frames, ResponseRecoveryOptions{});
  ASSERT_FALSE(result.has_value());
  EXPECT_EQ(result.error().cause, ResponseRefusal::EqualExposures);
  EXPECT_NE(result.error().message.find("frames 1 and 3"), std::string::npos)
      << result.error().message;
}

TEST(ResponseRecovery, RefusesSixteenBitFrames) {
  REQUIRE_LOBBY_SCENE(scene);
  std::vector<RawFrame> frames = scene->frames;
  frames[1].format.bits = 16;
  const auto result = recoverResponse(frames, ResponseRecoveryOptions{});
  ASSERT_FALSE(result.has_value());
  EXPECT_EQ(result.error().cause, ResponseRefusal::NotEightBit);
  EXPECT_NE(result.error().message.find("frame 2 is RGB16"), std::string::npos)
      << result.error().message;
}

TEST(ResponseRecovery, RefusesFramesOfDifferentSizes) {
  REQUIRE_LOBBY_SCENE(scene);
  std::vector<RawFrame> frames = scene->frames;
  frames[3] = RawFrame::blank(kWidth / 2, kHeight, kRgb8);
  frames[3].exposureUs = 64000.0;
  const auto result = recoverResponse(frames, ResponseRecoveryOptions{});
  ASSERT_FALSE(result.has_value());
  EXPECT_EQ(result.error().cause, ResponseRefusal::FramesDiffer);
}

TEST(ResponseRecovery, RefusesExposuresSpanningLessThanAStop) {
  REQUIRE_LOBBY_SCENE(scene);
  std::vector<RawFrame> frames(scene->frames.begin(), scene->frames.begin() + 2);
  frames[1].exposureUs = 1.5 * frames[0].exposureUs;
  const auto result = recoverResponse(frames, ResponseRecoveryOptions{});
  ASSERT_FALSE(result.has_value());
  EXPECT_EQ(result.error().cause, ResponseRefusal::SpanTooSmall);
}

TEST(ResponseRecovery, RefusesSwappedExposureLabels) {
  // Exposure times given in the wrong order make the fitted curve fall: refused, not fixed up.
  REQUIRE_LOBBY_SCENE(scene);
  std::vector<RawFrame> frames = scene->frames;
  std::swap(frames[0].exposureUs, frames[3].exposureUs);
  const auto result = recoverResponse(frames, ResponseRecoveryOptions{});
  ASSERT_FALSE(result.has_value());
  EXPECT_EQ(result.error().cause, ResponseRefusal::NotIncreasing) << result.error().message;
}

// --- Merging -----------------------------------------------------------------------------------

TEST(BracketMerge, MergedLuminanceMatchesTruthUpToOneScale) {
  REQUIRE_LOBBY_SCENE(scene);
  const RecoveredResponse& recovered = recoveredFromLobby();
  const PhotometricCalibration calibration{recovered.response, 0.0, 255.0};
  const BracketWeighting weighting;
  const MergedBracket merged = mergeBracket(scene->frames, calibration, weighting);
  ASSERT_EQ(merged.luminanceCdM2.size(), scene->trueLuminance.size());
  const double clippedFrom = 255.0 - weighting.saturationMarginCode;
  const auto samples = samplesWhere(
      *scene, [&](std::size_t i) { return !clippedInEveryFrame(*scene, i, clippedFrom); });
  ASSERT_GT(samples.size(), scene->trueLuminance.size() / 2);
  double scale = 0.0;
  const double error = medianRelativeError(merged, *scene, samples, &scale);
  EXPECT_LT(error, kMergeTolerance);
  EXPECT_GT(merged.clippedSamples, 0u);  // the lamps
  std::printf(
      "[ merge    ] median error %.2f%% over %zu samples (scale %.4g); clipped %zu, black "
      "%zu, gap %zu samples\n",
      100.0 * error, samples.size(), scale, merged.clippedSamples, merged.blackSamples,
      merged.gapSamples);
}

// How many frames read sample i at or above `from` (clipped), and at or below `upTo` (noise floor).
int framesAtOrAbove(const Scene& scene, std::size_t i, double from) {
  return int(std::count_if(scene.frames.begin(), scene.frames.end(),
                           [&](const RawFrame& f) { return f.codes[i] >= from; }));
}
int framesAtOrBelow(const Scene& scene, std::size_t i, double upTo) {
  return int(std::count_if(scene.frames.begin(), scene.frames.end(),
                           [&](const RawFrame& f) { return f.codes[i] <= upTo; }));
}

// The hat that stops at the black level and at saturation is what keeps a clipped code (which
// reads far less than the scene: the code of saturation) out of a sample some other frame sees.
// Samples next to the lamps, clipped in two frames or more but seen by another, must come out
// within the merge tolerance; through a hat that lets clipped codes in, they come out beyond twice
// that, so a weighting with that bug fails the first check.
TEST(BracketMerge, ClippedCodesCarryNoWeightNearBrightRegions) {
  REQUIRE_LOBBY_SCENE(scene);
  const PhotometricCalibration& truth = *scene->truth.photometric;  // only weights under test
  const BracketWeighting weighting;
  const double clippedFrom = 255.0 - weighting.saturationMarginCode;
  const auto bright = samplesWhere(*scene, [&](std::size_t i) {
    const int clipped = framesAtOrAbove(*scene, i, clippedFrom);
    return clipped >= 2 && clipped < int(scene->frames.size());
  });
  ASSERT_GT(bright.size(), 500u);
  const double error =
      medianRelativeError(mergeBracket(scene->frames, truth, weighting), *scene, bright);
  EXPECT_LT(error, kMergeTolerance);
  const BracketWeighting leaky{weighting.blackMarginCode, -64.0};  // w(255) = 0.4
  const double leakyError =
      medianRelativeError(mergeBracket(scene->frames, truth, leaky), *scene, bright);
  EXPECT_GT(leakyError, 2.0 * kMergeTolerance);
  std::printf(
      "[ weights  ] %zu bright samples: median error %.2f%%, %.2f%% with clipped codes "
      "weighed\n",
      bright.size(), 100.0 * error, 100.0 * leakyError);
}

// The same in the shadows: a noise-floor code reads about nothing of the scene (0, or noise).
// Samples that two exposures or more leave in the noise floor but another sees.
TEST(BracketMerge, NoiseFloorCodesCarryNoWeightInDarkRegions) {
  const Scene& scene = darkRampScene();
  const PhotometricCalibration& truth = *scene.truth.photometric;
  const BracketWeighting weighting;
  const auto dark = samplesWhere(scene, [&](std::size_t i) {
    const int black = framesAtOrBelow(scene, i, weighting.blackMarginCode);
    return black >= 2 && black < int(scene.frames.size());
  });
  ASSERT_GT(dark.size(), 2000u);
  const double error =
      medianRelativeError(mergeBracket(scene.frames, truth, weighting), scene, dark);
  EXPECT_LT(error, kShadowTolerance);
  const BracketWeighting leaky{-64.0, weighting.saturationMarginCode};  // w(0) = 0.4
  const double leakyError =
      medianRelativeError(mergeBracket(scene.frames, truth, leaky), scene, dark);
  EXPECT_GT(leakyError, 2.0 * kShadowTolerance);
  std::printf(
      "[ weights  ] %zu dark samples: median error %.2f%%, %.2f%% with noise-floor codes "
      "weighed\n",
      dark.size(), 100.0 * error, 100.0 * leakyError);
}

// Three one-pixel RGB frames given out of exposure order, each channel a case: R clipped
// everywhere, G in the noise floor everywhere, B in the noise floor at 1 ms but clipped at 4 ms
// and 16 ms (a gap).
TEST(BracketMerge, UnweighedSamplesReadTheShortestClippedOrTheLongestFrame) {
  const PhotometricCalibration truth = ldrCameraPhotometric(1.0);
  std::vector<RawFrame> frames;
  const std::array<double, 3> exposuresUs{4000.0, 1000.0, 16000.0};
  const std::array<std::array<std::uint16_t, 3>, 3> codes{
      {{255, 2, 255}, {254, 1, 3}, {255, 3, 255}}};
  for (std::size_t k = 0; k < 3; ++k) {
    RawFrame frame = RawFrame::blank(1, 1, kRgb8);
    frame.exposureUs = exposuresUs[k];
    frame.codes.assign(codes[k].begin(), codes[k].end());
    frames.push_back(std::move(frame));
  }
  const MergedBracket merged = mergeBracket(frames, truth, BracketWeighting{});
  EXPECT_EQ(merged.clippedSamples, 1u);
  EXPECT_EQ(merged.blackSamples, 1u);
  EXPECT_EQ(merged.gapSamples, 1u);
  const auto reading = [&](int channel, double code, double exposureUs) {
    return float(luminanceFromCode(truth, channel, code, exposureUs, 1.0));
  };
  EXPECT_FLOAT_EQ(merged.luminanceCdM2[0], reading(0, 254.0, 1000.0));  // shortest
  EXPECT_FLOAT_EQ(merged.luminanceCdM2[1], reading(1, 3.0, 16000.0));   // longest
  EXPECT_FLOAT_EQ(merged.luminanceCdM2[2], reading(2, 255.0, 4000.0));  // shortest clipped
}

TEST(BracketMerge, EachFrameIsReadWithItsOwnExposureAndGain) {
  // Noise-free frames of a luminance ramp at different exposures and gains, given out of order:
  // a merge that read every frame through the first frame's table, or ignored gain, would be off
  // by the exposure ratios.
  const PhotometricCalibration truth = ldrCameraPhotometric(1.0);
  const std::array<std::pair<double, double>, 3> settings{
      {{400.0, 2.0}, {100.0, 1.0}, {3200.0, 1.0}}};
  std::vector<double> luminance(256);
  for (std::size_t p = 0; p < luminance.size(); ++p)
    luminance[p] = 1e-4 * std::pow(2.0, 0.05 * double(p));
  std::vector<RawFrame> frames;
  for (const auto& [exposureUs, gain] : settings) {
    RawFrame frame = RawFrame::blank(16, 16, PixelFormat{1, 8});
    frame.exposureUs = exposureUs;
    frame.gain = gain;
    for (std::size_t p = 0; p < luminance.size(); ++p) {
      frame.codes[p] =
          std::uint16_t(std::lround(codeFromLuminance(truth, 0, luminance[p], exposureUs, gain)));
    }
    frames.push_back(std::move(frame));
  }
  const MergedBracket merged = mergeBracket(frames, truth, BracketWeighting{});
  int checked = 0;
  for (std::size_t p = 0; p < luminance.size(); ++p) {
    // Seen where a code is a small step of exposure (< 4 %): quantisation stays below 2 %.
    const bool seen = std::any_of(frames.begin(), frames.end(), [&](const RawFrame& f) {
      return f.codes[p] >= 16 && f.codes[p] <= 235;
    });
    if (!seen) continue;
    EXPECT_NEAR(double(merged.luminanceCdM2[p]) / luminance[p], 1.0, 0.03) << "pixel " << p;
    ++checked;
  }
  EXPECT_GT(checked, 150);
}

// The merge check compares two frames only where both weigh the sample: a clipped or noise-floor
// code in the comparison would report disagreement where the merge has none.
TEST(BracketMerge, ConsistencyOfATruthfulBracketIsTheNoiseLevel) {
  REQUIRE_LOBBY_SCENE(scene);
  const PhotometricCalibration& truth = *scene->truth.photometric;
  const BracketWeighting weighting;
  std::vector<BracketLut> luts;
  for (const RawFrame& f : scene->frames) {
    luts.push_back(buildBracketLut(truth, f.format, f.exposureUs, f.gain, weighting));
  }
  std::size_t weighedPairs = 0;
  for (std::size_t i = 0; i < scene->trueLuminance.size(); ++i) {
    const auto seen = std::count_if(scene->frames.begin(), scene->frames.end(), [&](const auto& f) {
      return bracketWeight(truth, weighting, f.codes[i]) > 0.0;
    });
    weighedPairs += std::size_t(seen * (seen - 1) / 2);
  }
  const BracketConsistency good = bracketConsistency(scene->frames, luts);
  EXPECT_EQ(good.comparedPairs, weighedPairs);
  EXPECT_LT(good.medianPercent, 5.0);
  // Wrong exposure times (the second frame read as if twice as long) disagree by about half.
  luts[1] =
      buildBracketLut(truth, kRgb8, 2.0 * scene->frames[1].exposureUs, 1.0, BracketWeighting{});
  const BracketConsistency wrong = bracketConsistency(scene->frames, luts);
  EXPECT_GT(wrong.medianPercent, 20.0);
}

}  // namespace
}  // namespace vem::calib
