#include "client/vemview/status_line.h"

#include <fmt/format.h>

namespace vem::view {

void StatusLine::add(bool drawn, double renderMs, const render::ShadingLights& lights) {
  ++frames_;
  ++framesSincePrint_;
  if (drawn) {
    ++drawn_;
    renderMsSum_ += renderMs;
    lastRenderMs_ = renderMs;
  }
  lights_ = lights.diffuse.lights.size();
  shadowed_ = lights.shadowCasters.size();
}

std::string StatusLine::line() const {
  return fmt::format(
      "frame {} | {:.1f} frames/s | drawn {} ({:.1f} ms last) | lights {} | shadowed {}", frames_,
      fps_, drawn_, lastRenderMs_, lights_, shadowed_);
}

void StatusLine::maybePrint(const RenderPlan& plan) {
  const auto now = std::chrono::steady_clock::now();
  const double seconds = std::chrono::duration<double>(now - lastPrint_).count();
  if (seconds < 1.0) {
    return;
  }
  fps_ = double(framesSincePrint_) / seconds;
  framesSincePrint_ = 0;
  lastPrint_ = now;
  shown_ = line();
  fmt::print(stderr, "vemview: {} | {}\n", shown_, plan.describe());
}

std::string StatusLine::overlay(const RenderPlan& plan) const {
  return (shown_.empty() ? line() : shown_) + "\n" + plan.describe();
}

void StatusLine::printSummary(const RenderPlan& plan, const std::string& lastPicture) const {
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  fmt::print(stderr,
             "vemview: {} frames in {:.2f} s, {} drawn ({:.1f} ms mean), {} not redrawn (nothing "
             "changed); lights {}, shadowed {}; plan: {}\n",
             frames_, seconds, drawn_, drawn_ ? renderMsSum_ / double(drawn_) : 0.0,
             frames_ - drawn_, lights_, shadowed_, plan.describe());
  if (!lastPicture.empty()) {
    fmt::print(stderr, "vemview: last picture {}\n", lastPicture);
  }
}

}  // namespace vem::view
