// recoverIndex: gives a truncated or damaged recording a trailing index again, for
// `vemtool recover` (docs/vem-format.md, "Recovery").
//
// It reads every record, then APPENDS a new Index record (listing every intact frame) and a new
// Footer at the end of the file, and syncs. Nothing already in the file is rewritten or removed:
// every complete frame stays where it was, damaged bytes stay (and are still reported as damage),
// and a crash during recovery leaves the file as readable as before. A file whose index is
// already valid is left untouched.
#pragma once

#include <cstdint>
#include <expected>
#include <filesystem>

#include "recording/recording_failure.h"
#include "recording/recording_summary.h"

namespace vem::recording {

struct RecoverReport {
  IndexState indexBefore = IndexState::Missing;
  std::uint64_t framesIndexed = 0;  // intact frames the new index lists
  std::uint64_t appendedBytes = 0;  // 0 when the index was already valid
  DamageStats damage;               // what the scan skipped
};

// Fails like RecordingReader::open, or with WriteFailed when the trailer cannot be appended (the
// file then stays as it was, or with an incomplete trailer that readers skip).
[[nodiscard]] std::expected<RecoverReport, RecordingFailure> recoverIndex(
    const std::filesystem::path& path);

}  // namespace vem::recording
