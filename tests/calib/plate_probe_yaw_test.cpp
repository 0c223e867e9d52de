// The light probe's yaw in the plate's world (calib/core/plate_probe_yaw.h): recovered from a
// simulated distant marker seen through the plate camera, in the sign plate_camera.h fixes
// (dir_plate = RotY(yaw) dir_probe with glm::rotate), and within the parallax bound for a near one.
#include "calib/core/plate_probe_yaw.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "calib/core/plate_camera.h"
#include "plate_truth.h"

namespace vem::calib {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

TEST(PlateProbeYaw, ASimulatedDistantMarkerGivesTheTruthsYaw) {
  for (const double yawDeg : {-170.0, -35.0, 0.0, 34.4, 179.0}) {
    PlateCamera truth = testing::plateTruth();
    truth.probeYawRad = yawDeg * kDeg;
    // A lamp far away, seen in the plate image's upper right; the probe sees it turned back.
    const glm::dvec3 markerPlate =
        worldDirectionFromPlate(truth.intrinsics, *truth.pose, {800, 90});
    const glm::dvec3 markerProbe =
        glm::transpose(plateWorldFromProbeWorld(truth.probeYawRad)) * markerPlate;
    // What the calibration measures: the marker's pixel, and the probe map's azimuth and elevation.
    const glm::dvec2 pixel = *plateFromWorldDirection(truth.intrinsics, *truth.pose, markerPlate);
    const glm::dvec3 probeDir =
        directionFromAzimuthElevation(azimuthRad(markerProbe), elevationRad(markerProbe));
    const auto yaw =
        probeYawFromMarker(worldDirectionFromPlate(truth.intrinsics, *truth.pose, pixel), probeDir);
    ASSERT_TRUE(yaw.has_value());
    EXPECT_NEAR(*yaw, truth.probeYawRad, 1e-9) << yawDeg;
  }
}

TEST(PlateProbeYaw, TheSignIsGlmRotatesAboutPlusY) {
  // RotY(+90 deg) turns +X into -Z: a marker the probe sees at phi = 0 the plate sees at -90 deg.
  const glm::dvec3 turned = plateWorldFromProbeWorld(std::numbers::pi / 2.0) * glm::dvec3(1, 0, 0);
  EXPECT_NEAR(turned.x, 0.0, 1e-15);
  EXPECT_NEAR(turned.z, -1.0, 1e-15);
  const auto yaw = probeYawFromMarker({0.0, 0.2, -1.0}, {1.0, 0.2, 0.0});
  ASSERT_TRUE(yaw.has_value());
  EXPECT_NEAR(*yaw, std::numbers::pi / 2.0, 1e-15);
}

TEST(PlateProbeYaw, AzimuthAndElevationFollowTheEnvMapConvention) {
  // phi = 0 faces +X, phi = 90 deg faces +Z, elevation 90 deg is +Y.
  const glm::dvec3 x = directionFromAzimuthElevation(0.0, 0.0);
  const glm::dvec3 z = directionFromAzimuthElevation(90.0 * kDeg, 0.0);
  const glm::dvec3 y = directionFromAzimuthElevation(0.0, 90.0 * kDeg);
  EXPECT_NEAR(x.x, 1.0, 1e-15);
  EXPECT_NEAR(z.z, 1.0, 1e-15);
  EXPECT_NEAR(y.y, 1.0, 1e-15);
  const glm::dvec3 d = directionFromAzimuthElevation(-120.0 * kDeg, 25.0 * kDeg);
  EXPECT_NEAR(azimuthRad(d), -120.0 * kDeg, 1e-12);
  EXPECT_NEAR(elevationRad(d), 25.0 * kDeg, 1e-12);
}

TEST(PlateProbeYaw, AMarkerStraightUpHasNoAzimuthAndIsRefused) {
  EXPECT_FALSE(probeYawFromMarker({0.0, 1.0, 0.001}, {1.0, 0.0, 0.0}).has_value());
  EXPECT_FALSE(probeYawFromMarker({1.0, 0.0, 0.0}, {0.0, -1.0, 0.0}).has_value());
}

TEST(PlateProbeYaw, ANearMarkersErrorStaysWithinTheParallaxBound) {
  // Probe at the origin, plate camera 2 m away, marker 30 m away: the yaw is off by at most
  // asin(b / d).
  const glm::dvec3 probeM(0.0), plateM(2.0, 0.5, 0.0), markerM(5.0, 3.0, 29.5);
  const double distanceM = glm::length(markerM - plateM);
  const double yawRad = 0.3;
  const glm::dvec3 markerPlate = markerM - plateM;  // the plate world is the truth's
  const glm::dvec3 markerProbe =
      glm::transpose(plateWorldFromProbeWorld(yawRad)) * (markerM - probeM);
  const double error = std::abs(*probeYawFromMarker(markerPlate, markerProbe) - yawRad);
  EXPECT_GT(error, 0.0);
  EXPECT_LE(error, markerParallaxRad(glm::length(plateM - probeM), distanceM) /
                       std::cos(elevationRad(markerPlate) + 0.1));
}

}  // namespace
}  // namespace vem::calib
