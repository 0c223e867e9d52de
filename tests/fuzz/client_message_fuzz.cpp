// libFuzzer target for vemd's client-message handler (daemon/stream/client_message_handler.h):
// any bytes, with or without the token, must give one action without crashing, without undefined
// behaviour and within the protocol's rules: a close carries a WebSocket code and a reason short
// enough for a close frame; a control action only with the token, with values in range.
//
//   client_message_fuzz --write-seeds=DIR   writes a few valid ClientMessages into DIR and exits
//   client_message_fuzz [libFuzzer flags] CORPUS...
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <string_view>
#include <variant>

#include "stream/client_message_handler.h"
#include "tests/fuzz/seed_option.h"

namespace {

using namespace vem::stream;

void check(bool condition) {
  if (!condition) std::abort();
}

void checkAction(const ClientAction& action, bool authorized) {
  if (const auto* close = std::get_if<CloseAction>(&action)) {
    check(close->code >= 1000 && close->code < 5000);
    check(close->reason.size() <= 123);
  } else if (const auto* control = std::get_if<ControlAction>(&action)) {
    check(authorized);
    check(control->command.action_case() != Control::ACTION_NOT_SET);
    if (control->command.has_set_light_count()) {
      check(control->command.set_light_count() >= 1 &&
            control->command.set_light_count() <= kMaxLights);
    }
  } else if (const auto* subscribe = std::get_if<SubscribeAction>(&action)) {
    const Subscription& s = subscribe->subscription;
    check(s.cubemapRateHz >= 0.0 && s.cubemapRateHz <= kMaxCubemapRateHz);
    check(s.cube.facePx >= kMinCubeFacePx && s.cube.facePx <= kMaxCubeFacePx);
    check(s.cube.levels >= 1 && s.cube.levels <= kMaxCubeLevels);
  } else {
    check(!std::get<ReplyAction>(action).reply.ok());
  }
}

void writeSeeds(const std::string& dir) {
  auto write = [&](const std::string& name, ClientMessage message) {
    message.set_protocol_major(kProtocolMajor);
    std::ofstream(dir + "/" + name, std::ios::binary) << message.SerializeAsString();
  };
  ClientMessage subscribe;
  subscribe.set_request_id(1);
  subscribe.mutable_subscribe()->set_lights(true);
  subscribe.mutable_subscribe()->set_cubemap_rate_hz(10.0);
  subscribe.mutable_subscribe()->set_cubemap_face_px(64);
  subscribe.mutable_subscribe()->set_cubemap_levels(4);
  subscribe.mutable_subscribe()->set_preview(true);
  write("subscribe", subscribe);
  ClientMessage lights;
  lights.mutable_control()->set_set_light_count(128);
  write("set_light_count", lights);
  ClientMessage filter;
  filter.mutable_control()->set_set_filter("paper9");
  write("set_filter", filter);
  ClientMessage record;
  record.mutable_control()->mutable_start_recording()->set_name("take.vem");
  write("start_recording", record);
  ClientMessage stop;
  stop.mutable_control()->mutable_stop_recording();
  write("stop_recording", stop);
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
  vem::fuzz::handleWriteSeedsOption(*argc, *argv, writeSeeds);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  checkAction(handleClientMessage(bytes, false), false);
  checkAction(handleClientMessage(bytes, true), true);
  return 0;
}
