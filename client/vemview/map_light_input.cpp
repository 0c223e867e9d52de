// The map-file input of light_input.h: lights and cube map computed once.
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "client/vemview/light_input.h"
#include "core/default_pattern.h"
#include "core/light_generator.h"
#include "core/sampling_tables.h"
#include "mapio/map_file.h"

namespace vem::view {
namespace {

constexpr int kCubeLevels = 8;

class MapLightInput final : public LightInput {
 public:
  MapLightInput(InputFacts facts, InputFrame frame) : facts_(std::move(facts)), frame_(frame) {}
  const InputFacts& facts() const override { return facts_; }
  std::optional<InputFrame> next(std::chrono::milliseconds /*wait*/) override { return frame_; }

 private:
  InputFacts facts_;
  InputFrame frame_;
};

}  // namespace

std::expected<std::unique_ptr<LightInput>, std::string> openMapInput(
    const std::string& path, const MapInputOptions& options) {
  auto map = mapio::loadMap(path);
  if (!map) {
    return std::unexpected(map.error().message);
  }
  const SamplingTables tables = buildSamplingTables(*map);
  if (tables.badPixels > 0) {
    spdlog::warn("{}: {} pixels had NaN, infinite or negative values; they count as 0", path,
                 tables.badPixels);
  }
  if (tables.black) {
    spdlog::warn("{}: the map is black; every light has rgb 0", path);
  }
  const std::size_t count = std::clamp<std::size_t>(options.lightCount, 1, kMaxLights);
  InputFrame frame;
  frame.seq = 1;
  frame.lights = std::make_shared<const LightSet>(generateLights(
      tables, defaultSamplingPattern(map->layout).first(count), SamplerKind::Havran));
  if (options.cubeMap) {
    frame.cube =
        std::make_shared<const CubeMap>(cubeMapFromEnvMap(*map, options.cubeFacePx, kCubeLevels));
    frame.cubeVersion = 1;
  }
  InputFacts facts;
  facts.description =
      fmt::format("map {} ({} x {}, {})", path, map->width, map->height, layoutName(map->layout));
  facts.layout = map->layout;
  frame.map = std::make_shared<const EnvMap>(std::move(*map));
  return std::make_unique<MapLightInput>(std::move(facts), std::move(frame));
}

}  // namespace vem::view
