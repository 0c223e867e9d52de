#include "client/vemview/adaptive_light_count.h"

#include <gtest/gtest.h>

namespace vem::view {
namespace {

// A renderer whose frame time is proportional to the light count: 0.1 ms a light.
double frameMs(std::size_t lights) { return 0.1 * double(lights); }

TEST(AdaptiveLightCount, SettlesWhereTheFrameTimeMeetsTheTarget) {
  AdaptiveLightCount adaptive(20.0, 1024, 4, 4096);  // 1024 lights take 102 ms
  for (int i = 0; i < 40; ++i) {
    adaptive.update(frameMs(adaptive.count()));
  }
  EXPECT_NEAR(frameMs(adaptive.count()), 20.0, 20.0 * kBand + 0.1);
}

TEST(AdaptiveLightCount, DoesNotOscillateInsideTheBand) {
  AdaptiveLightCount adaptive(20.0, 200, 4, 4096);
  adaptive.update(20.5);
  EXPECT_EQ(adaptive.count(), 200U);
  adaptive.update(19.0);
  EXPECT_EQ(adaptive.count(), 200U);
}

TEST(AdaptiveLightCount, StaysWithinItsBoundsAndGrowsFromTheSmallest) {
  AdaptiveLightCount adaptive(20.0, 4, 4, 64);
  adaptive.update(1000.0);
  EXPECT_EQ(adaptive.count(), 4U);
  for (int i = 0; i < 50; ++i) {
    adaptive.update(1.0);
  }
  EXPECT_EQ(adaptive.count(), 64U);
}

TEST(AdaptiveLightCount, IgnoresAMeasurementThatIsNotATime) {
  AdaptiveLightCount adaptive(20.0, 100, 4, 4096);
  adaptive.update(0.0);
  adaptive.update(-1.0);
  adaptive.update(std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(adaptive.count(), 100U);
}

}  // namespace
}  // namespace vem::view
