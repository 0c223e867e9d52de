// LightInput: where vemview's lights (and cube maps) come from, one InputFrame at a time.
//
// - stream (`--connect ws://HOST:PORT`): vemd's stream through client/stream_client.h; a new
//   frame each time the daemon publishes one; lights in vemd's world frame (hemisphere map).
// - light file (`--lights FILE.jsonl`): vemd's JSON-lines sink or `vemtool lights` output, one
//   frame per line (daemon/vemd/sinks/light_json.h); after the last line the last frame stays.
// - map file (`--map FILE`): an environment map (daemon/mapio); the lights are computed once with
//   the core (Havran sampler, the default pattern), the cube map once when the plan wants it; the
//   frame never changes.
// InputFrame::seq changes exactly when the lights change, so the render plan can reuse shadow maps
// and skip redraws. Directions in the world frame of core/env_map.h; rgb as in core/light.h.
#pragma once

#include <chrono>
#include <cstdint>
#include <expected>
#include <memory>
#include <optional>
#include <string>

#include "core/cube_map.h"
#include "core/env_map.h"
#include "core/light.h"

#include "util/mosquitto_client.h"

namespace vem::view {

struct InputFrame {
  std::uint64_t seq = 0;
  std::shared_ptr<const LightSet> lights;  // id order (a progressive set) unless clustered
  std::shared_ptr<const CubeMap> cube;     // null when none
  std::uint64_t cubeVersion = 0;           // changes when the cube map does
  std::shared_ptr<const EnvMap> map;       // the map file's map (reference renderer), else null
  std::size_t clusteredFrom = 0;  // lights are clusters already: how many lights they stand for
  // When the light probe's frame was captured (the stream's capture time, CLOCK_REALTIME), for
  // the age of the lights against a live plate's picture; nothing for files.
  std::optional<double> captureUnixSec;
};

struct InputFacts {
  std::string description;  // "map park.exr (512 x 256)", "stream ws://...", ...
  MapLayout layout = MapLayout::Hemisphere;
  bool clustered = false;  // the lights are clusters already (vemd --cluster in a light file)
  bool live = false;       // frames keep coming (stream)
  bool cubeMaps = true;    // the input can give cube maps (a light file cannot)
};

class LightInput {
 public:
  virtual ~LightInput() = default;
  [[nodiscard]] virtual const InputFacts& facts() const = 0;
  // The newest frame, waiting up to `wait` for one newer than the last returned; the last one
  // again when nothing newer came (empty only before the first frame ever arrived).
  [[nodiscard]] virtual std::optional<InputFrame> next(std::chrono::milliseconds wait) = 0;
  // One sentence when the input has failed for good (stream refused), else empty.
  [[nodiscard]] virtual std::string failure() const { return {}; }
};

struct MapInputOptions {
  std::size_t lightCount = 1024;  // lights generated once (the plan's N takes a prefix)
  bool cubeMap = false;
  int cubeFacePx = 128;
};

[[nodiscard]] std::expected<std::unique_ptr<LightInput>, std::string> openMapInput(
    const std::string& path, const MapInputOptions& options);
[[nodiscard]] std::expected<std::unique_ptr<LightInput>, std::string> openLightFileInput(
    const std::string& path);

struct StreamInputOptions {
  std::string url;
  std::string token;
  util::MqttSecurity security;  // MQTT credentials, and the CA file for wss and mqtts
  bool cubeMap = false;
  double cubeMapRateHz = 2.0;
  std::uint32_t cubeFacePx = 128;
};
[[nodiscard]] std::expected<std::unique_ptr<LightInput>, std::string> openStreamInput(
    const StreamInputOptions& options);

}  // namespace vem::view
