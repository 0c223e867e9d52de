#include "client/vemview/status_text.h"

#include <cmath>

#include <fmt/format.h>

namespace vem::view {
namespace {

// "3.4 frames/s, 290.1 ms each" for two frames or more; below one frame a second, two
// significant digits ("0.043 frames/s"), not "0.0".
std::string rateText(const DrawnFrames& drawn) {
  const double meanMs = drawn.renderMsSum / double(drawn.count);
  if (drawn.seconds <= 0.0) {
    return fmt::format("{:.1f} ms each", meanMs);
  }
  const double rate = double(drawn.count) / drawn.seconds;
  return rate >= 1.0 ? fmt::format("{:.1f} frames/s, {:.1f} ms each", rate, meanMs)
                     : fmt::format("{:.2g} frames/s, {:.1f} ms each", rate, meanMs);
}

}  // namespace

LightCounts lightCountsOf(const render::ShadingLights& shading, std::size_t clusteredFrom,
                          std::size_t shadowMapsPlanned) {
  const std::size_t diffuse = shading.diffuse.lights.size();
  return LightCounts{clusteredFrom > 0 ? clusteredFrom : diffuse, clusteredFrom > 0 ? diffuse : 0,
                     shading.shadowDirs.size(), shadowMapsPlanned, 0, std::nullopt, {}};
}

std::string lightCountsText(const LightCounts& counts) {
  std::string text = fmt::format("lights {}", counts.lights);
  if (counts.clusters > 0) {
    text += fmt::format(" ({} cluster{})", counts.clusters, counts.clusters == 1 ? "" : "s");
  }
  text += counts.shadowMapsPlanned == 0
              ? std::string(" | no shadow maps")
              : fmt::format(" | shadow maps {} of {}", counts.shadowMaps, counts.shadowMapsPlanned);
  if (counts.strataShadowMaps > 0) {
    text += fmt::format(" (soft: {} maps along strata draws)", counts.strataShadowMaps);
  }
  if (counts.lightAgeSec) {
    text += fmt::format(" | lights {:.3f} s {} than the picture", std::abs(*counts.lightAgeSec),
                        *counts.lightAgeSec >= 0.0 ? "older" : "newer");
  }
  if (!counts.plateState.empty()) {
    text += " | plate " + counts.plateState;
  }
  return text;
}

std::string drawnFramesText(const DrawnFrames& drawn) {
  if (drawn.count == 0) {
    return "no frame drawn";
  }
  if (drawn.count == 1) {
    return fmt::format("1 frame in {:.1f} ms", drawn.renderMsSum);
  }
  return fmt::format("{} frames, {}", drawn.count, rateText(drawn));
}

std::string statusText(const DrawnFrames& sinceLastLine, const LightCounts& counts) {
  return drawnFramesText(sinceLastLine) + " | " + lightCountsText(counts);
}

std::string summaryText(const DrawnFrames& all, std::uint64_t notRedrawn,
                        const LightCounts& counts) {
  std::string text;
  if (all.count == 0) {
    text = "no frame drawn";
  } else if (all.count == 1) {
    text = fmt::format("1 frame drawn in {:.1f} ms", all.renderMsSum);
  } else {
    text = fmt::format("{} frames drawn in {:.2f} s ({})", all.count, all.seconds, rateText(all));
  }
  if (notRedrawn > 0) {
    text += fmt::format(", {} not redrawn (nothing changed)", notRedrawn);
  }
  return text + " | " + lightCountsText(counts);
}

}  // namespace vem::view
