// StatusText: the words of vemview's status line and summary, as pure functions of counts and
// times, so that each rule is tested without a renderer or a clock:
// - one count per concept, named: "lights 256 (11 clusters) | shadow maps 11 of 64";
// - rates only over frames actually drawn (frames shown again because nothing changed are not
//   frames drawn), and no rate from one frame: "1 frame in 27.1 ms";
// - the plan is not part of these lines: vemview prints it once, at start and when it changes.
// Times in milliseconds and seconds as named.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "client/render/shading_lights.h"

namespace vem::view {

// What one frame is lit with.
struct LightCounts {
  std::size_t lights = 0;             // input lights the frame stands for
  std::size_t clusters = 0;           // the clusters they were merged into (0: not clustered)
  std::size_t shadowMaps = 0;         // lights drawn with a shadow map of their own
  std::size_t shadowMapsPlanned = 0;  // S of the plan (0: the plan has no shadow maps)
  std::size_t strataShadowMaps = 0;   // soft shadows: the maps that look along strata draws
  // --plate: how much older the lights are than the picture (live camera and stream), and the
  // plate's state when it is not a fresh picture ("ended: keeping the last picture").
  std::optional<double> lightAgeSec;
  std::string plateState;
};

// The counts of a frame's shading lights. clusteredFrom: when its diffuse lights are clusters
// (vemview's --cluster, or an input clustered already), how many lights they stand for; else 0.
[[nodiscard]] LightCounts lightCountsOf(const render::ShadingLights& shading,
                                        std::size_t clusteredFrom, std::size_t shadowMapsPlanned);

// Frames drawn over a span of wall time.
struct DrawnFrames {
  std::uint64_t count = 0;
  double seconds = 0.0;      // the wall time they were drawn in
  double renderMsSum = 0.0;  // the renderer's time for them, summed
};

// "lights 256 (11 clusters) | shadow maps 11 of 64" ("no shadow maps" without them).
[[nodiscard]] std::string lightCountsText(const LightCounts& counts);
// "1 frame in 27.1 ms", "12 frames, 3.4 frames/s, 290.1 ms each", "no frame drawn".
[[nodiscard]] std::string drawnFramesText(const DrawnFrames& drawn);
// The once-a-second line: the frames drawn since the last line, then the light counts.
[[nodiscard]] std::string statusText(const DrawnFrames& sinceLastLine, const LightCounts& counts);
// The end of a run: every frame drawn, those shown again, the light counts of the last frame.
[[nodiscard]] std::string summaryText(const DrawnFrames& all, std::uint64_t notRedrawn,
                                      const LightCounts& counts);

}  // namespace vem::view
