// Subscription: what one streaming connection receives (proto/vem_stream.proto, Subscribe), as a
// value checked against the protocol's limits (proto/stream_protocol.h). A new connection receives
// light frames only.
//
// Units: rates in Hz (frames per second of cube maps; 0: none), face sizes in texels a side.
// Pure value types; no <expected> (the fuzz target compiles this).
#pragma once

#include <compare>

#include "proto/stream_protocol.h"

namespace vem::stream {

// The shape of an environment frame a client asks for: cube face size, mip levels actually
// usable at that size (usableCubeLevels), with or without the polar preview.
struct CubeVariant {
  int facePx = kDefaultCubeFacePx;
  int levels = 1;
  bool preview = false;
  friend auto operator<=>(const CubeVariant&, const CubeVariant&) = default;
};

// The most a client without the token may ask for in cube maps ([stream] cubemap_max_face_px and
// cubemap_max_rate_hz): cube maps cost the daemon CPU time per size and rate, so a read-only
// client's share is capped. Clients with the token get the protocol's limits.
struct CubemapBudget {
  int maxFacePx = kMaxCubeFacePx;
  double maxRateHz = kMaxCubemapRateHz;
  friend bool operator==(const CubemapBudget&, const CubemapBudget&) = default;
};

struct Subscription {
  bool lights = true;
  double cubemapRateHz = 0.0;  // 0: no environment frames
  CubeVariant cube;
  [[nodiscard]] bool wantsCubemaps() const { return cubemapRateHz > 0.0; }
  friend bool operator==(const Subscription&, const Subscription&) = default;
};

}  // namespace vem::stream
