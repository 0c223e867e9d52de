// What `vemtool info` reports about a recording: its header, how many intact frames it holds,
// their time span and mean rate, gaps in sequence numbers and timestamps, damaged records, and
// whether the trailing index is there and agrees with the frames. Pure: computed from a cursor.
//
// Units: timestamps in ns on the writer's clock, rates in frames per second. A timestamp gap is
// an interval between consecutive intact frames longer than 1.5 frame periods, the period being
// 1 / nominalRateHz (or, when the header gives no rate, the mean interval).
//
// Sequence numbers (docs/vem-format.md, "Sequence numbers"): each step from one intact frame to
// the next in file order is classified by classifySequenceStep. Only a Gap counts missing frames
// (step - 1 of them, fewer than 2^63); a step that does not go forward (Repeat, Back, Wrap) is
// counted as out of order and the first one is described, never turned into missing frames.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "recording/record_scanner.h"
#include "recording/recording_cursor.h"
#include "recording/recording_header.h"
#include "recording/recording_index.h"

namespace vem::recording {

// Every intact frame's index entry, found by reading the whole file record by record.
struct FrameScan {
  std::vector<IndexEntry> entries;  // in file order
  std::uint64_t framesWithLights = 0;
  DamageStats damage;
  bool ioError = false;  // reading stopped early: the entries and counts cover the part before
};

// Rewinds `cursor` and reads every frame's metadata (CRCs checked, pixels not decompressed).
[[nodiscard]] FrameScan scanFrames(RecordingCursor& cursor);

enum class IndexState {
  Valid,    // intact and listing exactly the intact frames
  Stale,    // intact but listing other frames than the file holds (damage after it was written)
  Missing,  // no footer at the end of the file
  Damaged,  // a footer whose index is not intact
};

[[nodiscard]] const char* indexStateName(IndexState state);  // "valid", "stale", ...

// One step of the sequence number from an intact frame to the next, as unsigned 64-bit numbers
// on a circle of 2^64 (serial number arithmetic, RFC 1982): the shorter way round decides the
// direction, and a step whose direction on the circle differs from the plain comparison crosses
// zero.
enum class SequenceStep {
  Next,    // seq = previous + 1
  Gap,     // forward by 2 .. 2^63: step - 1 numbers skipped
  Repeat,  // seq = previous
  Back,    // backward by 1 .. 2^63 without crossing zero (a frame out of order, a restart)
  Wrap,    // across zero either way: 2^64 - 1 to 0 (a wrap) or 0 to 2^64 - 1 (back through zero)
};

[[nodiscard]] SequenceStep classifySequenceStep(std::uint64_t previous, std::uint64_t seq);
[[nodiscard]] const char* sequenceStepName(SequenceStep step);  // "next", "gap", "back", ...

// The first place where the sequence number does not go forward.
struct SequenceDisorder {
  SequenceStep step = SequenceStep::Back;  // Repeat, Back or Wrap
  std::uint64_t fromSeq = 0;               // the previous intact frame's
  std::uint64_t toSeq = 0;                 // this frame's
  std::uint64_t frame = 0;                 // this frame's position among the intact frames, from 1
  std::uint64_t offset = 0;                // of this frame's record

  friend bool operator==(const SequenceDisorder&, const SequenceDisorder&) = default;
};

struct RecordingSummary {
  RecordingHeader header;
  std::uint64_t fileBytes = 0;
  std::uint64_t frames = 0;
  std::uint64_t framesWithLights = 0;
  std::optional<std::uint64_t> firstSeq, lastSeq;
  std::optional<std::int64_t> firstTsNs, lastTsNs;
  double meanRateHz = 0.0;              // (frames - 1) / (lastTs - firstTs); 0 below two frames
  std::uint64_t sequenceGaps = 0;       // SequenceStep::Gap steps
  std::uint64_t missingFrames = 0;      // numbers they skip (saturating at 2^64 - 1)
  std::uint64_t sequenceDisorders = 0;  // Repeat, Back and Wrap steps: places out of order
  std::optional<SequenceDisorder> firstDisorder;
  std::uint64_t timestampGaps = 0;  // intervals longer than 1.5 frame periods
  std::int64_t longestIntervalNs = 0;
  DamageStats damage;
  IndexState index = IndexState::Missing;
  std::uint64_t indexEntries = 0;  // entries of the intact index (0 when none)
  bool ioError = false;
};

[[nodiscard]] RecordingSummary summarizeRecording(const RecordingCursor& cursor,
                                                  const FrameScan& scan);

}  // namespace vem::recording
