#include "client/stream_events.h"

namespace vem::client {

std::string_view sourceStateName(SourceState state) {
  switch (state) {
    case SourceState::Unspecified: return "unspecified";
    case SourceState::Ok: return "ok";
    case SourceState::NoSignal: return "no signal";
    case SourceState::NoDevice: return "no device";
    case SourceState::Timeout: return "timeout";
    case SourceState::Ended: return "ended";
    case SourceState::Unknown: break;
  }
  return "unknown";
}

}  // namespace vem::client
