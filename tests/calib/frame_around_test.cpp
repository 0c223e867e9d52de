// frameAround (calib/core/frame_around.h): each test names the bug it stops.
#include "calib/core/frame_around.h"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <gtest/gtest.h>

namespace vem::calib {
namespace {

void expectRightHandedFrameAround(const glm::dvec3& axis) {
  const glm::dmat3 frame = frameAround(axis);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(glm::length(frame[i]), 1.0, 1e-12) << "column " << i;
    for (int j = i + 1; j < 3; ++j) EXPECT_NEAR(glm::dot(frame[i], frame[j]), 0.0, 1e-12);
  }
  EXPECT_NEAR(glm::determinant(frame), 1.0, 1e-12);  // a rotation, not a reflection
  EXPECT_NEAR(glm::length(frame[2] - axis), 0.0, 1e-15);
}

TEST(FrameAround, ThirdColumnIsTheAxisAndTheFrameIsARotation) {
  expectRightHandedFrameAround({0.0, 0.0, 1.0});
  expectRightHandedFrameAround({0.0, 0.0, -1.0});
  expectRightHandedFrameAround(glm::normalize(glm::dvec3(0.3, -0.5, 0.8)));
}

TEST(FrameAround, AxisAlongXDoesNotCollapseTheFrame) {
  // The helper axis switches from x to y near x: a cross product with a parallel helper would
  // give a zero vector and NaNs.
  expectRightHandedFrameAround({1.0, 0.0, 0.0});
  expectRightHandedFrameAround({-1.0, 0.0, 0.0});
  expectRightHandedFrameAround(glm::normalize(glm::dvec3(0.95, 0.05, 0.0)));
}

}  // namespace
}  // namespace vem::calib
