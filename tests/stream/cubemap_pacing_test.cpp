// CubemapPacing (stream/cubemap_pacing.h): which cube maps a subscriber at a rate receives.
#include "stream/cubemap_pacing.h"

#include <cstdint>

#include <gtest/gtest.h>

namespace vem::stream {
namespace {

constexpr std::int64_t kMs = 1'000'000;

// The MQTT publisher gated at the full period: cube maps built every 200 ms for a 5 Hz subscriber
// that came a few ms early were dropped, and it received about 3 a second.
TEST(CubemapPacing, FiveHzScheduleWithTheWorkersJitterDeliversFiveASecond) {
  CubemapPacing pacing;
  int sent = 0;
  for (int i = 0; i < 50; ++i) {  // 10 s of a 5 Hz schedule, finished up to 15 ms off it
    const std::int64_t jitterNs = (i % 3 == 0 ? -15 : i % 3 == 1 ? 12 : -4) * kMs;
    sent += pacing.admit(std::int64_t(i) * 200 * kMs + jitterNs, 5.0);
  }
  EXPECT_EQ(sent, 50);
}

// A cube map built for a faster subscriber (30 Hz) goes to a 5 Hz one at 5 Hz, not more.
TEST(CubemapPacing, FasterBuildsAreThinnedToTheSubscribersRate) {
  CubemapPacing pacing;
  int sent = 0;
  for (int i = 0; i < 300; ++i) sent += pacing.admit(std::int64_t(i) * 100 * kMs / 3, 5.0);
  EXPECT_GE(sent, 49);
  EXPECT_LE(sent, 56);  // 10 % early at most: never 6 a second
}

TEST(CubemapPacing, FirstCubeMapGoesOutAtOnceWhateverTheClock) {
  CubemapPacing pacing;
  EXPECT_TRUE(pacing.admit(-5 * kMs, 0.5));
  EXPECT_FALSE(pacing.admit(1000 * kMs, 0.5));
  EXPECT_TRUE(pacing.admit(1795 * kMs, 0.5));
}

}  // namespace
}  // namespace vem::stream
