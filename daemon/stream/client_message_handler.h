// handleClientMessage: what vemd does with one binary WebSocket message from a client
// (proto/vem_stream.proto, ClientMessage), decided without I/O: a new subscription, a control
// command for the processing thread, a reply, or closing the connection with a WebSocket status
// and reason. The server (stream_server.h) carries the decision out.
//
// - Bytes that are not a ClientMessage: close 1007 (invalid payload).
// - A protocol_major other than kProtocolMajor: close 1002 with "protocol major version N is not
//   supported (vemd speaks 1)".
// - Subscribe out of range (rate not in [0, 60], face not 0 or 8..512, levels over 8), or, for a
//   client without the token, over the read-only budget (CubemapBudget: a smaller face or rate):
//   a reply ok = false naming the field; the old subscription stays. Face 0 means 64, levels 0
//   mean 1; levels are clamped to those usable at the face size.
// - Control without the token (`authorized` false): reply ok = false "control messages need the
//   token". Control values checked here: light count 1..kMaxLights, cluster budget 0..kMaxLights,
//   a filter name of 1..64 bytes, a recording name of 1 to 128 letters, digits, '.', '_' and '-'
//   (recordingNameProblem). The filter name itself is checked where it is applied.
// - A message with no body (a later minor version's request): reply ok = false.
// Pure: no threads, I/O, logging, no <expected> (the libFuzzer target compiles this with clang).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <variant>

#include "proto/vem_stream.pb.h"
#include "stream/subscription.h"

namespace vem::stream {

namespace close_code {
inline constexpr std::uint16_t kProtocolError = 1002;
inline constexpr std::uint16_t kUnsupportedData = 1003;
inline constexpr std::uint16_t kInvalidPayload = 1007;
inline constexpr std::uint16_t kPolicyViolation = 1008;
inline constexpr std::uint16_t kTooBig = 1009;
}  // namespace close_code

inline constexpr const char* kControlNeedsToken = "control messages need the token";

struct SubscribeAction {
  Subscription subscription;
  std::uint64_t requestId = 0;
};
struct ControlAction {
  Control command;  // validated as above
  std::uint64_t requestId = 0;
};
struct ReplyAction {
  ControlReply reply;  // ok = false with the reason
};
struct CloseAction {
  std::uint16_t code = close_code::kInvalidPayload;
  std::string reason;  // at most 123 bytes (a WebSocket close reason's limit)
};

using ClientAction = std::variant<SubscribeAction, ControlAction, ReplyAction, CloseAction>;

// `readOnlyBudget` applies to subscriptions when `authorized` is false.
[[nodiscard]] ClientAction handleClientMessage(std::string_view bytes, bool authorized,
                                               const CubemapBudget& readOnlyBudget = {});

// The subscription a valid Subscribe asks for, or the reason it is out of range.
struct SubscriptionResult {
  Subscription subscription;
  std::string problem;  // empty when valid
};
[[nodiscard]] SubscriptionResult subscriptionFrom(const Subscribe& subscribe,
                                                  const CubemapBudget& budget = {});

// Empty when `name` may name a recording a client starts: "" (vemd picks one), or 1 to 128 bytes
// of ASCII letters, digits, '.', '_' and '-', not starting with '.' or '-', with no extension or
// ".vem". Otherwise why not, in one sentence (the name itself is not repeated: it may not be
// printable).
[[nodiscard]] std::string recordingNameProblem(const std::string& name);

}  // namespace vem::stream
