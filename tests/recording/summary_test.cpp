// The info summary: frame count, time span, rate, and the gaps it must notice.
#include <cstdint>
#include <limits>

#include <gtest/gtest.h>

#include "recording/recording_reader.h"
#include "recording/recording_writer.h"
#include "recording_fixtures.h"

namespace vem::testing {
namespace {

using Summary = RecordingFiles;

TEST_F(Summary, CountsFramesRateAndSequenceAndTimestampGaps) {
  const recording::RecordingHeader header = smallHeader();
  const fs::path path = dir_ / "gaps.vem";
  {
    auto writer = recording::RecordingWriter::create(path, header);
    ASSERT_TRUE(writer);
    // seq 0..4, then 8 (3 missing) with a 4-period pause, then 9 after 1.4 periods (no gap).
    const std::vector<std::pair<std::uint64_t, std::int64_t>> stamps{
        {0, 0}, {1, 1}, {2, 2}, {3, 3}, {4, 4}};
    for (const auto& [seq, n] : stamps) {
      ASSERT_TRUE(writer->append(seq, n * kPeriodNs, smallFrame(header, int(seq))));
    }
    ASSERT_TRUE(writer->append(8, 8 * kPeriodNs, smallFrame(header, 8)));
    ASSERT_TRUE(writer->append(9, 8 * kPeriodNs + 14 * kPeriodNs / 10, smallFrame(header, 9)));
    ASSERT_TRUE(writer->close());
  }
  auto reader = recording::RecordingReader::open(path);
  ASSERT_TRUE(reader);
  auto s = reader->summarize();
  ASSERT_TRUE(s);
  EXPECT_EQ(s->frames, 7U);
  EXPECT_EQ(s->firstSeq, 0U);
  EXPECT_EQ(s->lastSeq, 9U);
  EXPECT_EQ(s->sequenceGaps, 1U);
  EXPECT_EQ(s->missingFrames, 3U);
  EXPECT_EQ(s->sequenceDisorders, 0U);
  EXPECT_EQ(s->timestampGaps, 1U);
  EXPECT_EQ(s->longestIntervalNs, 4 * kPeriodNs);
  const double spanNs = double(8 * kPeriodNs + 14 * kPeriodNs / 10);
  EXPECT_DOUBLE_EQ(s->meanRateHz, 6 * 1e9 / spanNs);
  EXPECT_EQ(s->index, recording::IndexState::Valid);
  EXPECT_EQ(s->indexEntries, 7U);
  EXPECT_EQ(s->header, header);
}

constexpr std::uint64_t kMaxSeq = std::numeric_limits<std::uint64_t>::max();

recording::RecordingSummary summaryOf(const fs::path& path) {
  auto reader = recording::RecordingReader::open(path);
  EXPECT_TRUE(reader) << reader.error().message;
  if (!reader) return {};
  auto s = reader->summarize();
  EXPECT_TRUE(s) << s.error().message;
  return s ? *s : recording::RecordingSummary{};
}

// seq going from 0 to 2^64 - 1 was a forward jump of 2^64 - 1: "18446744073709551614 frames
// missing". It is one step back through zero.
TEST_F(Summary, SeqGoingBackThroughZeroIsAWrapNotEighteenQuintillionMissingFrames) {
  const fs::path path = dir_ / "back.vem";
  writeRecordingByHand(path, {{0, 0}, {kMaxSeq, kPeriodNs}, {kMaxSeq - 1, 2 * kPeriodNs}});
  const recording::RecordingSummary s = summaryOf(path);
  EXPECT_EQ(s.frames, 3U);
  EXPECT_EQ(s.missingFrames, 0U);
  EXPECT_EQ(s.sequenceGaps, 0U);
  EXPECT_EQ(s.sequenceDisorders, 2U);
  ASSERT_TRUE(s.firstDisorder);
  EXPECT_EQ(s.firstDisorder->step, recording::SequenceStep::Wrap);
  EXPECT_EQ(s.firstDisorder->fromSeq, 0U);
  EXPECT_EQ(s.firstDisorder->toSeq, kMaxSeq);
  EXPECT_EQ(s.firstDisorder->frame, 2U);
}

TEST_F(Summary, SeqWrappingPastTheTopCountsNoMissingFramesAndIsDescribed) {
  const fs::path path = dir_ / "wrap.vem";
  writeRecordingByHand(path, {{kMaxSeq - 1, 0}, {kMaxSeq, 1}, {0, 2}, {1, 3}, {5, 4}});
  const recording::RecordingSummary s = summaryOf(path);
  EXPECT_EQ(s.missingFrames, 3U) << "only 1 -> 5 skips numbers";
  EXPECT_EQ(s.sequenceGaps, 1U);
  EXPECT_EQ(s.sequenceDisorders, 1U);
  ASSERT_TRUE(s.firstDisorder);
  EXPECT_EQ(s.firstDisorder->step, recording::SequenceStep::Wrap);
  EXPECT_EQ(s.firstDisorder->fromSeq, kMaxSeq);
  EXPECT_EQ(s.firstDisorder->toSeq, 0U);
  EXPECT_EQ(s.firstDisorder->frame, 3U);
}

// A frame out of order: one step back, described with the frame where it happens and its record.
TEST_F(Summary, SeqGoingBackNamesTheFrameWhereItGoesBack) {
  const fs::path path = dir_ / "swapped.vem";
  writeRecordingByHand(path, {{0, 0}, {1, 1}, {3, 2}, {2, 3}, {4, 4}, {4, 5}});
  auto reader = recording::RecordingReader::open(path);
  ASSERT_TRUE(reader);
  auto scan = reader->scan();
  ASSERT_TRUE(scan);
  const recording::RecordingSummary s = reader->summarize(*scan);
  EXPECT_EQ(s.sequenceGaps, 2U) << "1 -> 3 and 2 -> 4";
  EXPECT_EQ(s.missingFrames, 2U);
  EXPECT_EQ(s.sequenceDisorders, 2U) << "3 -> 2 and 4 -> 4";
  const recording::SequenceDisorder expected{recording::SequenceStep::Back, 3, 2, 4,
                                             scan->entries[3].offset};
  EXPECT_EQ(s.firstDisorder, expected);
}

TEST(SequenceStep, DirectionIsTheShorterWayRoundAndCrossingZeroIsAWrap) {
  using recording::classifySequenceStep;
  using recording::SequenceStep;
  constexpr std::uint64_t kHalf = std::uint64_t(1) << 63;
  EXPECT_EQ(classifySequenceStep(4, 5), SequenceStep::Next);
  EXPECT_EQ(classifySequenceStep(4, 7), SequenceStep::Gap);
  EXPECT_EQ(classifySequenceStep(0, kHalf), SequenceStep::Gap);
  EXPECT_EQ(classifySequenceStep(0, kHalf + 1), SequenceStep::Wrap);
  EXPECT_EQ(classifySequenceStep(0, kMaxSeq), SequenceStep::Wrap);
  EXPECT_EQ(classifySequenceStep(kMaxSeq, 0), SequenceStep::Wrap);
  EXPECT_EQ(classifySequenceStep(kMaxSeq - 2, 3), SequenceStep::Wrap);
  EXPECT_EQ(classifySequenceStep(7, 7), SequenceStep::Repeat);
  EXPECT_EQ(classifySequenceStep(7, 4), SequenceStep::Back);
  EXPECT_EQ(classifySequenceStep(kHalf, 0), SequenceStep::Back);
  EXPECT_EQ(classifySequenceStep(kHalf + 1, 0), SequenceStep::Wrap);
  EXPECT_EQ(classifySequenceStep(kMaxSeq - 1, kMaxSeq), SequenceStep::Next);
}

// Forward jumps just short of half the circle, again and again: the total saturates instead of
// wrapping round to a small number.
TEST_F(Summary, MissingFramesSaturateInsteadOfOverflowing) {
  constexpr std::uint64_t kJump = (std::uint64_t(1) << 63) - 1;
  const fs::path path = dir_ / "jumps.vem";
  writeRecordingByHand(path, {{0, 0}, {kJump, 1}, {0, 2}, {kJump, 3}, {0, 4}, {kJump, 5}});
  const recording::RecordingSummary s = summaryOf(path);
  EXPECT_EQ(s.sequenceGaps, 3U);
  EXPECT_EQ(s.missingFrames, kMaxSeq);
  EXPECT_EQ(s.sequenceDisorders, 2U);
}

}  // namespace
}  // namespace vem::testing
