// StatusLine: what vemview tells the user while it runs: once a second on stderr (and as the
// window's overlay) the frame rate, the light count, the shadowed lights, how many shadow maps were
// redrawn or reused, the skipped frames and the plan; a summary at the end.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>

#include "client/render/shading_lights.h"
#include "client/vemview/render_plan.h"

namespace vem::view {

class StatusLine {
 public:
  void add(bool drawn, double renderMs, const render::ShadingLights& lights);
  void maybePrint(const RenderPlan& plan);  // at most once a second
  // The window's overlay: the line as last printed (it changes once a second, so the overlay is
  // redrawn once a second), then the plan.
  [[nodiscard]] std::string overlay(const RenderPlan& plan) const;
  void printSummary(const RenderPlan& plan, const std::string& lastPicture) const;

 private:
  [[nodiscard]] std::string line() const;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point lastPrint_ = start_;
  std::uint64_t frames_ = 0;
  std::uint64_t drawn_ = 0;
  std::uint64_t framesSincePrint_ = 0;
  double fps_ = 0.0;
  double renderMsSum_ = 0.0;
  double lastRenderMs_ = 0.0;
  std::size_t lights_ = 0;
  std::size_t shadowed_ = 0;
  std::string shown_;
};

}  // namespace vem::view
