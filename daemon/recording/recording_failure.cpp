#include "recording/recording_failure.h"

namespace vem::recording {

const char* recordingErrorName(RecordingError error) {
  switch (error) {
    case RecordingError::NotFound:
      return "NotFound";
    case RecordingError::Unreadable:
      return "Unreadable";
    case RecordingError::NotVem:
      return "NotVem";
    case RecordingError::UnknownVersion:
      return "UnknownVersion";
    case RecordingError::BadHeader:
      return "BadHeader";
    case RecordingError::InvalidFrame:
      return "InvalidFrame";
    case RecordingError::WriteFailed:
      return "WriteFailed";
    case RecordingError::Closed:
      return "Closed";
  }
  return "?";
}

}  // namespace vem::recording
