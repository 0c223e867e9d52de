// The sensor-to-polar-map remap (calib/core/polar_remap.h): every map pixel reads the sensor point
// its direction projects to, invalid pixels are exactly those outside the lens, and radiance (not
// code) is interpolated.
#include "calib/core/polar_remap.h"

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <gtest/gtest.h>

#include "calib/core/camera_simulator.h"
#include "support/test_cameras.h"

namespace vem::calib {
namespace {

constexpr int kSensorWidth = 400;
constexpr int kSensorHeight = 320;

TEST(PolarRemap, EachMapPixelReadsTheSensorPointOfItsOwnDirection) {
  const KannalaBrandtLens lens = testing::wideLensTruth(kSensorWidth, kSensorHeight);
  const CameraOrientation orientation{30.0, 10.0, 45.0};
  const PolarRemap remap =
      buildPolarRemap(lens, orientation, kSensorWidth, kSensorHeight, MapLayout::Hemisphere, 128, 32);
  const glm::dmat3 worldFromCam = worldFromCamera(orientation);
  int checked = 0;
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 128; x += 7) {
      const std::size_t i = std::size_t(y) * 128 + std::size_t(x);
      const std::uint32_t tap = remap.topLeftTap[i];
      if (tap == PolarRemap::kInvalid) continue;
      const glm::dvec2 sensor(tap % kSensorWidth + remap.fractionU[i],
                              tap / kSensorWidth + remap.fractionV[i]);
      const glm::dvec3 dir = worldFromCam * *lens.cameraFromSensor(sensor);
      const glm::dvec3 expected = directionFromAngles(
          thetaFromRowCoord(MapLayout::Hemisphere, 32, y + 0.5),
          phiFromColumnCoord(MapLayout::Hemisphere, 128, x + 0.5));
      EXPECT_LT(std::acos(std::min(1.0, glm::dot(dir, expected))), 1e-5) << x << "," << y;
      ++checked;
    }
  }
  EXPECT_GT(checked, 500);
}

TEST(PolarRemap, InvalidPixelsAreExactlyThoseBeyondTheLensFieldOfView) {
  KannalaBrandtLens lens = equidistantLens(kSensorWidth, kSensorHeight, 160.0, 150.0);
  const PolarRemap remap =
      buildPolarRemap(lens, {}, kSensorWidth, kSensorHeight, MapLayout::Hemisphere, 90, 90);
  const auto mask = remap.validMask();
  for (int y = 0; y < 90; ++y) {
    const bool inside = y + 0.5 < 80.0;  // one row per degree; the lens reaches 80 degrees
    for (int x = 0; x < 90; ++x) {
      EXPECT_EQ(mask[std::size_t(y) * 90 + std::size_t(x)], inside ? 1 : 0) << x << "," << y;
    }
  }
  EXPECT_NEAR(remap.validFraction(), 80.0 / 90.0, 1e-12);
}

TEST(PolarRemap, AUniformSceneGivesAUniformMapAndZeroOutsideTheLens) {
  CameraCalibration camera = testing::cameraTruth(kSensorWidth, kSensorHeight, 1);
  camera.lens = equidistantLens(kSensorWidth, kSensorHeight, 160.0, 150.0);
  RawFrame frame = RawFrame::blank(kSensorWidth, kSensorHeight, {1, 12});
  std::ranges::fill(frame.codes, 2000);
  const CodeToLuminanceLut lut = buildCodeToLuminanceLut(*camera.photometric, {1, 12}, 1000.0, 1.0);
  const PolarRemap remap =
      buildPolarRemap(*camera.lens, {}, kSensorWidth, kSensorHeight, MapLayout::Hemisphere, 64, 16);
  EnvMap map;
  applyPolarRemap(remap, frame, lut, map);
  const float expected = lut.luminanceCdM2[2000];
  const auto mask = remap.validMask();
  for (std::size_t i = 0; i < mask.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_FLOAT_EQ(map.rgb[3 * i + std::size_t(c)], mask[i] ? expected : 0.0f) << i;
    }
  }
}

TEST(PolarRemap, BilinearInterpolationMixesRadianceNotLogCodes) {
  // Columns alternate between two codes eight decades... of a log sensor apart: the average of
  // the luminances is not the luminance of the average code.
  const PhotometricCalibration photometric = testing::logSensorTruth(1);
  RawFrame frame = RawFrame::blank(8, 8, {1, 12});
  for (int v = 0; v < 8; ++v) {
    for (int u = 0; u < 8; ++u) frame.codes[frame.index(u, v)] = u % 2 ? 3000 : 1000;
  }
  PolarRemap remap;
  remap.layout = MapLayout::Hemisphere;
  remap.mapWidth = 1;
  remap.mapHeight = 1;
  remap.sensorWidth = 8;
  remap.sensorHeight = 8;
  remap.topLeftTap = {2 * 8 + 2};
  remap.fractionU = {0.5f};
  remap.fractionV = {0.25f};
  const CodeToLuminanceLut lut = buildCodeToLuminanceLut(photometric, {1, 12}, 1000.0, 1.0);
  EnvMap map;
  applyPolarRemap(remap, frame, lut, map);
  EXPECT_FLOAT_EQ(map.rgb[0], 0.5f * (lut.luminanceCdM2[1000] + lut.luminanceCdM2[3000]));
}

TEST(PolarRemap, TiltedAndRotatedCameraStillFillsAWorldAlignedMap) {
  // A scene that varies with world direction, seen by a tilted, rotated camera: the remapped map
  // must show the scene where it is in the world, not where it is on the sensor.
  CameraCalibration camera = testing::cameraTruth(kSensorWidth, kSensorHeight, 3);
  camera.orientation = {40.0, 7.0, 120.0};
  const RadianceFunction scene = [](const glm::dvec3& d) {
    return glm::dvec3(100.0 * (1.5 + d.x), 100.0 * (1.5 + d.y), 100.0 * (1.5 + d.z));
  };
  const RawFrame frame = simulateFrame(scene, camera, {});
  const PolarRemap remap = buildPolarRemap(*camera.lens, camera.orientation, kSensorWidth,
                                           kSensorHeight, MapLayout::Hemisphere, 64, 16);
  EnvMap map;
  applyPolarRemap(remap,
                  frame, buildCodeToLuminanceLut(*camera.photometric, {3, 12}, 1000.0, 1.0), map);
  const auto mask = remap.validMask();
  int compared = 0;
  for (int y = 0; y < 14; ++y) {  // away from the tilted lens's edge
    for (int x = 0; x < 64; ++x) {
      if (!mask[std::size_t(y) * 64 + std::size_t(x)]) continue;
      const glm::dvec3 expected = scene(pixelCentreDirection(map, x, y));
      const glm::vec3 got = map.at(x, y);
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(double(got[c]) / expected[c], 1.0, 0.02) << x << "," << y << " channel " << c;
      }
      ++compared;
    }
  }
  EXPECT_GT(compared, 800);
}

}  // namespace
}  // namespace vem::calib
