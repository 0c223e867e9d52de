// What `vemtool info` reports about a recording: its header, how many intact frames it holds,
// their time span and mean rate, gaps in sequence numbers and timestamps, damaged records, and
// whether the trailing index is there and agrees with the frames. Pure: computed from a cursor.
//
// Units: timestamps in ns on the writer's clock, rates in frames per second. A timestamp gap is
// an interval between consecutive intact frames longer than 1.5 frame periods, the period being
// 1 / nominalRateHz (or, when the header gives no rate, the mean interval).
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

struct RecordingSummary {
  RecordingHeader header;
  std::uint64_t fileBytes = 0;
  std::uint64_t frames = 0;
  std::uint64_t framesWithLights = 0;
  std::optional<std::uint64_t> firstSeq, lastSeq;
  std::optional<std::int64_t> firstTsNs, lastTsNs;
  double meanRateHz = 0.0;              // (frames - 1) / (lastTs - firstTs); 0 below two frames
  std::uint64_t sequenceGaps = 0;       // places where seq jumps forward by more than 1
  std::uint64_t missingFrames = 0;      // sequence numbers skipped by those jumps
  std::uint64_t sequenceDisorders = 0;  // places where seq does not increase
  std::uint64_t timestampGaps = 0;      // intervals longer than 1.5 frame periods
  std::int64_t longestIntervalNs = 0;
  DamageStats damage;
  IndexState index = IndexState::Missing;
  std::uint64_t indexEntries = 0;  // entries of the intact index (0 when none)
  bool ioError = false;
};

[[nodiscard]] RecordingSummary summarizeRecording(const RecordingCursor& cursor,
                                                  const FrameScan& scan);

}  // namespace vem::recording
