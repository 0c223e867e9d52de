#include "client/stream_test_messages.h"

#include <cmath>

#include "proto/stream_protocol.h"
#include "proto/texel_packing.h"

namespace vem::client::test {

stream::ServerMessage lightFrameMessage(std::uint64_t seq, int count) {
  stream::ServerMessage message;
  stream::LightFrame& frame = *message.mutable_lights();
  frame.set_seq(seq);
  frame.set_lights_seq(seq >= 4 ? seq - 4 : 0);
  frame.set_capture_ts_ns(std::int64_t(seq) * 33'333'333);
  frame.set_capture_unix_ns(1'700'000'000'000'000'000 + std::int64_t(seq));
  frame.set_publish_unix_ns(1'700'000'000'000'000'100 + std::int64_t(seq));
  frame.set_status(stream::SOURCE_STATE_OK);
  frame.set_filtered(true);
  frame.set_filter_delay_frames(4.0);
  frame.set_total_luminance_sr(12.5);
  for (int i = 0; i < count; ++i) {
    const double angle = 0.3 * i;
    frame.add_ids(std::uint32_t(i));
    frame.add_dirs(float(std::cos(angle)));
    frame.add_dirs(0.0F);
    frame.add_dirs(float(std::sin(angle)));
    frame.add_rgb(float(i + 1));
    frame.add_rgb(float(2 * i + 1));
    frame.add_rgb(0.5F);
  }
  return message;
}

std::vector<float> testTexels(int facePx, int levels) {
  std::vector<float> texels(stream::cubeRawBytes(facePx, levels) / 2);
  for (std::size_t i = 0; i < texels.size(); ++i) texels[i] = float(i % 7) * 0.25F;
  return texels;
}

stream::ServerMessage environmentMessage(std::uint64_t seq, int facePx, int levels) {
  stream::ServerMessage message;
  stream::EnvironmentFrame& frame = *message.mutable_environment();
  frame.set_seq(seq);
  frame.set_capture_ts_ns(std::int64_t(seq) * 33'333'333);
  frame.set_publish_unix_ns(1'700'000'000'000'000'000 + std::int64_t(seq));
  frame.set_face_px(std::uint32_t(facePx));
  frame.set_levels(std::uint32_t(levels));
  frame.set_raw_bytes(stream::cubeRawBytes(facePx, levels));
  frame.set_texels_zstd(stream::packTexels(testTexels(facePx, levels), 3));
  return message;
}

stream::ServerMessage helloMessage(bool controlAllowed) {
  stream::ServerMessage message;
  stream::Hello& hello = *message.mutable_hello();
  hello.set_server("fixture 1.0");
  hello.set_source("replay:test");
  hello.set_calibration_id("cal-1");
  hello.set_max_lights(256);
  hello.set_control_allowed(controlAllowed);
  hello.set_max_client_message_bytes(65536);
  return message;
}

std::string bytesOf(stream::ServerMessage message, std::uint32_t major, std::uint32_t minor) {
  message.set_protocol_major(major);
  message.set_protocol_minor(minor);
  return message.SerializeAsString();
}

}  // namespace vem::client::test
