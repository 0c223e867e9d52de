// The client's decoder and validator of the daemon's messages: the bytes of one binary WebSocket
// message (a vem.stream.ServerMessage, proto/vem_stream.proto) to a checked C++ value
// (stream_events.h), or one sentence saying why the message is refused.
//
// Refused: more than kMaxServerMessageBytes; not a ServerMessage; a protocol major other than
// kProtocolMajor ("protocol major version N is not supported (this client speaks 1)"); non-finite
// numbers; light or cluster directions that are not unit vectors (|length - 1| > 1e-3); negative
// rgb; array lengths that disagree (dirs and rgb must hold 3 floats per id, member_of one entry per
// light naming an existing cluster); more than kMaxLights lights or clusters; cube maps whose face
// size, level count or raw_bytes break stream_protocol.h's limits or disagree with each other
// (checked before anything is allocated from them), whose texels do not decompress to exactly
// raw_bytes, or that hold non-finite or negative texels; a preview whose size disagrees with its
// bytes. A body this client does not know (a newer minor) decodes to Ignored.
//
// Pure: no I/O, no threads, no logging, thread-safe; no <expected> (the fuzz target compiles it
// with clang).
#pragma once

#include <string>
#include <string_view>
#include <variant>

#include "client/stream_events.h"

namespace vem::client {

using ServerEvent = std::variant<Ignored, Hello, LightFrame, EnvironmentFrame, Status, ControlReply>;

// The validation bound on a direction's length: |length - 1| <= kUnitDirectionTolerance.
inline constexpr double kUnitDirectionTolerance = 1e-3;

struct DecodeResult {
  ServerEvent event;
  std::string error;              // empty when the message is accepted; one sentence otherwise
  bool unsupportedMajor = false;  // the error is a protocol major this client does not speak
  [[nodiscard]] bool ok() const { return error.empty(); }
};

[[nodiscard]] DecodeResult decodeServerMessage(std::string_view bytes);

}  // namespace vem::client
