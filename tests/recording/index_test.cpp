// The trailing index: used for seeking when intact, never needed to read the frames, and rebuilt
// by recoverIndex without losing a complete frame.
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "recording/byte_source.h"
#include "recording/recording_cursor.h"
#include "recording/recording_reader.h"
#include "recording/recover_index.h"
#include "recording_fixtures.h"

namespace vem::testing {
namespace {

using Index = RecordingFiles;

// Counts the bytes read through it.
class CountingSource final : public recording::ByteSource {
 public:
  explicit CountingSource(std::span<const std::byte> bytes) : inner_(bytes) {}
  [[nodiscard]] std::uint64_t size() const override { return inner_.size(); }
  [[nodiscard]] bool readAt(std::uint64_t offset, std::span<std::byte> out) override {
    bytesRead += out.size();
    return inner_.readAt(offset, out);
  }
  std::uint64_t bytesRead = 0;

 private:
  recording::MemoryByteSource inner_;
};

std::span<const std::byte> asBytes(const std::vector<char>& bytes) {
  return std::as_bytes(std::span(bytes));
}

TEST_F(Index, ClosedRecordingHasAnIndexListingEveryFrameRecord) {
  const fs::path path = dir_ / "a.vem";
  writeSmallRecording(path, 12);
  auto reader = recording::RecordingReader::open(path);
  ASSERT_TRUE(reader);
  ASSERT_TRUE(reader->hasIndex());
  ASSERT_EQ(reader->index().size(), 12U);
  auto scan = reader->scan();
  ASSERT_TRUE(scan);
  EXPECT_TRUE(std::ranges::equal(reader->index(), scan->entries));
  EXPECT_EQ(reader->index()[5].seq, 5U);
  EXPECT_EQ(reader->index()[5].captureTsNs, 5 * kPeriodNs);
}

TEST_F(Index, SeekUsesTheIndexInsteadOfReadingTheFile) {
  const fs::path path = dir_ / "a.vem";
  writeSmallRecording(path, 20);
  const std::vector<char> bytes = readBytes(path);
  CountingSource source(asBytes(bytes));
  recording::RecordingCursor cursor(source);
  ASSERT_EQ(cursor.open(), recording::OpenStatus::Ok);
  ASSERT_EQ(cursor.indexStatus(), recording::IndexStatus::Valid);
  const std::uint64_t afterOpen = source.bytesRead;
  ASSERT_EQ(cursor.seek(17), recording::SeekStep::Found);
  EXPECT_EQ(source.bytesRead, afterOpen) << "seeking with an index reads nothing";
  recording::RecordedFrame frame;
  ASSERT_EQ(cursor.next(frame), recording::ReadStep::Frame);
  EXPECT_EQ(frame.seq, 17U);
  EXPECT_LT(source.bytesRead - afterOpen, bytes.size() / 10) << "one frame read, not the file";
}

TEST_F(Index, WithoutTheIndexEveryFrameIsStillReadAndSeekScansOnce) {
  const fs::path path = dir_ / "a.vem";
  writeSmallRecording(path, 20, smallHeader(), /*close=*/false);  // destructor closes...
  std::vector<char> bytes = readBytes(path);
  {
    auto reader = recording::RecordingReader::open(path);
    ASSERT_TRUE(reader && reader->hasIndex());
    bytes.resize(std::size_t(reader->index().back().offset));  // ... so cut the last frame off
  }
  const fs::path cut = dir_ / "cut.vem";
  writeBytes(cut, bytes.data(), bytes.size());
  auto reader = recording::RecordingReader::open(cut);
  ASSERT_TRUE(reader);
  EXPECT_EQ(reader->indexStatus(), recording::IndexStatus::Missing);
  EXPECT_TRUE(reader->index().empty());
  EXPECT_EQ(readAll(*reader).frames.size(), 19U);
  auto found = reader->seek(11);
  ASSERT_TRUE(found && *found);
  auto frame = reader->next();
  ASSERT_TRUE(frame && *frame);
  EXPECT_EQ((*frame)->seq, 11U);
  auto past = reader->seek(19);
  ASSERT_TRUE(past);
  EXPECT_FALSE(*past);
}

TEST_F(Index, DamagedIndexIsIgnoredAndEveryFrameIsRead) {
  const fs::path path = dir_ / "a.vem";
  writeSmallRecording(path, 10);
  std::vector<char> bytes = readBytes(path);
  const std::size_t inIndex = bytes.size() - recording::kFooterRecordBytes - 5;
  bytes[inIndex] = char(bytes[inIndex] ^ 1);
  writeBytes(path, bytes.data(), bytes.size());
  auto reader = recording::RecordingReader::open(path);
  ASSERT_TRUE(reader);
  EXPECT_EQ(reader->indexStatus(), recording::IndexStatus::Damaged);
  const ReadBack back = readAll(*reader);
  EXPECT_EQ(back.frames.size(), 10U);
  EXPECT_EQ(back.damage.damagedRecords, 1U) << "the index record itself";
}

TEST_F(Index, IndexPointingOutsideTheFramesIsRefused) {
  // A hand-made trailer whose entry points into the footer: not trusted.
  const fs::path path = dir_ / "a.vem";
  writeSmallRecording(path, 2, smallHeader(), false);
  std::vector<char> bytes = readBytes(path);
  std::uint64_t indexOffset = 0;
  {
    auto reader = recording::RecordingReader::open(path);
    ASSERT_TRUE(reader && reader->hasIndex());
    indexOffset = reader->index().back().offset + 1;  // drop the trailer and the last frame's end
  }
  bytes.resize(std::size_t(indexOffset));
  const std::vector<recording::IndexEntry> bogus{{0, 0, indexOffset + 5}};
  const auto trailer = recording::encodeTrailer(bogus, indexOffset);
  const auto* t = reinterpret_cast<const char*>(trailer.data());
  bytes.insert(bytes.end(), t, t + trailer.size());
  writeBytes(path, bytes.data(), bytes.size());
  auto reader = recording::RecordingReader::open(path);
  ASSERT_TRUE(reader);
  EXPECT_EQ(reader->indexStatus(), recording::IndexStatus::Damaged);
  EXPECT_EQ(readAll(*reader).frames.size(), 1U);
}

TEST_F(Index, RecoverRestoresTheIndexOfATruncatedFileWithoutLosingAFrame) {
  const fs::path path = dir_ / "a.vem";
  writeSmallRecording(path, 15);
  std::vector<char> bytes = readBytes(path);
  std::vector<recording::IndexEntry> original;
  {
    auto reader = recording::RecordingReader::open(path);
    ASSERT_TRUE(reader);
    original.assign(reader->index().begin(), reader->index().end());
  }
  // Cut in the middle of frame 12: frames 0..11 are complete.
  bytes.resize(std::size_t(original[12].offset + 40));
  writeBytes(path, bytes.data(), bytes.size());

  auto report = recording::recoverIndex(path);
  ASSERT_TRUE(report) << report.error().message;
  EXPECT_EQ(report->indexBefore, recording::IndexState::Missing);
  EXPECT_EQ(report->framesIndexed, 12U);
  EXPECT_GT(report->appendedBytes, 0U);
  EXPECT_EQ(report->damage.truncatedTailBytes, 40U);

  const std::vector<char> after = readBytes(path);
  ASSERT_GE(after.size(), bytes.size());
  EXPECT_TRUE(std::equal(bytes.begin(), bytes.end(), after.begin())) << "appended only";
  auto reader = recording::RecordingReader::open(path);
  ASSERT_TRUE(reader);
  ASSERT_TRUE(reader->hasIndex());
  EXPECT_TRUE(std::ranges::equal(reader->index(), std::span(original).first(12)));
  EXPECT_EQ(readAll(*reader).frames.size(), 12U);
  auto summary = reader->summarize();
  ASSERT_TRUE(summary);
  EXPECT_EQ(summary->index, recording::IndexState::Valid);

  auto again = recording::recoverIndex(path);
  ASSERT_TRUE(again);
  EXPECT_EQ(again->appendedBytes, 0U) << "a valid index is left alone";
  EXPECT_EQ(readBytes(path), after);
}

TEST_F(Index, RecoverOfADamagedFileIndexesEveryIntactFrame) {
  const fs::path path = dir_ / "a.vem";
  writeSmallRecording(path, 10);
  std::vector<char> bytes = readBytes(path);
  std::uint64_t frame6 = 0;
  {
    auto reader = recording::RecordingReader::open(path);
    ASSERT_TRUE(reader);
    frame6 = reader->index()[6].offset;
  }
  bytes[std::size_t(frame6 + 200)] ^= 0x10;
  writeBytes(path, bytes.data(), bytes.size());
  {
    auto reader = recording::RecordingReader::open(path);
    ASSERT_TRUE(reader);
    auto summary = reader->summarize();
    ASSERT_TRUE(summary);
    EXPECT_EQ(summary->index, recording::IndexState::Stale);
  }
  auto report = recording::recoverIndex(path);
  ASSERT_TRUE(report) << report.error().message;
  EXPECT_EQ(report->framesIndexed, 9U);
  EXPECT_EQ(report->damage.damagedRecords, 1U);
  auto reader = recording::RecordingReader::open(path);
  ASSERT_TRUE(reader && reader->hasIndex());
  EXPECT_EQ(reader->index().size(), 9U);
  auto seek = reader->seek(6);
  ASSERT_TRUE(seek && *seek);
  auto frame = reader->next();
  ASSERT_TRUE(frame && *frame);
  EXPECT_EQ((*frame)->seq, 7U) << "the first intact frame at or after 6";
}

// Sequence numbers a camera or writer should never produce but a file may hold: a frame out of
// order, a repeat, a counter wrapping past 2^64 - 1, one going back from 0 to 2^64 - 1.
const std::vector<std::vector<HandFrame>>& awkwardSequences() {
  constexpr std::uint64_t kMax = std::numeric_limits<std::uint64_t>::max();
  static const std::vector<std::vector<HandFrame>> sequences{
      {{0, 0}, {1, 1}, {2, 2}, {4, 3}, {3, 4}, {5, 5}, {6, 6}},
      {{0, 0}, {1, 1}, {1, 2}, {2, 3}},
      {{kMax - 1, 0}, {kMax, 1}, {0, 2}, {1, 3}},
      {{1, 0}, {0, 1}, {kMax, 2}, {kMax - 1, 3}},
  };
  return sequences;
}

// recover used to index only the frames whose seq increased: info then called that index stale
// and every run appended another one. Now the file settles after one run.
TEST_F(Index, RecoverRunThreeTimesLeavesTheSameBytes) {
  for (const std::vector<HandFrame>& frames : awkwardSequences()) {
    SCOPED_TRACE(::testing::Message() << "seq " << frames[1].seq << " after " << frames[0].seq);
    const fs::path path = dir_ / "awkward.vem";
    writeRecordingByHand(path, frames);
    std::vector<std::vector<char>> after;
    for (int run = 0; run < 3; ++run) {
      auto report = recording::recoverIndex(path);
      ASSERT_TRUE(report) << report.error().message;
      EXPECT_EQ(report->framesIndexed, frames.size()) << "run " << run + 1;
      EXPECT_EQ(report->appendedBytes > 0, run == 0) << "run " << run + 1;
      after.push_back(readBytes(path));
    }
    EXPECT_EQ(after[1], after[0]);
    EXPECT_EQ(after[2], after[0]);
    fs::remove(path);
  }
}

TEST_F(Index, RecoverIndexesTheFrameOutOfOrderThatInfoCounts) {
  for (const std::vector<HandFrame>& frames : awkwardSequences()) {
    SCOPED_TRACE(::testing::Message() << "seq " << frames[1].seq << " after " << frames[0].seq);
    const fs::path path = dir_ / "awkward.vem";
    writeRecordingByHand(path, frames);
    ASSERT_TRUE(recording::recoverIndex(path));
    auto reader = recording::RecordingReader::open(path);
    ASSERT_TRUE(reader && reader->hasIndex());
    auto summary = reader->summarize();
    ASSERT_TRUE(summary);
    EXPECT_EQ(summary->frames, frames.size());
    EXPECT_EQ(summary->indexEntries, frames.size());
    EXPECT_EQ(summary->index, recording::IndexState::Valid);
    ASSERT_EQ(reader->index().size(), frames.size());
    for (std::size_t i = 0; i < frames.size(); ++i)
      EXPECT_EQ(reader->index()[i].seq, frames[i].seq);
    fs::remove(path);
  }
}

// Seeking used to search only the increasing sequence numbers, so it jumped past a frame that came
// out of order to the next higher one.
TEST_F(Index, SeekFindsAFrameThatCameOutOfOrder) {
  const std::vector<HandFrame> frames{{0, 0}, {1, 1}, {2, 2}, {4, 3}, {3, 4}, {5, 5}, {6, 6}};
  const fs::path path = dir_ / "swapped.vem";
  writeRecordingByHand(path, frames);
  for (const bool indexed : {false, true}) {
    SCOPED_TRACE(indexed ? "with the index recover wrote" : "without an index");
    if (indexed) {
      ASSERT_TRUE(recording::recoverIndex(path));
    }
    auto reader = recording::RecordingReader::open(path);
    ASSERT_TRUE(reader);
    ASSERT_EQ(reader->hasIndex(), indexed);
    auto found = reader->seek(3);
    ASSERT_TRUE(found && *found);
    auto frame = reader->next();
    ASSERT_TRUE(frame && *frame);
    EXPECT_EQ((*frame)->seq, 3U);
    auto after = reader->next();
    ASSERT_TRUE(after && *after);
    EXPECT_EQ((*after)->seq, 5U) << "then on in file order";
    auto past = reader->seek(7);
    ASSERT_TRUE(past);
    EXPECT_FALSE(*past);
  }
}

TEST(SeekEntry, LeastSequenceNumberAtOrAboveTheTargetFirstInFileOrder) {
  const std::vector<recording::IndexEntry> entries{
      {10, 0, 100}, {4, 0, 200}, {7, 0, 300}, {4, 0, 400}, {12, 0, 500}};
  EXPECT_EQ(recording::seekEntry(entries, 0), 1U);
  EXPECT_EQ(recording::seekEntry(entries, 4), 1U);
  EXPECT_EQ(recording::seekEntry(entries, 5), 2U);
  EXPECT_EQ(recording::seekEntry(entries, 8), 0U);
  EXPECT_EQ(recording::seekEntry(entries, 12), 4U);
  EXPECT_EQ(recording::seekEntry(entries, 13), std::nullopt);
  EXPECT_EQ(recording::seekEntry({}, 0), std::nullopt);
}

}  // namespace
}  // namespace vem::testing
