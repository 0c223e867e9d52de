// StatusLine: what vemview tells the user while it runs, on stderr (and as the window's overlay):
// the plan once, at start and whenever it changes; then once a second, when frames were drawn,
// a short line (status_text.h: the frames drawn since the last line and their rate, the light
// counts); a summary at the end. Times come from the caller, so tests can drive it.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <string>

#include "client/vemview/render_plan.h"
#include "client/vemview/status_text.h"

namespace vem::view {

class StatusLine {
 public:
  using Clock = std::chrono::steady_clock;
  using Print = std::function<void(const std::string& line)>;  // one line, without newline

  // start: when the frame loop begins; print: where lines go ("vemview: " + line on stderr).
  explicit StatusLine(Clock::time_point start, Print print = {});

  void showPlan(const RenderPlan& plan);  // prints "plan: ..." when it differs from the last one
  void add(bool drawn, double renderMs, const LightCounts& counts);
  void maybePrint(Clock::time_point now);  // at most once a second, and only after drawn frames
  // The window's overlay: the line as last printed (it changes at most once a second, so the
  // overlay is redrawn at most once a second), then the plan.
  [[nodiscard]] std::string overlay() const;
  void printSummary(Clock::time_point now, const std::string& lastPicture) const;

 private:
  Print print_;
  Clock::time_point start_;
  Clock::time_point lastPrint_;
  DrawnFrames all_;
  DrawnFrames sinceLastLine_;
  std::uint64_t notRedrawn_ = 0;
  LightCounts counts_;
  std::string plan_;
  std::string shown_;
};

}  // namespace vem::view
