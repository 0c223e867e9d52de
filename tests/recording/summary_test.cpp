// The info summary: frame count, time span, rate, and the gaps it must notice.
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

}  // namespace
}  // namespace vem::testing
