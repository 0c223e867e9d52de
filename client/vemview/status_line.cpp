#include "client/vemview/status_line.h"

#include <cstdio>

#include <fmt/format.h>

namespace vem::view {
namespace {

void printToStderr(const std::string& line) { fmt::print(stderr, "vemview: {}\n", line); }

double secondsBetween(StatusLine::Clock::time_point from, StatusLine::Clock::time_point to) {
  return std::chrono::duration<double>(to - from).count();
}

}  // namespace

StatusLine::StatusLine(Clock::time_point start, Print print)
    : print_(print ? std::move(print) : Print(printToStderr)), start_(start), lastPrint_(start) {}

void StatusLine::showPlan(const RenderPlan& plan) {
  std::string text = plan.describe();
  if (text != plan_) {
    plan_ = std::move(text);
    print_("plan: " + plan_);
  }
}

void StatusLine::add(bool drawn, double renderMs, const LightCounts& counts) {
  counts_ = counts;
  if (!drawn) {
    ++notRedrawn_;
    return;
  }
  for (DrawnFrames* d : {&all_, &sinceLastLine_}) {
    ++d->count;
    d->renderMsSum += renderMs;
  }
}

void StatusLine::maybePrint(Clock::time_point now) {
  const double seconds = secondsBetween(lastPrint_, now);
  if (seconds < 1.0 || sinceLastLine_.count == 0) {
    return;
  }
  sinceLastLine_.seconds = seconds;
  shown_ = statusText(sinceLastLine_, counts_);
  print_(shown_);
  sinceLastLine_ = {};
  lastPrint_ = now;
}

std::string StatusLine::overlay() const {
  return (shown_.empty() ? statusText(sinceLastLine_, counts_) : shown_) + "\n" + plan_;
}

void StatusLine::printSummary(Clock::time_point now, const std::string& lastPicture) const {
  DrawnFrames all = all_;
  all.seconds = secondsBetween(start_, now);
  print_(summaryText(all, notRedrawn_, counts_));
  if (!lastPicture.empty()) {
    print_("last picture " + lastPicture);
  }
}

}  // namespace vem::view
