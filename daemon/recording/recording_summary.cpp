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

SequenceStep classifySequenceStep(std::uint64_t previous, std::uint64_t seq) {
  if (seq == previous) return SequenceStep::Repeat;
  constexpr std::uint64_t kHalf = std::uint64_t(1) << 63;
  const std::uint64_t ahead = seq - previous;  // modulo 2^64: the way forward round the circle
  const bool forward = seq > previous;
  const bool forwardOnCircle = ahead < kHalf || (ahead == kHalf && forward);
  if (forward != forwardOnCircle) return SequenceStep::Wrap;
  if (!forward) return SequenceStep::Back;
  return ahead == 1 ? SequenceStep::Next : SequenceStep::Gap;
}

const char* sequenceStepName(SequenceStep step) {
  switch (step) {
    case SequenceStep::Next: return "next";
    case SequenceStep::Gap: return "gap";
    case SequenceStep::Repeat: return "repeat";
    case SequenceStep::Back: return "back";
    case SequenceStep::Wrap: return "wrap";
  }
  return "?";
}

namespace {

void summarizeSequence(const std::vector<IndexEntry>& entries, RecordingSummary& s) {
  for (std::size_t i = 1; i < entries.size(); ++i) {
    const std::uint64_t previous = entries[i - 1].seq, seq = entries[i].seq;
    switch (const SequenceStep step = classifySequenceStep(previous, seq)) {
      case SequenceStep::Next: break;
      case SequenceStep::Gap: {
        ++s.sequenceGaps;
        const std::uint64_t skipped = seq - previous - 1;  // seq > previous + 1 here
        s.missingFrames =
            skipped > UINT64_MAX - s.missingFrames ? UINT64_MAX : s.missingFrames + skipped;
        break;
      }
      case SequenceStep::Repeat:
      case SequenceStep::Back:
      case SequenceStep::Wrap:
        if (s.sequenceDisorders++ == 0) {
          s.firstDisorder = SequenceDisorder{step, previous, seq, i + 1, entries[i].offset};
        }
        break;
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
