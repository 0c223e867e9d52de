// The merged stream through vemd's pipeline, as the daemon runs it: the virtual camera's file
// (describe().calibrationToml) creates the Pipeline, and its lights are those an ideal HDR camera
// gives of the same scene. Also measures ghosting: what motion between the bracket's frames does.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>

#include <gtest/gtest.h>

#include "calib/core/bracket_simulation.h"
#include "calib/io/camera_file.h"
#include "cameras/bracketing/bracketing_source.h"
#include "cameras/bracketing/ldr_camera_fake.h"
#include "core/color.h"
#include "mapio/map_file.h"
#include "synth/hdri_scene.h"
#include "synth/sky_scene.h"
#include "synth/synthetic_camera.h"
#include "vemd/pipeline.h"
#include "vemd/pipeline_setup.h"

namespace vem::cameras {
namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 256;
constexpr double kRateHz = 30.0;

vem::ProcessingOptions smallMaps() {
  vem::ProcessingOptions o;
  o.mapWidth = 512;
  o.mapHeight = 128;
  o.lightCount = 256;
  o.clustering = false;
  return o;
}

struct BracketRun {
  std::shared_ptr<const synth::SyntheticScene> scene;
  testing::LdrFakeCamera* camera = nullptr;
  std::unique_ptr<BracketingSource> source;
};

// An 8-bit RGB camera whose shortest exposure (50 us) reads `brightestCdM2` at code 240.
BracketRun bracketRun(std::shared_ptr<const synth::SyntheticScene> scene, double brightestCdM2,
                      BracketSettings settings) {
  const double scale =
      calib::scaleForCode(calib::ldrCameraResponse(), 240, brightestCdM2, settings.baseExposureUs);
  testing::LdrFakeOptions options;
  options.rateHz = kRateHz;
  options.samplesPerAxis = 3;
  options.noise = calib::ldrSensorNoise(11);
  auto camera = std::make_unique<testing::LdrFakeCamera>(
      testing::ldrCamera(kWidth, kHeight, 3, scale), scene, options);
  BracketRun run{scene, camera.get(), nullptr};
  auto made = BracketingSource::create(std::move(camera), settings);
  EXPECT_TRUE(made.has_value()) << (made ? "" : made.error().message);
  if (made) run.source = std::move(*made);
  return run;
}

// The scene time of a merged frame: its captureTsNs on the fake camera's clock.
double sceneTimeS(const testing::LdrFakeCamera& camera, const vem::CapturedFrame& frame) {
  return double(frame.captureTsNs - camera.captureTsNs(0)) / 1e9;
}

// What an ideal HDR camera (the virtual sensor itself, noiseless) delivers of the scene at t.
vem::CapturedFrame idealFrame(const BracketRun& run, double timeS) {
  auto calibration =
      calib::io::parseCameraFile(run.source->describe().calibrationToml, "the virtual camera");
  EXPECT_TRUE(calibration.has_value());
  synth::SyntheticCamera ideal(*calibration, synth::SyntheticCameraOptions{3, {}});
  vem::CapturedFrame out;
  out.frame = ideal.render(run.scene->at(timeS), 0);
  out.frame.exposureUs = 1.0;
  return out;
}

// The luminance-weighted direction of the polar map's pixels above 1 % of its brightest.
glm::dvec3 brightestDirection(const EnvMap& map) {
  float peak = 0.0F;
  for (int y = 0; y < map.height; ++y) {
    for (int x = 0; x < map.width; ++x) peak = std::max(peak, float(luminance(map.at(x, y))));
  }
  glm::dvec3 sum(0.0);
  for (int y = 0; y < map.height; ++y) {
    for (int x = 0; x < map.width; ++x) {
      const double l = luminance(map.at(x, y));
      if (l > 0.01 * double(peak)) {
        sum += l * pixelSolidAngleSr(map.layout, map.width, map.height, y) *
               pixelCentreDirection(map, x, y);
      }
    }
  }
  return glm::normalize(sum);
}

double angleDeg(const glm::dvec3& a, const glm::dvec3& b) {
  return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0, 1.0)) * 180.0 /
         std::numbers::pi;
}

TEST(BracketingPipeline, LightsOfTheMergedSkyMatchAnIdealHdrCameraAndPointAtTheSun) {
  BracketSettings settings;
  settings.count = 5;
  settings.stopsApart = 3.0;
  settings.baseExposureUs = 50.0;
  // The sun stands still here: a sun disc (0.53 deg) a little smaller than a pixel (0.6 deg) is hit
  // by a varying count of the 3 x 3 samples per pixel as it moves, so a moving sun's power
  // flickers by tens of percent from frame to frame in any simulated camera (the ghosting test
  // below measures the moving sun).
  synth::SkyParams sky;
  sky.arc.speedDegPerS = 0.0;
  BracketRun run = bracketRun(std::make_shared<synth::SkyScene>(sky), 1e5, settings);
  ASSERT_TRUE(run.source);
  const vem::SourceDescription d = run.source->describe();
  auto pipeline = vemd::pipelineFromCameraFile(d.calibrationToml, d.spec, smallMaps());
  ASSERT_TRUE(pipeline.has_value()) << pipeline.error();
  auto idealPipeline = vemd::pipelineFromCameraFile(d.calibrationToml, "ideal", smallMaps());
  ASSERT_TRUE(idealPipeline.has_value());

  for (int group = 0; group < 2; ++group) {
    auto merged = run.source->next();
    ASSERT_TRUE(merged.has_value()) << merged.error().message;
    ASSERT_EQ(pipeline->frameProblem(merged->frame), std::nullopt);
    const vem::ProcessedFrame& got = pipeline->process(*merged);
    const double lumSr = got.lights.luminanceSr;
    const glm::dvec3 brightest = brightestDirection(*got.polar);

    const double timeS = sceneTimeS(*run.camera, *merged);
    const vem::CapturedFrame truthFrame = idealFrame(run, timeS);
    const vem::ProcessedFrame& truth = idealPipeline->process(truthFrame);
    const glm::dvec3 sun = *run.scene->at(timeS).sunDirWorld;
    const double powerError = lumSr / truth.lights.luminanceSr - 1.0;
    std::printf(
        "[ pipeline ] sky group %d at t = %.3f s: power %.4g vs ideal %.4g cd/m2 sr "
        "(%+.2f %%); brightest direction %.3f deg from the sun; %zu saturated, %zu dark "
        "samples\n",
        group, timeS, lumSr, truth.lights.luminanceSr, 100.0 * powerError, angleDeg(brightest, sun),
        run.source->lastMergeStats().saturatedSamples, run.source->lastMergeStats().darkSamples);
    EXPECT_LT(std::abs(powerError), 0.03);
    EXPECT_LT(angleDeg(brightest, sun), 1.0);
    run.source->recycle(std::move(*merged));
  }
}

// Mean |ln(L / L_truth)| over samples both read above 0 and below saturation.
double meanLogError(const vem::RawFrame& merged, const vem::RawFrame& truth,
                    const calib::PhotometricCalibration& response) {
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t s = 0; s < merged.codes.size(); ++s) {
    if (merged.codes[s] == 0 || truth.codes[s] == 0 || merged.codes[s] == 65535 ||
        truth.codes[s] == 65535) {
      continue;
    }
    const int c = int(s % 3);
    sum += std::abs(calib::luminanceFromCode(response, c, merged.codes[s], 1.0, 1.0) -
                    calib::luminanceFromCode(response, c, truth.codes[s], 1.0, 1.0)) /
           calib::luminanceFromCode(response, c, truth.codes[s], 1.0, 1.0);
    ++n;
  }
  return n ? sum / double(n) : 0.0;
}

// Ghosting: the frames of a group are taken up to (K - 1) / rate apart, so a moving scene is
// merged from K different instants. The merged frame stands for the middle frame's time: it is
// closer to the truth then than at the first frame's time, and a static scene has no ghost.
TEST(BracketingPipeline, MotionBetweenBracketsGhostsAndTheMiddleFrameTimeFitsBest) {
  const std::string path = std::string(VEM_SHARED_DATA_DIR) + "/hdri/esplanade.exr";
  auto map = mapio::loadMap(path);
  ASSERT_TRUE(map.has_value()) << path;
  BracketSettings settings;
  settings.count = 5;
  settings.stopsApart = 2.5;
  settings.baseExposureUs = 50.0;
  double staticError = 0.0;
  for (const double panDegPerS : {0.0, 10.0, 45.0}) {
    auto scene =
        std::make_shared<synth::HdriScene>(*map, "esplanade", synth::HdriParams{1.0, panDegPerS});
    BracketRun run = bracketRun(scene, 8.2e3, settings);
    ASSERT_TRUE(run.source);
    auto merged = run.source->next();
    ASSERT_TRUE(merged.has_value());
    const calib::PhotometricCalibration response = run.source->sensor().photometric();
    const double middleS = sceneTimeS(*run.camera, *merged);
    const double firstS = middleS - double(settings.count / 2) / kRateHz;
    const double atMiddle = meanLogError(merged->frame, idealFrame(run, middleS).frame, response);
    const double atFirst = meanLogError(merged->frame, idealFrame(run, firstS).frame, response);
    std::printf(
        "[ ghosting ] esplanade turning %.0f deg/s, K = %d at %.0f Hz (group spans %.2f "
        "deg): mean error %.2f %% vs the truth at the middle frame, %.2f %% at the first\n",
        panDegPerS, settings.count, kRateHz, panDegPerS * double(settings.count - 1) / kRateHz,
        100.0 * atMiddle, 100.0 * atFirst);
    if (panDegPerS == 0.0) {
      staticError = atMiddle;
      EXPECT_NEAR(atMiddle, atFirst, 1e-12);
    } else {
      EXPECT_LT(atMiddle, atFirst);
      EXPECT_GT(atMiddle, staticError);
    }
  }
  EXPECT_LT(staticError, 0.03);
}

// The moving sun of the sky scene at 30 Hz. Only the shortest exposure (the first frame of each
// group) sees the sun unclipped, so the merged sun stands where it was at that frame, (K - 1) / 2
// frames before the merged frame's captureTsNs: at the default 1 deg/s (a 240x time lapse) that is
// 0.07 deg, within the 1 degree the lights need; a fast 20 deg/s sun is 1.3 deg behind.
TEST(BracketingPipeline, AMovingSunIsMergedWhereTheShortestExposureSawIt) {
  BracketSettings settings;
  settings.count = 5;
  settings.stopsApart = 3.0;
  settings.baseExposureUs = 50.0;
  for (const double speed : {1.0, 20.0}) {
    synth::SkyParams sky;
    sky.arc.speedDegPerS = speed;
    BracketRun run = bracketRun(std::make_shared<synth::SkyScene>(sky), 1e5, settings);
    ASSERT_TRUE(run.source);
    const vem::SourceDescription d = run.source->describe();
    auto pipeline = vemd::pipelineFromCameraFile(d.calibrationToml, d.spec, smallMaps());
    ASSERT_TRUE(pipeline.has_value());
    auto merged = run.source->next();
    ASSERT_TRUE(merged.has_value());
    const vem::ProcessedFrame& got = pipeline->process(*merged);
    const double middleS = sceneTimeS(*run.camera, *merged);
    const double firstS = middleS - double(settings.count / 2) / kRateHz;
    const glm::dvec3 brightest = brightestDirection(*got.polar);
    const double atMiddle = angleDeg(brightest, *run.scene->at(middleS).sunDirWorld);
    const double atFirst = angleDeg(brightest, *run.scene->at(firstS).sunDirWorld);
    std::printf(
        "[ ghosting ] sky sun at %.0f deg/s, K = %d at %.0f Hz (sun moves %.2f deg per "
        "group): brightest direction %.3f deg from the sun at the middle frame, %.3f deg "
        "at the first\n",
        speed, settings.count, kRateHz, speed * double(settings.count - 1) / kRateHz, atMiddle,
        atFirst);
    EXPECT_LT(atFirst, 0.3);
    if (speed < 10.0) {
      EXPECT_LT(atMiddle, 1.0);
    } else {
      EXPECT_GT(atMiddle, 1.0);
    }
  }
}

}  // namespace
}  // namespace vem::cameras
