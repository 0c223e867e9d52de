#include "stream/client_message_handler.h"

#include <cmath>
#include <cstdio>

namespace vem::stream {

namespace {

constexpr std::size_t kMaxFilterNameBytes = 64;
constexpr std::size_t kMaxRecordingNameBytes = 128;

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

ReplyAction refuse(std::uint64_t requestId, std::string message) {
  ReplyAction action;
  action.reply.set_request_id(requestId);
  action.reply.set_ok(false);
  action.reply.set_message(std::move(message));
  return action;
}

// Empty when the command's values are within the protocol's ranges.
std::string controlProblem(const Control& control) {
  switch (control.action_case()) {
    case Control::kSetLightCount:
      if (control.set_light_count() < 1 || control.set_light_count() > kMaxLights) {
        return "set_light_count must be 1 to " + std::to_string(kMaxLights) + ", not " +
               std::to_string(control.set_light_count());
      }
      return {};
    case Control::kSetClusterBudget:
      if (control.set_cluster_budget() > kMaxLights) {
        return "set_cluster_budget must be 0 (off) to " + std::to_string(kMaxLights) + ", not " +
               std::to_string(control.set_cluster_budget());
      }
      return {};
    case Control::kSetFilter:
      if (control.set_filter().empty() || control.set_filter().size() > kMaxFilterNameBytes) {
        return "set_filter must name a filter preset (\"none\", \"paper9\", \"equiripple5\", "
               "\"minphase9\")";
      }
      return {};
    case Control::kStartRecording: return recordingNameProblem(control.start_recording().name());
    case Control::kStopRecording: return {};
    case Control::ACTION_NOT_SET: break;
  }
  return "the control message has no action this daemon knows (it speaks protocol 1.0)";
}

ClientAction control(const ClientMessage& message, bool authorized) {
  if (!authorized) return refuse(message.request_id(), kControlNeedsToken);
  if (std::string problem = controlProblem(message.control()); !problem.empty()) {
    return refuse(message.request_id(), std::move(problem));
  }
  return ControlAction{message.control(), message.request_id()};
}

ClientAction subscribe(const ClientMessage& message, bool authorized,
                       const CubemapBudget& readOnlyBudget) {
  SubscriptionResult result =
      subscriptionFrom(message.subscribe(), authorized ? CubemapBudget{} : readOnlyBudget);
  if (!result.problem.empty()) return refuse(message.request_id(), std::move(result.problem));
  return SubscribeAction{result.subscription, message.request_id()};
}

bool nameCharacter(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
         c == '_' || c == '-';
}

}  // namespace

std::string recordingNameProblem(const std::string& name) {
  if (name.empty()) return {};
  if (name.size() > kMaxRecordingNameBytes) {
    return "the recording name must be at most 128 bytes";
  }
  for (const char c : name) {
    if (!nameCharacter(c)) {
      return "the recording name may hold only ASCII letters, digits, '.', '_' and '-'";
    }
  }
  if (name.front() == '.' || name.front() == '-') {
    return "the recording name must not start with '.' or '-'";
  }
  const auto dot = name.rfind('.');
  if (dot != std::string::npos && name.substr(dot) != ".vem") {
    return "the recording name must end in \".vem\" or have no extension";
  }
  return {};
}

SubscriptionResult subscriptionFrom(const Subscribe& subscribe, const CubemapBudget& budget) {
  SubscriptionResult result;
  const double rate = subscribe.cubemap_rate_hz();
  if (!std::isfinite(rate) || rate < 0.0 || rate > kMaxCubemapRateHz) {
    result.problem = "cubemap_rate_hz must be 0 (none) to " + number(kMaxCubemapRateHz) + ", not " +
                     number(rate);
    return result;
  }
  const std::uint32_t face = subscribe.cubemap_face_px();
  if (face != 0 && (face < std::uint32_t(kMinCubeFacePx) || face > std::uint32_t(kMaxCubeFacePx))) {
    result.problem = "cubemap_face_px must be 0 (64) or " + std::to_string(kMinCubeFacePx) +
                     " to " + std::to_string(kMaxCubeFacePx) + ", not " + std::to_string(face);
    return result;
  }
  if (rate > budget.maxRateHz) {
    result.problem = "cubemap_rate_hz " + number(rate) + " is over the " +
                     number(budget.maxRateHz) + " this daemon allows clients without the token";
    return result;
  }
  if (face != 0 && face > std::uint32_t(budget.maxFacePx)) {
    result.problem = "cubemap_face_px " + std::to_string(face) + " is over the " +
                     std::to_string(budget.maxFacePx) +
                     " this daemon allows clients without the token";
    return result;
  }
  const std::uint32_t levels = subscribe.cubemap_levels();
  if (levels > std::uint32_t(kMaxCubeLevels)) {
    result.problem = "cubemap_levels must be 0 or 1 (no mip levels) to " +
                     std::to_string(kMaxCubeLevels) + ", not " + std::to_string(levels);
    return result;
  }
  Subscription& s = result.subscription;
  s.lights = subscribe.lights();
  s.cubemapRateHz = rate;
  s.cube.facePx = face == 0 ? kDefaultCubeFacePx : int(face);
  s.cube.levels = usableCubeLevels(s.cube.facePx, int(levels));
  s.cube.preview = subscribe.preview();
  return result;
}

ClientAction handleClientMessage(std::string_view bytes, bool authorized,
                                 const CubemapBudget& readOnlyBudget) {
  ClientMessage message;
  if (bytes.size() > kMaxClientMessageBytes ||
      !message.ParseFromArray(bytes.data(), int(bytes.size()))) {
    return CloseAction{close_code::kInvalidPayload,
                       "the message is not a vem.stream.ClientMessage"};
  }
  if (message.protocol_major() != kProtocolMajor) {
    return CloseAction{close_code::kProtocolError, "protocol major version " +
                                                       std::to_string(message.protocol_major()) +
                                                       " is not supported (vemd speaks " +
                                                       std::to_string(kProtocolMajor) + ")"};
  }
  switch (message.body_case()) {
    case ClientMessage::kSubscribe: return subscribe(message, authorized, readOnlyBudget);
    case ClientMessage::kControl: return control(message, authorized);
    case ClientMessage::BODY_NOT_SET: break;
  }
  return refuse(message.request_id(),
                "the message asks for nothing this daemon knows (it speaks protocol 1.0)");
}

}  // namespace vem::stream
