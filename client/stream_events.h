// The messages a vemd stream sends (proto/vem_stream.proto, docs/protocol.md) as C++ values, after
// the client's decoder (server_message_decoder.h) has checked them.
//
// Conventions (docs/conventions.md): directions are unit vectors from the scene toward the light in
// the world frame (right-handed, +Y up); rgb is radiance times solid angle (map units x sr), >= 0.
// Times in ns: *UnixNs on CLOCK_REALTIME, captureTsNs on the source's own clock. Cube maps use
// core/cube_map.h's faces, order and orientation (OpenGL +X, -X, +Y, -Y, +Z, -Z), floats RGB.
// Plain values: no threads, no I/O; no <expected> (the fuzz target compiles this with clang).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

#include "core/cube_map.h"
#include "core/light.h"

namespace vem::client {

// The source's state as the daemon reports it; Unknown: a value from a newer protocol minor.
enum class SourceState { Unspecified, Ok, NoSignal, NoDevice, Timeout, Ended, Unknown };

[[nodiscard]] std::string_view sourceStateName(SourceState state);  // "ok", "no signal", ...

struct Hello {
  std::string server;         // "vemd 0.5.0"
  std::string source;         // the source spec
  std::string calibrationId;
  std::uint32_t maxLights = 0;
  bool controlAllowed = false;  // this connection presented the token
  std::uint32_t maxClientMessageBytes = 0;
};

struct Cluster {
  glm::vec3 dir{0.0F, 1.0F, 0.0F};  // unit
  glm::vec3 rgb{0.0F};              // >= 0
};

struct Clusters {
  double radiusRad = 0.0;
  std::vector<Cluster> clusters;
  std::vector<std::uint32_t> memberOf;  // one per light: the index of its cluster
};

struct LightFrame {
  std::uint64_t seq = 0;
  std::uint64_t lightsSeq = 0;  // the frame the lights stand for (seq - filter delay)
  std::int64_t captureTsNs = 0;
  std::int64_t captureUnixNs = 0;
  std::int64_t publishUnixNs = 0;
  SourceState status = SourceState::Unspecified;
  bool filtered = false;
  double filterDelayFrames = 0.0;
  // The lights in id order; lights.luminanceSr is total_luminance_sr, lights.black is black.
  LightSet lights;
  std::optional<Clusters> clusters;  // present when the daemon clusters
};

// A small tone-mapped picture of the polar map: 8-bit sRGB, row-major, widthPx x heightPx x 3.
struct PolarPreview {
  std::uint32_t widthPx = 0;
  std::uint32_t heightPx = 0;
  std::string srgb8;
};

struct EnvironmentFrame {
  std::uint64_t seq = 0;
  std::int64_t captureTsNs = 0;
  std::int64_t publishUnixNs = 0;
  std::uint64_t rawBytes = 0;         // decompressed texel bytes, all levels (as sent)
  std::uint64_t compressedBytes = 0;  // size of texels_zstd
  CubeMap cube;                       // cube.levels[0].facePx is face_px; levels as sent
  std::optional<PolarPreview> preview;
};

struct Status {
  std::string source;
  SourceState state = SourceState::Unspecified;
  double frameRateHz = 0.0;
  std::uint64_t framesProcessed = 0;
  std::uint64_t framesDropped = 0;
  std::uint64_t framesRefused = 0;
  double latencyMedianMs = 0.0;
  std::string calibrationId;
  std::uint32_t clients = 0;
  std::uint64_t skippedForYou = 0;
  std::uint32_t lightCount = 0;
  bool clustering = false;
  std::string filter;
  bool recording = false;
  bool offline = false;              // MQTT: the camera's vemd is gone (its will or its goodbye)
  std::uint64_t publishDropped = 0;  // MQTT: messages vemd's publisher dropped
};

struct ControlReply {
  std::uint64_t requestId = 0;
  bool ok = false;
  std::string message;  // why not, when !ok
};

// A message whose body this client does not know (a newer protocol minor): ignored, not an error.
struct Ignored {};

}  // namespace vem::client
