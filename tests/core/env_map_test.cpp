#include "core/env_map.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

namespace vem {
namespace {

TEST(EnvMapGeometry, PixelSolidAnglesSumToTheCoveredSphere) {
  for (MapLayout layout : {MapLayout::Sphere, MapLayout::Hemisphere}) {
    double total = 0;
    for (int y = 0; y < 90; ++y) total += 360 * pixelSolidAngleSr(layout, 360, 90, y);
    EXPECT_NEAR(total, coveredSolidAngleSr(layout), 1e-12) << layoutName(layout);
  }
}

TEST(EnvMapGeometry, EquirectCentreColumnFacesPlusXAndRowZeroIsTheZenith) {
  const EnvMap map = EnvMap::filled(MapLayout::Sphere, 4, 2, glm::vec3(1));
  // Between columns 1 and 2 (the centre line) at the equator: +X.
  const glm::dvec3 centre = directionFromAngles(thetaFromRowCoord(map.layout, 2, 1.0),
                                                phiFromColumnCoord(map.layout, 4, 2.0));
  EXPECT_NEAR(centre.x, 1.0, 1e-12);
  EXPECT_GT(pixelCentreDirection(map, 0, 0).y, 0.7);
  EXPECT_LT(pixelCentreDirection(map, 0, 1).y, -0.7);
  EXPECT_NEAR(glm::length(pixelCentreDirection(map, 3, 1)), 1.0, 1e-12);
}

TEST(EnvMapGeometry, PolarMapLastRowTouchesTheHorizonAndPhiZeroFacesPlusX) {
  EXPECT_NEAR(thetaFromRowCoord(MapLayout::Hemisphere, 90, 90.0), std::numbers::pi / 2, 1e-15);
  const glm::dvec3 d = directionFromAngles(std::numbers::pi / 2,
                                           phiFromColumnCoord(MapLayout::Hemisphere, 360, 0.0));
  EXPECT_NEAR(d.x, 1.0, 1e-15);
  EXPECT_NEAR(d.y, 0.0, 1e-15);
}

}  // namespace
}  // namespace vem
