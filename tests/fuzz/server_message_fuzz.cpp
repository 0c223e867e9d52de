// libFuzzer target for the client's decoder (client/server_message_decoder.h): any bytes from a
// daemon must decode or be refused with a sentence, without crashing, without undefined behaviour,
// and without allocating from unchecked sizes; what it accepts must hold what the checks promise.
//
//   server_message_fuzz --write-seeds=DIR   writes a few valid ServerMessages into DIR and exits
//   server_message_fuzz [libFuzzer flags] CORPUS...
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "client/server_message_decoder.h"
#include "proto/stream_protocol.h"
#include "proto/texel_packing.h"
#include "proto/vem_stream.pb.h"
#include "tests/fuzz/seed_option.h"

namespace {

namespace pb = vem::stream;
using namespace vem::client;

std::string bytesOf(pb::ServerMessage message) {
  message.set_protocol_major(pb::kProtocolMajor);
  message.set_protocol_minor(pb::kProtocolMinor);
  return message.SerializeAsString();
}

pb::ServerMessage lightSeed(int count, bool clusters) {
  pb::ServerMessage message;
  pb::LightFrame& frame = *message.mutable_lights();
  frame.set_seq(7);
  frame.set_lights_seq(3);
  frame.set_publish_unix_ns(1'700'000'000'000'000'000);
  frame.set_status(pb::SOURCE_STATE_OK);
  frame.set_total_luminance_sr(2.5);
  for (int i = 0; i < count; ++i) {
    frame.add_ids(std::uint32_t(i));
    for (float v : {0.0F, 1.0F, 0.0F}) frame.add_dirs(v);
    for (float v : {0.5F, float(i), 1.0F}) frame.add_rgb(v);
    if (clusters) frame.mutable_clusters()->add_member_of(std::uint32_t(i % 2));
  }
  if (clusters) {
    pb::Clusters& c = *frame.mutable_clusters();
    c.set_radius_rad(0.3);
    for (float v : {1.0F, 0.0F, 0.0F, 0.0F, 0.0F, 1.0F}) c.add_dirs(v);
    for (float v : {1.0F, 2.0F, 3.0F, 4.0F, 5.0F, 6.0F}) c.add_rgb(v);
  }
  return message;
}

pb::ServerMessage environmentSeed(int facePx, int levels, bool preview) {
  pb::ServerMessage message;
  pb::EnvironmentFrame& frame = *message.mutable_environment();
  frame.set_seq(9);
  frame.set_face_px(std::uint32_t(facePx));
  frame.set_levels(std::uint32_t(levels));
  frame.set_raw_bytes(pb::cubeRawBytes(facePx, levels));
  std::vector<float> texels(pb::cubeRawBytes(facePx, levels) / 2);
  for (std::size_t i = 0; i < texels.size(); ++i) texels[i] = float(i % 5);
  frame.set_texels_zstd(pb::packTexels(texels, 3));
  if (preview) {
    frame.mutable_preview()->set_width_px(2);
    frame.mutable_preview()->set_height_px(2);
    frame.mutable_preview()->set_srgb8(std::string(12, '\x40'));
  }
  return message;
}

void writeSeeds(const std::string& dir) {
  const auto write = [&](const std::string& name, const std::string& bytes) {
    std::ofstream out(dir + "/" + name, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), std::streamsize(bytes.size()));
  };
  pb::ServerMessage hello;
  hello.mutable_hello()->set_server("vemd seed");
  hello.mutable_hello()->set_max_lights(64);
  write("hello.bin", bytesOf(hello));
  write("lights.bin", bytesOf(lightSeed(4, false)));
  write("lights_clustered.bin", bytesOf(lightSeed(5, true)));
  write("environment_8.bin", bytesOf(environmentSeed(8, 4, false)));
  write("environment_12_preview.bin", bytesOf(environmentSeed(12, 2, true)));
  pb::ServerMessage status;
  status.mutable_status()->set_frame_rate_hz(30.0);
  status.mutable_status()->set_filter("paper9");
  write("status.bin", bytesOf(status));
  pb::ServerMessage reply;
  reply.mutable_reply()->set_request_id(3);
  reply.mutable_reply()->set_message("no");
  write("reply.bin", bytesOf(reply));
}

bool unit(glm::vec3 dir) {
  return std::abs(glm::length(glm::dvec3(dir)) - 1.0) <= kUnitDirectionTolerance;
}

bool nonNegative(glm::vec3 rgb) { return rgb.x >= 0.0F && rgb.y >= 0.0F && rgb.z >= 0.0F; }

// What an accepted message must hold (the decoder's promises).
void checkAccepted(const ServerEvent& event) {
  if (const auto* frame = std::get_if<LightFrame>(&event)) {
    if (frame->lights.lights.size() > pb::kMaxLights) std::abort();
    for (const vem::Light& light : frame->lights.lights) {
      if (!unit(light.dir) || !nonNegative(light.rgb)) std::abort();
    }
    if (frame->clusters) {
      for (std::uint32_t m : frame->clusters->memberOf) {
        if (m >= frame->clusters->clusters.size()) std::abort();
      }
      if (frame->clusters->memberOf.size() != frame->lights.lights.size()) std::abort();
    }
  } else if (const auto* environment = std::get_if<EnvironmentFrame>(&event)) {
    const auto& levels = environment->cube.levels;
    if (levels.empty() || levels.size() > std::size_t(pb::kMaxCubeLevels)) std::abort();
    for (const vem::CubeMapLevel& level : levels) {
      for (const std::vector<float>& face : level.faces) {
        if (face.size() != std::size_t(level.facePx) * std::size_t(level.facePx) * 3) std::abort();
      }
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
  vem::fuzz::handleWriteSeedsOption(*argc, *argv, writeSeeds);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const DecodeResult result =
      decodeServerMessage(std::string_view(reinterpret_cast<const char*>(data), size));
  if (result.ok()) {
    checkAccepted(result.event);
  } else if (result.error.empty() || !std::holds_alternative<Ignored>(result.event)) {
    std::abort();
  }
  return 0;
}
