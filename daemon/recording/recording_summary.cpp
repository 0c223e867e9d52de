#include "recording/recording_summary.h"

#include <algorithm>
#include <ranges>

namespace vem::recording {

FrameScan scanFrames(RecordingCursor& cursor) {
  cursor.rewind();
  FrameScan scan;
  FrameSummary frame;
  std::uint64_t offset = 0;
  ReadStep step;
  while ((step = cursor.nextSummary(frame, offset)) == ReadStep::Frame) {
    scan.entries.push_back({frame.seq, frame.captureTsNs, offset});
    if (frame.hasLights) ++scan.framesWithLights;
  }
  scan.ioError = step == ReadStep::IoError;
  scan.damage = cursor.stats();
  cursor.rewind();
  return scan;
}

const char* indexStateName(IndexState state) {
  switch (state) {
    case IndexState::Valid: return "valid";
    case IndexState::Stale: return "stale";
    case IndexState::Missing: return "missing";
    case IndexState::Damaged: return "damaged";
  }
  return "?";
}

namespace {

void summarizeSequence(const std::vector<IndexEntry>& entries, RecordingSummary& s) {
  for (std::size_t i = 1; i < entries.size(); ++i) {
    const std::uint64_t previous = entries[i - 1].seq, seq = entries[i].seq;
    if (seq <= previous) {
      ++s.sequenceDisorders;
    } else if (seq - previous > 1) {
      ++s.sequenceGaps;
      s.missingFrames += seq - previous - 1;
    }
  }
}

void summarizeTimes(const std::vector<IndexEntry>& entries, RecordingSummary& s) {
  if (entries.empty()) return;
  s.firstTsNs = entries.front().captureTsNs;
  s.lastTsNs = entries.back().captureTsNs;
  const double spanNs = double(*s.lastTsNs) - double(*s.firstTsNs);
  if (entries.size() >= 2 && spanNs > 0.0) s.meanRateHz = double(entries.size() - 1) * 1e9 / spanNs;
  const double rateHz = s.header.nominalRateHz > 0.0 ? s.header.nominalRateHz : s.meanRateHz;
  if (rateHz <= 0.0) return;
  const double gapNs = 1.5 * 1e9 / rateHz;
  for (std::size_t i = 1; i < entries.size(); ++i) {
    // Differences in double: hostile timestamps must not overflow.
    const double intervalNs = double(entries[i].captureTsNs) - double(entries[i - 1].captureTsNs);
    if (intervalNs > gapNs) ++s.timestampGaps;
    if (intervalNs > double(s.longestIntervalNs)) {
      s.longestIntervalNs = intervalNs >= 9.2e18 ? INT64_MAX : std::int64_t(intervalNs);
    }
  }
}

}  // namespace

RecordingSummary summarizeRecording(const RecordingCursor& cursor, const FrameScan& scan) {
  RecordingSummary s;
  s.header = cursor.header();
  s.fileBytes = cursor.sourceBytes();
  s.frames = scan.entries.size();
  s.framesWithLights = scan.framesWithLights;
  if (!scan.entries.empty()) {
    s.firstSeq = scan.entries.front().seq;
    s.lastSeq = scan.entries.back().seq;
  }
  summarizeSequence(scan.entries, s);
  summarizeTimes(scan.entries, s);
  s.damage = scan.damage;
  s.ioError = scan.ioError;
  switch (cursor.indexStatus()) {
    case IndexStatus::Valid:
      s.indexEntries = cursor.index().size();
      s.index =
          std::ranges::equal(cursor.index(), scan.entries) ? IndexState::Valid : IndexState::Stale;
      break;
    case IndexStatus::Missing: s.index = IndexState::Missing; break;
    case IndexStatus::Damaged: s.index = IndexState::Damaged; break;
  }
  return s;
}

}  // namespace vem::recording
