#include "client/server_message_decoder.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "proto/stream_protocol.h"
#include "proto/texel_packing.h"
#include "proto/vem_stream.pb.h"

namespace vem::client {
namespace {

namespace pb = vem::stream;
using Error = std::optional<std::string>;  // a refusal sentence, or nothing when valid

SourceState sourceState(int wire) {
  switch (wire) {
    case pb::SOURCE_STATE_UNSPECIFIED: return SourceState::Unspecified;
    case pb::SOURCE_STATE_OK: return SourceState::Ok;
    case pb::SOURCE_STATE_NO_SIGNAL: return SourceState::NoSignal;
    case pb::SOURCE_STATE_NO_DEVICE: return SourceState::NoDevice;
    case pb::SOURCE_STATE_TIMEOUT: return SourceState::Timeout;
    case pb::SOURCE_STATE_ENDED: return SourceState::Ended;
    default: return SourceState::Unknown;
  }
}

Error checkFinite(double value, std::string_view what) {
  if (std::isfinite(value)) return std::nullopt;
  return fmt::format("{} is {}, not a finite number", what, value);
}

Error checkNonNegative(double value, std::string_view what) {
  if (std::isfinite(value) && value >= 0.0) return std::nullopt;
  return fmt::format("{} is {}, not a finite number >= 0", what, value);
}

glm::vec3 vec3At(const google::protobuf::RepeatedField<float>& values, int i) {
  return {values.Get(3 * i), values.Get(3 * i + 1), values.Get(3 * i + 2)};
}

// `dir` must be finite and of unit length, `rgb` finite and >= 0; `what` names the light.
Error checkDirRgb(glm::vec3 dir, glm::vec3 rgb, std::string_view what) {
  if (!std::isfinite(dir.x) || !std::isfinite(dir.y) || !std::isfinite(dir.z)) {
    return fmt::format("{} has a non-finite direction ({}, {}, {})", what, dir.x, dir.y, dir.z);
  }
  const double length = glm::length(glm::dvec3(dir));
  if (std::abs(length - 1.0) > kUnitDirectionTolerance) {
    return fmt::format("{}'s direction ({}, {}, {}) is not a unit vector (length {})", what, dir.x,
                       dir.y, dir.z, length);
  }
  for (float channel : {rgb.x, rgb.y, rgb.z}) {
    if (!std::isfinite(channel) || channel < 0.0F) {
      return fmt::format("{}'s rgb ({}, {}, {}) is not finite and >= 0", what, rgb.x, rgb.y,
                         rgb.z);
    }
  }
  return std::nullopt;
}

Error decodeLights(const pb::LightFrame& in, LightFrame& out) {
  const std::size_t count = std::size_t(in.ids_size());
  if (count > pb::kMaxLights) {
    return fmt::format("it holds {} lights, more than the limit of {}", count, pb::kMaxLights);
  }
  if (std::size_t(in.dirs_size()) != 3 * count || std::size_t(in.rgb_size()) != 3 * count) {
    return fmt::format("it holds {} ids but {} dirs and {} rgb values (expected {} each)", count,
                       in.dirs_size(), in.rgb_size(), 3 * count);
  }
  out.lights.lights.reserve(count);
  for (int i = 0; i < int(count); ++i) {
    const Light light{in.ids(i), vec3At(in.dirs(), i), vec3At(in.rgb(), i)};
    if (Error e = checkDirRgb(light.dir, light.rgb, fmt::format("light {} (id {})", i, light.id))) {
      return e;
    }
    out.lights.lights.push_back(light);
  }
  return std::nullopt;
}

Error decodeClusters(const pb::Clusters& in, std::size_t lightCount, Clusters& out) {
  if (Error e = checkNonNegative(in.radius_rad(), "the cluster radius")) return e;
  const std::size_t count = std::size_t(in.dirs_size()) / 3;
  if (std::size_t(in.dirs_size()) != 3 * count || std::size_t(in.rgb_size()) != 3 * count) {
    return fmt::format("its clusters hold {} dirs and {} rgb values (expected 3 per cluster each)",
                       in.dirs_size(), in.rgb_size());
  }
  if (count > pb::kMaxLights) {
    return fmt::format("it holds {} clusters, more than the limit of {}", count, pb::kMaxLights);
  }
  if (std::size_t(in.member_of_size()) != lightCount) {
    return fmt::format("its clusters' member_of has {} entries for {} lights", in.member_of_size(),
                       lightCount);
  }
  out.radiusRad = in.radius_rad();
  out.clusters.reserve(count);
  for (int c = 0; c < int(count); ++c) {
    const Cluster cluster{vec3At(in.dirs(), c), vec3At(in.rgb(), c)};
    if (Error e = checkDirRgb(cluster.dir, cluster.rgb, fmt::format("cluster {}", c))) return e;
    out.clusters.push_back(cluster);
  }
  for (int i = 0; i < in.member_of_size(); ++i) {
    if (in.member_of(i) >= count) {
      return fmt::format("light {} is a member of cluster {}, but there are {} clusters", i,
                         in.member_of(i), count);
    }
  }
  out.memberOf.assign(in.member_of().begin(), in.member_of().end());
  return std::nullopt;
}

Error decodeLightFrame(const pb::LightFrame& in, LightFrame& out) {
  out.seq = in.seq();
  out.lightsSeq = in.lights_seq();
  out.captureTsNs = in.capture_ts_ns();
  out.captureUnixNs = in.capture_unix_ns();
  out.publishUnixNs = in.publish_unix_ns();
  out.status = sourceState(in.status());
  out.filtered = in.filtered();
  out.filterDelayFrames = in.filter_delay_frames();
  out.lights.luminanceSr = in.total_luminance_sr();
  out.lights.black = in.black();
  if (Error e = checkFinite(in.filter_delay_frames(), "filter_delay_frames")) return e;
  if (Error e = checkNonNegative(in.total_luminance_sr(), "total_luminance_sr")) return e;
  if (Error e = decodeLights(in, out)) return e;
  if (in.has_clusters()) {
    out.clusters.emplace();
    if (Error e = decodeClusters(in.clusters(), out.lights.lights.size(), *out.clusters)) return e;
  }
  return std::nullopt;
}

// face_px, levels and raw_bytes must lie within the limits and agree, before anything is allocated.
Error checkCubeShape(const pb::EnvironmentFrame& in) {
  const std::uint32_t facePx = in.face_px();
  if (facePx < std::uint32_t(pb::kMinCubeFacePx) || facePx > std::uint32_t(pb::kMaxCubeFacePx)) {
    return fmt::format("its face_px is {}, outside {} to {}", facePx, pb::kMinCubeFacePx,
                       pb::kMaxCubeFacePx);
  }
  const std::uint32_t levels = in.levels();
  if (levels < 1 || levels > std::uint32_t(pb::kMaxCubeLevels) ||
      pb::usableCubeLevels(int(facePx), int(levels)) != int(levels)) {
    return fmt::format("its {} levels do not fit a face of {} px (1 to {}, halving exactly)",
                       levels, facePx, pb::kMaxCubeLevels);
  }
  const std::uint64_t expected = pb::cubeRawBytes(int(facePx), int(levels));
  if (in.raw_bytes() != expected) {
    return fmt::format("its raw_bytes is {}, but {} levels of {} px faces take {} bytes",
                       in.raw_bytes(), levels, facePx, expected);
  }
  return std::nullopt;
}

// Splits the unpacked floats (level 0's six faces, then level 1's...) into `cube`, checking each.
// texels are halves times the frame's texel_scale (a power of two >= 1; 0 means 1).
Error fillCube(const std::vector<float>& rgb, float texelScale, int facePx, int levels, CubeMap& cube) {
  std::size_t at = 0;
  cube.levels.resize(std::size_t(levels));
  for (int k = 0; k < levels; ++k) {
    CubeMapLevel& level = cube.levels[std::size_t(k)];
    level.facePx = facePx >> k;
    const std::size_t faceFloats = std::size_t(level.facePx) * std::size_t(level.facePx) * 3;
    for (std::vector<float>& face : level.faces) {
      face.assign(rgb.begin() + std::ptrdiff_t(at), rgb.begin() + std::ptrdiff_t(at + faceFloats));
      if (texelScale != 1.0F) {
        for (float& value : face) value *= texelScale;
      }
      at += faceFloats;
    }
  }
  for (std::size_t i = 0; i < rgb.size(); ++i) {
    if (!std::isfinite(rgb[i]) || rgb[i] < 0.0F) {
      return fmt::format("its texel value {} is {}, not a finite number >= 0", i, rgb[i]);
    }
  }
  return std::nullopt;
}

Error decodePreview(const pb::PolarPreview& in, PolarPreview& out) {
  const std::uint64_t expected = std::uint64_t(in.width_px()) * in.height_px() * 3;
  if (in.srgb8().size() != expected) {
    return fmt::format("its preview of {} x {} px holds {} bytes, not {}", in.width_px(),
                       in.height_px(), in.srgb8().size(), expected);
  }
  out = {in.width_px(), in.height_px(), in.srgb8()};
  return std::nullopt;
}

Error decodeEnvironmentFrame(const pb::EnvironmentFrame& in, EnvironmentFrame& out) {
  out.seq = in.seq();
  out.captureTsNs = in.capture_ts_ns();
  out.publishUnixNs = in.publish_unix_ns();
  out.rawBytes = in.raw_bytes();
  out.compressedBytes = in.texels_zstd().size();
  if (Error e = checkCubeShape(in)) return e;
  const stream::UnpackResult unpacked = stream::unpackTexels(in.texels_zstd(), in.raw_bytes());
  if (!unpacked.ok()) return "its texels are unusable: " + unpacked.error;
  if (unpacked.rgb.size() * 2 != in.raw_bytes()) {
    return fmt::format("its texels unpacked to {} values, not {}", unpacked.rgb.size(),
                       in.raw_bytes() / 2);
  }
  const float texelScale = in.texel_scale() == 0.0F ? 1.0F : in.texel_scale();
  int exponent = 0;
  if (!std::isfinite(texelScale) || texelScale < 1.0F ||
      std::frexp(texelScale, &exponent) != 0.5F) {
    return fmt::format("its texel_scale is {}, not a power of two >= 1 (or 0 for 1)", in.texel_scale());
  }
  if (Error e = fillCube(unpacked.rgb, texelScale, int(in.face_px()), int(in.levels()), out.cube)) {
    return e;
  }
  if (in.has_preview()) {
    out.preview.emplace();
    if (Error e = decodePreview(in.preview(), *out.preview)) return e;
  }
  return std::nullopt;
}

Error decodeHello(const pb::Hello& in, Hello& out) {
  out = {in.server(), in.source(), in.calibration_id(), in.max_lights(), in.control_allowed(),
         in.max_client_message_bytes()};
  if (in.max_lights() > pb::kMaxLights) {
    return fmt::format("its max_lights is {}, more than the protocol's {}", in.max_lights(),
                       pb::kMaxLights);
  }
  return std::nullopt;
}

Error decodeStatus(const pb::Status& in, Status& out) {
  out = {in.source(),         sourceState(in.state()), in.frame_rate_hz(),    in.frames_processed(),
         in.frames_dropped(), in.frames_refused(),     in.latency_median_ms(), in.calibration_id(),
         in.clients(),        in.skipped_for_you(),    in.light_count(),      in.clustering(),
         in.filter(),         in.recording(),          in.offline(),          in.publish_dropped()};
  if (Error e = checkNonNegative(in.frame_rate_hz(), "frame_rate_hz")) return e;
  return checkFinite(in.latency_median_ms(), "latency_median_ms");
}

// Decodes the body into `event`; the sentence names the message kind on refusal.
Error decodeBody(const pb::ServerMessage& message, ServerEvent& event) {
  const auto run = [&event](auto value, const auto& in, auto decode, std::string_view kind) -> Error {
    Error e = decode(in, value);
    event = std::move(value);
    if (e) return fmt::format("the {} message is refused: {}", kind, *e);
    return std::nullopt;
  };
  switch (message.body_case()) {
    case pb::ServerMessage::kHello: return run(Hello{}, message.hello(), decodeHello, "hello");
    case pb::ServerMessage::kLights:
      return run(LightFrame{}, message.lights(), decodeLightFrame,
                 fmt::format("light frame {}", message.lights().seq()));
    case pb::ServerMessage::kEnvironment:
      return run(EnvironmentFrame{}, message.environment(), decodeEnvironmentFrame,
                 fmt::format("environment frame {}", message.environment().seq()));
    case pb::ServerMessage::kStatus: return run(Status{}, message.status(), decodeStatus, "status");
    case pb::ServerMessage::kReply:
      event = ControlReply{message.reply().request_id(), message.reply().ok(),
                           message.reply().message()};
      return std::nullopt;
    case pb::ServerMessage::BODY_NOT_SET: break;
  }
  event = Ignored{};
  return std::nullopt;
}

}  // namespace

DecodeResult decodeServerMessage(std::string_view bytes) {
  DecodeResult result;
  if (bytes.size() > pb::kMaxServerMessageBytes) {
    result.error = fmt::format("the daemon's message of {} bytes is over the limit of {} bytes",
                               bytes.size(), pb::kMaxServerMessageBytes);
    return result;
  }
  pb::ServerMessage message;
  if (!message.ParseFromArray(bytes.data(), int(bytes.size()))) {
    result.error = fmt::format("the daemon's message of {} bytes is not a vem.stream.ServerMessage",
                               bytes.size());
    return result;
  }
  if (message.protocol_major() != pb::kProtocolMajor) {
    result.error = fmt::format("protocol major version {} is not supported (this client speaks {})",
                               message.protocol_major(), pb::kProtocolMajor);
    result.unsupportedMajor = true;
    return result;
  }
  if (Error e = decodeBody(message, result.event)) {
    result.error = std::move(*e);
    result.event = Ignored{};
  }
  return result;
}

}  // namespace vem::client
