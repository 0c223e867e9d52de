// risesSection of render_report.h: every step of the light-count and shadow-count sweeps where an
// error grows, listed from the numbers, followed by what issue 17's investigation found for each
// (render_rise_notes.cpp).
#include <fmt/format.h>

#include "bench/render/render_report.h"

namespace vem::bench {
namespace {

// A rise smaller than this (a fraction, absolute) is not listed: half the reference's target error,
// below which the reference's noise can decide the order of two renders.
double listedRise(double referenceTarget) { return 0.5 * referenceTarget; }

std::string risesOf(const Sweep& sweep, const std::vector<MapStudy>& studies, double threshold) {
  std::string md;
  for (const SweepSeries& series : sweep.series) {
    for (std::size_t i = 1; i < series.points.size(); ++i) {
      const SweepPoint& before = series.points[i - 1];
      const SweepPoint& after = series.points[i];
      for (const MapStudy& s : studies) {
        const PointResult& a = s.at(before.config);
        const PointResult& b = s.at(after.config);
        const bool rms = b.relativeRms - a.relativeRms > threshold;
        const bool abs = b.meanAbsoluteRelative - a.meanAbsoluteRelative > threshold;
        if (!rms && !abs) continue;
        md += fmt::format("| {} | {} | {} {} -> {} | {} -> {} | {} -> {} |\n", columnName(s),
                          series.name, sweep.variable, before.label, after.label,
                          percent(a.relativeRms), percent(b.relativeRms),
                          percent(a.meanAbsoluteRelative), percent(b.meanAbsoluteRelative));
      }
    }
  }
  return md;
}

}  // namespace

std::string risesSection(const std::vector<Sweep>& sweeps, const std::vector<MapStudy>& studies,
                         double referenceTarget) {
  std::string rows;
  for (const Sweep& sweep : sweeps) {
    if (sweep.id == "a" || sweep.id == "b") {
      rows += risesOf(sweep, studies, listedRise(referenceTarget));
    }
  }
  std::string md = fmt::format(
      "## Where the error rises as N or S rises\n\n"
      "Every step of sweeps a (N) and b (S) where the relative RMS or the mean absolute error "
      "grows by more than {} (half the reference's target error; smaller changes can be the "
      "reference's noise):\n\n",
      percent(listedRise(referenceTarget)));
  if (rows.empty()) {
    md += "None.\n\n";
  } else {
    md += "| map | renderer | step | RMS | abs |\n|---|---|---|---:|---:|\n" + rows + "\n";
  }
  return md + riseNotes() + "\n";
}

}  // namespace vem::bench
