// Frame encoding: vemd's processed frames and cube maps as the streaming protocol's messages
// (proto/vem_stream.proto). Pure functions of their arguments (unixNowNs reads the clock); callable
// from any thread; the returned messages own their data.
//
// Conventions: directions unit, in the world frame of env_map.h (right-handed, +Y up); rgb in
// light.h's units (map units x sr); times in nanoseconds, *UnixNs on CLOCK_REALTIME, capture_ts_ns
// on the source's clock. Light frames carry exactly the lights the JSON-lines sink writes
// (frames/published_lights.h): the filtered set when the frame has one, else its own lights, in
// id order, and the clustering of that set when present.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "core/cube_map.h"
#include "core/env_map.h"
#include "frames/processed_frame.h"
#include "proto/vem_stream.pb.h"

namespace vem::stream {

// What a light frame carries besides the processed frame itself.
struct LightFrameStamp {
  std::int64_t captureUnixNs = 0;  // when vemd received the frame
  std::int64_t publishUnixNs = 0;  // when processing finished
  SourceState status = SOURCE_STATE_OK;
  double filterDelayFrames = 0.0;  // the temporal filter's delay (0 without a filter)
};

// A ServerMessage holding a LightFrame (protocol version not yet set: see serialize).
// `frame.captured` must not be null.
[[nodiscard]] ServerMessage lightFrameMessage(const ProcessedFrame& frame,
                                              const LightFrameStamp& stamp);

// A ServerMessage holding an EnvironmentFrame of `cube` (all its levels; face size and level count
// from the cube): texels divided by texel_scale, the smallest power of two that brings the
// brightest finite texel into the half range, as halves in zstd at `zstdLevel`
// (proto/texel_packing.h). Only infinities are then clamped; their count is stored in
// *clampedCount when not null.
[[nodiscard]] ServerMessage environmentFrameMessage(const CubeMap& cube, std::uint64_t seq,
                                                    std::int64_t captureTsNs,
                                                    std::int64_t publishUnixNs, int zstdLevel,
                                                    std::size_t* clampedCount = nullptr);

// Adds a PolarPreview of `polar` to the environment message: widthPx x widthPx (1..1024) sRGB
// bytes, the map seen as the camera sees it: an equidistant disc, zenith at the centre, theta
// proportional to the distance from it up to the map's thetaMax at the disc's edge (the horizon for
// a Hemisphere map), phi = 0 (+X) to the right and phi = pi/2 (+Z) downward; outside the disc
// black. Tone mapped with preview_image.h's operator (Reinhard's global operator, key 0.18,
// log-average over the disc's pixels, then sRGB). `environment` must hold an EnvironmentFrame.
void attachPolarPreview(ServerMessage& environment, const EnvMap& polar, int widthPx);

// The message's bytes with protocol_major / protocol_minor set to this build's version.
[[nodiscard]] std::string serialize(ServerMessage message);

// Now on CLOCK_REALTIME, in nanoseconds since the Unix epoch.
[[nodiscard]] std::int64_t unixNowNs();

}  // namespace vem::stream
