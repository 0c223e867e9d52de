// The acceptance test: raw frames of real HDRIs simulated through a known camera, calibrated
// back from simulated grey patches and simulated checkerboards only (never from the true
// parameters), and applied to the raw frames. The recovered polar maps must hold the true luminance
// (median error under 3 % over the field of view) in the true directions (within 0.2 degrees), and
// the lights computed from them must light a surface as the truth does (irradiance within 2 % RMS).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "calib/core/camera_simulator.h"
#include "calib/core/checkerboard.h"
#include "calib/core/fisheye_fit.h"
#include "calib/core/photometric_fit.h"
#include "calib/core/polar_remap.h"
#include "core/color.h"
#include "core/default_pattern.h"
#include "core/irradiance.h"
#include "core/light_generator.h"
#include "core/sampling_tables.h"
#include "core/sphere_points.h"
#include "mapio/map_file.h"
#include "support/test_cameras.h"
#include "support/test_maps.h"

namespace vem::calib {
namespace {

constexpr int kSensorWidth = 800;
constexpr int kSensorHeight = 640;
constexpr int kMapWidth = 256;
constexpr int kMapHeight = 64;

// The truth camera, and the calibration recovered from its simulated calibration frames.
struct RoundTrip {
  CameraCalibration truth;
  CameraCalibration recovered;
  bool complete = false;  // both calibrations succeeded
};

std::optional<PhotometricCalibration> calibratePhotometric(const CameraCalibration& truth) {
  const std::vector<PatchSpec> patches = testing::greyChart(kSensorWidth, kSensorHeight);
  std::vector<RawFrame> frames;
  for (std::uint64_t seed : {11u, 12u}) {
    SimulationOptions options;
    options.noise = {3.0, 0.0, seed};
    frames.push_back(simulatePatchFrame(patches, 1.0, truth, options));
  }
  PhotometricFitOptions fitOptions;
  fitOptions.blackLevelCode = 64.0;
  fitOptions.saturationCode = 4095.0;
  std::vector<PatchMeasurement> measured;
  for (const PatchSpec& p : patches) measured.push_back(measurePatch(frames, p, 64.0, 4095.0));
  const auto fit = fitPhotometric(measured, fitOptions);
  if (!fit) {
    ADD_FAILURE() << "photometric calibration refused: " << fit.error().message;
    return {};
  }
  return fit->calibration;
}

std::optional<KannalaBrandtLens> calibrateLens(const CameraCalibration& truth) {
  const Checkerboard board{9, 6, 60.0};
  const auto poses =
      boardPosesCoveringLens(board, *truth.lens, kSensorWidth, kSensorHeight, 12, 7);
  std::vector<RawFrame> frames;
  for (std::size_t i = 0; i < poses.size(); ++i) {
    SimulationOptions options;
    options.noise = {2.0, 0.0, 100 + i};
    frames.push_back(simulateBoardView(board, poses[i], truth, options, 400.0, 8.0));
  }
  FisheyeFitOptions fitOptions;
  fitOptions.fovDeg = 190.0;
  const auto fit = calibrateFisheye(frames, board, fitOptions);
  if (!fit) {
    ADD_FAILURE() << "fisheye calibration refused: " << fit.error().message;
    return {};
  }
  std::printf("fisheye fit: RMS %.3f px over %d views, %d corners\n", fit->quality.rmsReprojectionPx,
              fit->quality.views, fit->quality.corners);
  return fit->lens;
}

const RoundTrip& roundTrip() {
  static const RoundTrip trip = [] {
    RoundTrip t;
    t.truth = testing::cameraTruth(kSensorWidth, kSensorHeight, 3);
    t.truth.orientation = {25.0, 0.0, 0.0};
    t.recovered = t.truth;  // identity and orientation are given, not calibrated
    t.recovered.photometric = calibratePhotometric(t.truth);
    t.recovered.lens = calibrateLens(t.truth);
    t.complete = t.recovered.photometric.has_value() && t.recovered.lens.has_value();
    return t;
  }();
  return trip;
}

double angleDeg(const glm::dvec3& a, const glm::dvec3& b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)) * 180.0 / std::numbers::pi;
}

TEST(CalibrationRoundTrip, RecoveredLensPointsEverySensorPixelWithinAFifthOfADegree) {
  const RoundTrip& t = roundTrip();
  ASSERT_TRUE(t.complete);
  double worst = 0.0;
  double worstThetaDeg = 0.0;
  int compared = 0;
  for (int v = 0; v < kSensorHeight; v += 8) {
    for (int u = 0; u < kSensorWidth; u += 8) {
      const auto truthDir = t.truth.lens->cameraFromSensor({u, v});
      if (!truthDir) continue;
      const auto recoveredDir = t.recovered.lens->cameraFromSensor({u, v});
      ASSERT_TRUE(recoveredDir.has_value()) << u << "," << v << " lies inside the true circle";
      const double error = angleDeg(*truthDir, *recoveredDir);
      if (error > worst) {
        worst = error;
        worstThetaDeg = std::acos(truthDir->z) * 180.0 / std::numbers::pi;
      }
      ++compared;
    }
  }
  std::printf("directions: worst %.4f deg (at theta %.1f deg) over %d sensor points up to 95 deg\n",
              worst, worstThetaDeg, compared);
  EXPECT_LT(worst, 0.2);
  EXPECT_GT(compared, 4000);
}

struct MapResult {
  double medianLuminanceError = 0.0;
  double irradianceError = 0.0;       // recovered map's lights against the true map
  double truthLightsError = 0.0;      // the true map's own lights (sampling error alone)
};

MapResult roundTripMap(const EnvMap& environment) {
  const RoundTrip& t = roundTrip();
  SimulationOptions options;
  options.noise = {3.0, 0.0, 5};
  const RadianceFunction radiance = radianceFromMap(environment);
  const RawFrame raw = simulateFrame(radiance, t.truth, options);

  const PolarRemap remap = buildPolarRemap(*t.recovered.lens, t.recovered.orientation,
                                           kSensorWidth, kSensorHeight, MapLayout::Hemisphere,
                                           kMapWidth, kMapHeight);
  EnvMap recovered;
  applyPolarRemap(remap, raw,
                  buildCodeToLuminanceLut(*t.recovered.photometric, raw.format, raw.exposureUs,
                                          raw.gain),
                  recovered);
  EnvMap truthMap = EnvMap::filled(MapLayout::Hemisphere, kMapWidth, kMapHeight, glm::vec3(0.0f));
  for (int y = 0; y < kMapHeight; ++y) {
    for (int x = 0; x < kMapWidth; ++x) {
      truthMap.set(x, y, glm::vec3(radiance(pixelCentreDirection(truthMap, x, y))));
    }
  }
  MapResult result;
  std::vector<double> errors;
  const auto mask = remap.validMask();
  for (int y = 0; y < kMapHeight; ++y) {
    for (int x = 0; x < kMapWidth; ++x) {
      if (!mask[std::size_t(y) * kMapWidth + std::size_t(x)]) continue;
      const double truthY = luminance(truthMap.at(x, y));
      if (truthY > 0.0) errors.push_back(std::abs(luminance(recovered.at(x, y)) / truthY - 1.0));
    }
  }
  EXPECT_GT(remap.validFraction(), 0.999) << "a 190-degree lens sees the whole sky";
  std::ranges::nth_element(errors, errors.begin() + std::ptrdiff_t(errors.size() / 2));
  result.medianLuminanceError = errors[errors.size() / 2];

  const auto pattern = defaultSamplingPattern(MapLayout::Hemisphere).first(1024);
  const auto normals = fibonacciSphere(64);
  const auto exact = irradianceFromMap(truthMap, normals);
  const LightSet lights =
      generateLights(buildSamplingTables(recovered), pattern, SamplerKind::Havran);
  result.irradianceError = relativeRmsError(irradianceFromLights(lights.lights, normals), exact);
  const LightSet truthLights =
      generateLights(buildSamplingTables(truthMap), pattern, SamplerKind::Havran);
  result.truthLightsError =
      relativeRmsError(irradianceFromLights(truthLights.lights, normals), exact);
  return result;
}

TEST(CalibrationRoundTrip, RecoveredMapsHoldTrueLuminanceAndLightSurfacesAsTheTruthDoes) {
  ASSERT_TRUE(roundTrip().complete);
  const auto paths = testing::sharedHdriPaths();
  ASSERT_GE(paths.size(), 6u) << "the shared HDRIs are missing under " << VEM_SHARED_DATA_DIR;
  for (std::size_t i = 0; i < paths.size(); i += 3) {
    const auto environment = mapio::loadMap(paths[i], MapLayout::Sphere);
    ASSERT_TRUE(environment.has_value()) << environment.error().message;
    const MapResult r = roundTripMap(*environment);
    std::printf("%-24s median luminance error %.2f%%, irradiance %.2f%% (truth's own lights %.2f%%)\n",
                paths[i].filename().c_str(), 100.0 * r.medianLuminanceError,
                100.0 * r.irradianceError, 100.0 * r.truthLightsError);
    EXPECT_LT(r.medianLuminanceError, 0.03) << paths[i];
    EXPECT_LT(r.irradianceError, 0.02) << paths[i];
  }
}

}  // namespace
}  // namespace vem::calib
