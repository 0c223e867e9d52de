// The error value of every recording file operation: a cause and one sentence that names the file
// and says what was expected (docs/vem-format.md lists them).
#pragma once

#include <string>

namespace vem::recording {

enum class RecordingError {
  NotFound,        // nothing at the path
  Unreadable,      // a folder, or the file cannot be opened or read
  NotVem,          // empty, or not starting with a VEM record
  UnknownVersion,  // a format version this build does not read
  BadHeader,       // the header record is damaged or describes no valid frames
  InvalidFrame,    // append(): a frame that does not fit the header, or a non-increasing seq
  WriteFailed,     // creating, writing, syncing or renaming failed (ENOSPC, EIO, ...)
  Closed,          // append() or close() after close()
};

[[nodiscard]] const char* recordingErrorName(RecordingError error);

struct RecordingFailure {
  RecordingError cause;
  std::string message;
};

}  // namespace vem::recording
