// Why lights jump (synth/jump_causes.h): a point whose CDF value sits at the level of a black gap
// between two bright blobs crosses the whole gap when one blob brightens a little. Side by side in
// the same rows, that is a jump along the row; one above the other, a jump across rows. Both are
// found, classified and measured as crossing a dark gap.
#include "synth/jump_causes.h"

#include <gtest/gtest.h>

#include "core/default_pattern.h"
#include "core/light_generator.h"

namespace vem::synth {
namespace {

constexpr int kWidth = 256, kHeight = 64;

struct Blob {
  int x0, x1, y0, y1;
};

EnvMap twoBlobs(Blob first, float firstLevel, Blob second) {
  EnvMap map = EnvMap::filled(MapLayout::Hemisphere, kWidth, kHeight, glm::vec3(0.0F));
  auto paint = [&](Blob b, float level) {
    for (int y = b.y0; y < b.y1; ++y)
      for (int x = b.x0; x < b.x1; ++x) map.set(x, y, glm::vec3(level));
  };
  paint(first, firstLevel);
  paint(second, 1.0F);
  return map;
}

std::vector<LargeJump> jumpsWhenTheFirstBlobBrightens(Blob first, Blob second, SamplerKind kind) {
  const EnvMap before = twoBlobs(first, 1.0F, second);
  const EnvMap after = twoBlobs(first, 1.1F, second);
  const auto pattern = defaultSamplingPattern(MapLayout::Hemisphere).first(256);
  const SamplingTables tablesBefore = buildSamplingTables(before);
  const SamplingTables tablesAfter = buildSamplingTables(after);
  std::vector<LargeJump> jumps;
  appendLargeJumps(tablesAfter, generateLights(tablesBefore, pattern, kind),
                   generateLights(tablesAfter, pattern, kind), glm::dmat3(1.0), jumps);
  return jumps;
}

TEST(LargeJumps, BlobsSideBySideMakeJumpsAlongTheRowOverTheBlackGapBetweenThem) {
  for (SamplerKind kind : {SamplerKind::Havran, SamplerKind::Standard}) {
    const auto jumps =
        jumpsWhenTheFirstBlobBrightens({40, 60, 20, 40}, {180, 200, 20, 40}, kind);
    ASSERT_FALSE(jumps.empty()) << samplerName(kind);
    const JumpCauses causes = summariseJumps(jumps);
    EXPECT_LT(causes.fractionAcrossRows, 0.2) << samplerName(kind);
    EXPECT_GT(causes.fractionGapBelowPercent, 0.8) << samplerName(kind);
  }
}

TEST(LargeJumps, BlobsOneAboveTheOtherMakeJumpsAcrossTheBlackRowsBetweenThem) {
  for (SamplerKind kind : {SamplerKind::Havran, SamplerKind::Standard}) {
    const auto jumps = jumpsWhenTheFirstBlobBrightens({0, kWidth, 4, 12}, {0, kWidth, 44, 52}, kind);
    ASSERT_FALSE(jumps.empty()) << samplerName(kind);
    const JumpCauses causes = summariseJumps(jumps);
    EXPECT_GT(causes.fractionAcrossRows, 0.8) << samplerName(kind);
    EXPECT_GT(causes.fractionGapBelowPercent, 0.8) << samplerName(kind);
  }
}

// The upper rows bright on the left, the lower rows on the right: where they meet, neighbouring
// rows have very different conditionals, and a small shift of the marginal moves a point far along
// its row. The standard sampler's points that jump crossed the row edge; Havran's sit between rows
// whose conditionals disagree.
TEST(LargeJumps, RowsWithDifferentConditionalsMakePointsJumpWhereTheRowsMeet) {
  for (SamplerKind kind : {SamplerKind::Havran, SamplerKind::Standard}) {
    const auto jumps = jumpsWhenTheFirstBlobBrightens({0, 64, 8, 32}, {128, 192, 32, 56}, kind);
    ASSERT_FALSE(jumps.empty()) << samplerName(kind);
    const JumpCauses causes = summariseJumps(jumps);
    EXPECT_LT(causes.fractionAcrossRows, 0.2) << samplerName(kind);
    if (kind == SamplerKind::Standard) {
      EXPECT_GT(causes.fractionRowIndexChanged, 0.8);
    } else {
      EXPECT_GT(causes.fractionRowsDisagree, 0.5);  // 0.73 measured
    }
  }
}

TEST(LargeJumps, AnUnchangedMapHasNone) {
  const EnvMap map = twoBlobs({40, 60, 20, 40}, 1.0F, {180, 200, 20, 40});
  const SamplingTables tables = buildSamplingTables(map);
  const auto pattern = defaultSamplingPattern(MapLayout::Hemisphere).first(256);
  const LightSet set = generateLights(tables, pattern, SamplerKind::Havran);
  std::vector<LargeJump> jumps;
  appendLargeJumps(tables, set, set, glm::dmat3(1.0), jumps);
  EXPECT_TRUE(jumps.empty());
  EXPECT_EQ(summariseJumps(jumps).count, 0U);
}

}  // namespace
}  // namespace vem::synth
