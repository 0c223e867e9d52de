// Damage: a recording cut anywhere, or with bytes flipped, still yields every intact frame, and
// the reader says what it skipped.
#include <algorithm>
#include <vector>

#include <gtest/gtest.h>

#include "recording/byte_source.h"
#include "recording/recording_cursor.h"
#include "recording/recording_reader.h"
#include "recording_fixtures.h"

namespace vem::testing {
namespace {

using Damage = RecordingFiles;

TEST_F(Damage, FileCutAtEvery997thByteYieldsExactlyTheFramesBeforeTheCut) {
  const fs::path full = dir_ / "full.vem";
  writeSmallRecording(full, 20);
  const std::vector<char> bytes = readBytes(full);
  auto intact = recording::RecordingReader::open(full);
  ASSERT_TRUE(intact);
  const auto index = intact->index();
  ASSERT_EQ(index.size(), 20U);
  // Frame i is complete when the cut lies at or after the start of the record that follows it.
  const std::uint64_t indexOffset = recording::loadLe64(
      reinterpret_cast<const std::byte*>(bytes.data()) + bytes.size() -
      recording::kFooterPayloadBytes);
  std::vector<std::uint64_t> ends;
  for (std::size_t i = 1; i < index.size(); ++i) ends.push_back(index[i].offset);
  ends.push_back(indexOffset);

  int cuts = 0;
  for (std::size_t cut = 0; cut < bytes.size(); cut += 997, ++cuts) {
    SCOPED_TRACE(cut);
    const fs::path path = dir_ / "cut.vem";
    writeBytes(path, bytes.data(), cut);
    auto reader = recording::RecordingReader::open(path);
    if (cut < std::size_t(index[0].offset)) {  // the header itself is cut
      ASSERT_FALSE(reader);
      EXPECT_TRUE(reader.error().cause == recording::RecordingError::NotVem ||
                  reader.error().cause == recording::RecordingError::BadHeader)
          << reader.error().message;
      continue;
    }
    ASSERT_TRUE(reader) << reader.error().message;
    EXPECT_FALSE(reader->hasIndex());
    const ReadBack back = readAll(*reader);
    const auto complete = std::size_t(std::ranges::count_if(ends, [&](std::uint64_t end) {
      return end <= cut;
    }));
    ASSERT_EQ(back.frames.size(), complete);
    for (std::size_t i = 0; i < complete; ++i) {
      EXPECT_EQ(back.frames[i].seq, i);
      EXPECT_EQ(back.frames[i].frame.codes, smallFrame(smallHeader(), int(i)).codes);
    }
    EXPECT_EQ(back.damage.damagedRecords, 0U) << "a cut is a truncated tail, not damage";
  }
  EXPECT_GE(cuts, 20);
}

TEST_F(Damage, CutAtEveryByteOfTheLastTwoRecordsNeverCrashesAndKeepsEarlierFrames) {
  const fs::path full = dir_ / "full.vem";
  writeSmallRecording(full, 5);
  const std::vector<char> bytes = readBytes(full);
  auto intact = recording::RecordingReader::open(full);
  ASSERT_TRUE(intact);
  const std::uint64_t from = intact->index()[3].offset;
  for (std::size_t cut = std::size_t(from); cut <= bytes.size(); ++cut) {
    recording::MemoryByteSource source(std::as_bytes(std::span(bytes.data(), cut)));
    recording::RecordingCursor cursor(source);
    ASSERT_EQ(cursor.open(), recording::OpenStatus::Ok);
    recording::RecordedFrame frame;
    int frames = 0;
    while (cursor.next(frame) == recording::ReadStep::Frame) ++frames;
    ASSERT_GE(frames, 3) << cut;
    ASSERT_EQ(cursor.stats().damagedRecords, 0U) << cut;
    ASSERT_EQ(cursor.indexStatus() == recording::IndexStatus::Valid, cut == bytes.size()) << cut;
  }
}

struct Flip {
  const char* name;
  std::size_t offsetInRecord;  // from the record's first byte; SIZE_MAX: its last byte
  friend void PrintTo(const Flip& flip, std::ostream* os) { *os << flip.name; }
};

class FlippedByte : public RecordingFiles, public ::testing::WithParamInterface<Flip> {};

TEST_P(FlippedByte, DamagedFrameIsSkippedAndCountedAndAllOthersAreRead) {
  const fs::path path = dir_ / "flip.vem";
  writeSmallRecording(path, 10);
  std::vector<char> bytes = readBytes(path);
  std::uint64_t start = 0, end = 0;
  {
    auto reader = recording::RecordingReader::open(path);
    ASSERT_TRUE(reader && reader->hasIndex());
    start = reader->index()[4].offset;
    end = reader->index()[5].offset;
  }
  const std::size_t at = GetParam().offsetInRecord == SIZE_MAX
                             ? std::size_t(end - 1)
                             : std::size_t(start + GetParam().offsetInRecord);
  bytes[at] = char(bytes[at] ^ 0x5A);
  writeBytes(path, bytes.data(), bytes.size());

  auto reader = recording::RecordingReader::open(path);
  ASSERT_TRUE(reader) << reader.error().message;
  const ReadBack back = readAll(*reader);
  ASSERT_EQ(back.frames.size(), 9U);
  for (std::size_t i = 0; i < 9; ++i) {
    const int want = i < 4 ? int(i) : int(i) + 1;
    EXPECT_EQ(back.frames[i].seq, std::uint64_t(want));
    EXPECT_EQ(back.frames[i].frame.codes, smallFrame(smallHeader(), want).codes);
  }
  EXPECT_EQ(back.damage.damagedRecords, 1U);
  EXPECT_EQ(back.damage.damagedBytes, end - start);
  EXPECT_EQ(back.damage.truncatedTailBytes, 0U);
}

INSTANTIATE_TEST_SUITE_P(
    InEveryField, FlippedByte,
    ::testing::Values(Flip{"Magic", 0}, Flip{"Type", 4}, Flip{"Reserved", 6}, Flip{"Length", 9},
                      Flip{"Crc", 13}, Flip{"MetaLength", 16}, Flip{"Meta", 22},
                      Flip{"Pixels", 900}, Flip{"LastByte", SIZE_MAX}),
    [](const ::testing::TestParamInfo<Flip>& p) { return std::string(p.param.name); });

TEST_F(Damage, ZeroedRunAcrossTwoRecordsCountsOneRegionAndKeepsTheRest) {
  const fs::path path = dir_ / "zeroed.vem";
  writeSmallRecording(path, 8);
  std::vector<char> bytes = readBytes(path);
  std::uint64_t from = 0, to = 0;
  {
    auto reader = recording::RecordingReader::open(path);
    ASSERT_TRUE(reader);
    from = reader->index()[2].offset + 100;  // inside frame 2 ...
    to = reader->index()[3].offset + 50;     // ... to inside frame 3
  }
  std::fill(bytes.begin() + std::ptrdiff_t(from), bytes.begin() + std::ptrdiff_t(to), char(0));
  writeBytes(path, bytes.data(), bytes.size());
  auto reader = recording::RecordingReader::open(path);
  ASSERT_TRUE(reader);
  const ReadBack back = readAll(*reader);
  ASSERT_EQ(back.frames.size(), 6U);
  EXPECT_EQ(back.frames[2].seq, 4U);
  EXPECT_EQ(back.damage.damagedRecords, 1U);
}

}  // namespace
}  // namespace vem::testing
