// The light-file input of light_input.h: JSON lines as vemd's sink and vemtool lights write them.
#include <cmath>
#include <fstream>

#include <fmt/format.h>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "client/vemview/light_input.h"
#include "core/color.h"

namespace vem::view {
namespace {

// A light file is read whole at open: vemd's lines are ~30 kB at 1024 lights.
constexpr std::size_t kMaxLines = 100000;

std::expected<glm::vec3, std::string> vec3Of(const nlohmann::json& value, const char* field) {
  if (!value.is_array() || value.size() != 3) {
    return std::unexpected(fmt::format("\"{}\" must be an array of three numbers", field));
  }
  glm::vec3 v;
  for (int c = 0; c < 3; ++c) {
    if (!value[std::size_t(c)].is_number()) {
      return std::unexpected(fmt::format("\"{}\" must be an array of three numbers", field));
    }
    v[c] = value[std::size_t(c)].get<float>();
    if (!std::isfinite(v[c])) {
      return std::unexpected(fmt::format("\"{}\" holds a non-finite number", field));
    }
  }
  return v;
}

std::expected<Light, std::string> lightOf(const nlohmann::json& value) {
  if (!value.is_object() || !value.contains("dir") || !value.contains("rgb")) {
    return std::unexpected("each light must be an object with \"dir\" and \"rgb\"");
  }
  auto dir = vec3Of(value["dir"], "dir");
  auto rgb = vec3Of(value["rgb"], "rgb");
  if (!dir) return std::unexpected(dir.error());
  if (!rgb) return std::unexpected(rgb.error());
  const float length = glm::length(*dir);
  if (std::abs(length - 1.0F) > 1e-3F) {
    return std::unexpected(fmt::format("\"dir\" must be a unit vector (its length is {})", length));
  }
  if (rgb->x < 0.0F || rgb->y < 0.0F || rgb->z < 0.0F) {
    return std::unexpected("\"rgb\" must not be negative");
  }
  Light light;
  light.id = value.value("id", 0U);
  light.dir = *dir / length;
  light.rgb = *rgb;
  return light;
}

// One line's lights, and how many lights they stand for when they are clusters (vemtool's and
// vemd's "clustered_from"; else the sum of the clusters' "members"; 0 when not clustered).
struct FileFrame {
  LightSet set;
  std::size_t clusteredFrom = 0;
};

std::size_t clusteredFromOf(const nlohmann::json& value) {
  if (value.contains("clustered_from") && value["clustered_from"].is_number_unsigned()) {
    return value["clustered_from"].get<std::size_t>();
  }
  std::size_t members = 0;
  for (const auto& entry : value["lights"]) {
    if (entry.contains("members") && entry["members"].is_array())
      members += entry["members"].size();
  }
  return members;
}

std::expected<FileFrame, std::string> lightSetOf(const std::string& line) {
  const nlohmann::json value = nlohmann::json::parse(line, nullptr, false);
  if (value.is_discarded() || !value.is_object()) {
    return std::unexpected("not a JSON object");
  }
  if (!value.contains("lights") || !value["lights"].is_array()) {
    return std::unexpected("no \"lights\" array");
  }
  LightSet set;
  for (const auto& entry : value["lights"]) {
    auto light = lightOf(entry);
    if (!light) {
      return std::unexpected(fmt::format("light {}: {}", set.lights.size(), light.error()));
    }
    set.luminanceSr += luminance(light->rgb);
    set.lights.push_back(*light);
  }
  set.black = set.luminanceSr <= 0.0;
  return FileFrame{std::move(set), clusteredFromOf(value)};
}

class LightFileInput final : public LightInput {
 public:
  LightFileInput(InputFacts facts, std::vector<std::shared_ptr<const FileFrame>> frames)
      : facts_(std::move(facts)), frames_(std::move(frames)) {}
  const InputFacts& facts() const override { return facts_; }
  std::optional<InputFrame> next(std::chrono::milliseconds /*wait*/) override {
    InputFrame frame;
    frame.seq = next_ + 1;
    frame.lights = std::shared_ptr<const LightSet>(frames_[next_], &frames_[next_]->set);
    frame.clusteredFrom = frames_[next_]->clusteredFrom;
    if (next_ + 1 < frames_.size()) {
      ++next_;
    }
    return frame;
  }

 private:
  InputFacts facts_;
  std::vector<std::shared_ptr<const FileFrame>> frames_;
  std::size_t next_ = 0;
};

}  // namespace

std::expected<std::unique_ptr<LightInput>, std::string> openLightFileInput(
    const std::string& path) {
  std::ifstream file(path);
  if (!file) {
    return std::unexpected(fmt::format("{}: cannot open the light file", path));
  }
  std::vector<std::shared_ptr<const FileFrame>> frames;
  bool clustered = false;
  std::string line;
  for (std::size_t number = 1; std::getline(file, line) && frames.size() < kMaxLines; ++number) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) {
      continue;
    }
    auto set = lightSetOf(line);
    if (!set) {
      return std::unexpected(
          fmt::format("{}: line {}: {} (expected a light frame as vemd's "
                      "--jsonl or vemtool lights writes it)",
                      path, number, set.error()));
    }
    if (set->set.lights.empty()) {
      return std::unexpected(fmt::format("{}: line {}: the frame holds no light", path, number));
    }
    clustered = clustered || line.find("\"members\"") != std::string::npos;
    frames.push_back(std::make_shared<const FileFrame>(std::move(*set)));
  }
  if (frames.empty()) {
    return std::unexpected(fmt::format("{}: the light file holds no frame", path));
  }
  InputFacts facts;
  facts.description =
      fmt::format("light file {} ({} frames, {} lights{})", path, frames.size(),
                  frames.front()->set.lights.size(), clustered ? ", clustered" : "");
  facts.layout = MapLayout::Hemisphere;
  facts.clustered = clustered;
  facts.cubeMaps = false;
  return std::make_unique<LightFileInput>(std::move(facts), std::move(frames));
}

}  // namespace vem::view
