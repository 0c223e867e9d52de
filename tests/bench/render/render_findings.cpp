// The generated sentences of render_report.h (studyFindings) and the BENCHMARKS.md section.
#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "bench/render/render_report.h"

namespace vem::bench {
namespace {

const SweepSeries* findSeries(const std::vector<Sweep>& sweeps, const std::string& id,
                              const std::string& name) {
  for (const Sweep& sweep : sweeps) {
    if (sweep.id != id) continue;
    for (const SweepSeries& series : sweep.series) {
      if (series.name == name) return &series;
    }
  }
  return nullptr;
}

std::optional<StudyConfig> configAt(const std::vector<Sweep>& sweeps, const std::string& id,
                                    const std::string& series, const std::string& label) {
  const SweepSeries* s = findSeries(sweeps, id, series);
  if (s == nullptr) return std::nullopt;
  for (const SweepPoint& point : s->points) {
    if (point.label == label) return point.config;
  }
  return std::nullopt;
}

std::string lightCountSentence(const std::vector<Sweep>& sweeps,
                               const std::vector<MapStudy>& studies) {
  std::string out;
  for (const char* renderer : {"OpenGL", "Embree"}) {
    const SweepSeries* s = findSeries(sweeps, "a", renderer);
    if (s == nullptr) continue;
    const StudyConfig& first = s->points.front().config;
    const StudyConfig& last = s->points.back().config;
    out += fmt::format(
        "{}{} goes from {} relative RMS error at N = {} to {} at N = {} while its frame time "
        "goes from {} to {} ms",
        out.empty() ? fmt::format("Over the maps ({}; geometric mean of the error, mean time), ",
                                  meanedMaps(studies))
                    : "; ",
        renderer,
        percent(meanError(studies, first)), s->points.front().label,
        percent(meanError(studies, last)), s->points.back().label,
        milliseconds(meanTimeMs(studies, first)), milliseconds(meanTimeMs(studies, last)));
  }
  return out + ".";
}

std::string gapSentence(const std::vector<Sweep>& sweeps, const std::vector<MapStudy>& studies) {
  const SweepSeries* gl = findSeries(sweeps, "a", "OpenGL");
  const SweepSeries* embree = findSeries(sweeps, "a", "Embree");
  if (gl == nullptr || embree == nullptr) return "";
  const auto best = std::ranges::min_element(
      gl->points, {}, [&](const SweepPoint& p) { return meanError(studies, p.config); });
  const StudyConfig& last = gl->points.back().config;
  const double ratio =
      meanError(studies, last) / std::max(meanError(studies, embree->points.back().config), 1e-12);
  return fmt::format(
      " OpenGL's error is smallest at N = {} ({}, {} ms); at N = {} it is {:.1f} times Embree's, "
      "the part the shadow maps add: {} of the {} lights have a map of their own, the others take "
      "the map of the nearest caster.",
      best->label, percent(meanError(studies, best->config)),
      milliseconds(meanTimeMs(studies, best->config)), gl->points.back().label, ratio,
      last.lighting.shadowedCount, last.lighting.lightCount);
}

std::string shadowSentence(const std::vector<Sweep>& sweeps, const std::vector<MapStudy>& studies) {
  const auto s0 = configAt(sweeps, "b", "OpenGL", "0");
  const auto s4 = configAt(sweeps, "b", "OpenGL", "4");
  const auto s64 = configAt(sweeps, "b", "OpenGL", "64");
  const auto s256 = configAt(sweeps, "b", "OpenGL", "256");
  const auto px64 = configAt(sweeps, "c", "OpenGL", "64");
  const auto px1024 = configAt(sweeps, "c", "OpenGL", "1024");
  if (!s0 || !s4 || !s64 || !s256 || !px64 || !px1024) return "";
  const double e0 = meanError(studies, *s0);
  const double e4 = meanError(studies, *s4);
  return fmt::format(
      " At N = 256, OpenGL has {} error without shadows, {} with S = 4 maps, {} with 64 and {} "
      "with 256 (a map per light, {} ms more than none){}; from 64 to 1024 px maps the error goes "
      "from {} to {}.",
      percent(e0), percent(e4), percent(meanError(studies, *s64)),
      percent(meanError(studies, *s256)),
      milliseconds(meanTimeMs(studies, *s256) - meanTimeMs(studies, *s0)),
      e4 > e0 ? ": the lights that take the nearest caster's map are shaded worse than with no "
                "shadow at all"
              : "",
      percent(meanError(studies, *px64)), percent(meanError(studies, *px1024)));
}

// The time ratio of regions on to off over the sweep: its extremes and where, and the largest
// change of the error they cause.
struct RegionEffect {
  std::pair<double, std::string> fastest;  // (ratio, N)
  std::pair<double, std::string> slowest;
  double errorChange = 0.0;
};

std::optional<RegionEffect> regionEffect(const std::vector<Sweep>& sweeps,
                                         const std::vector<MapStudy>& studies,
                                         const std::string& renderer) {
  const SweepSeries* on = findSeries(sweeps, "d", renderer + ", regions on");
  const SweepSeries* off = findSeries(sweeps, "d", renderer + ", regions off");
  if (on == nullptr || off == nullptr || on->points.size() != off->points.size()) {
    return std::nullopt;
  }
  std::vector<std::pair<double, std::string>> ratios;
  RegionEffect out;
  for (std::size_t i = 0; i < on->points.size(); ++i) {
    const StudyConfig& with = on->points[i].config;
    const StudyConfig& without = off->points[i].config;
    out.errorChange =
        std::max(out.errorChange, std::abs(meanError(studies, with) - meanError(studies, without)));
    ratios.emplace_back(meanTimeMs(studies, with) / meanTimeMs(studies, without),
                        on->points[i].label);
  }
  const auto [low, high] = std::ranges::minmax_element(ratios);
  out.fastest = *low;
  out.slowest = *high;
  return out;
}

std::string clusterPart(const std::vector<Sweep>& sweeps, const std::vector<MapStudy>& studies,
                        const std::string& renderer) {
  const auto q72 = configAt(sweeps, "e", renderer + ", N = 1024", "72");
  const auto q128 = configAt(sweeps, "e", renderer + ", N = 1024", "128");
  const auto off = configAt(sweeps, "e", renderer + ", N = 1024", "off");
  if (!q72 || !q128 || !off) return "";
  return fmt::format("{} from {} ms and {} error to {} ms and {} (Q = 72: {} ms, {})", renderer,
                     milliseconds(meanTimeMs(studies, *off)), percent(meanError(studies, *off)),
                     milliseconds(meanTimeMs(studies, *q128)), percent(meanError(studies, *q128)),
                     milliseconds(meanTimeMs(studies, *q72)), percent(meanError(studies, *q72)));
}

std::string regionClusterSentence(const std::vector<Sweep>& sweeps,
                                  const std::vector<MapStudy>& studies) {
  std::vector<std::string> ratios;
  std::vector<std::string> clusters;
  double errorChange = 0.0;
  for (const std::string renderer : {"OpenGL", "Embree"}) {
    if (const auto r = regionEffect(sweeps, studies, renderer)) {
      ratios.push_back(fmt::format("{:.2f} (N = {}) to {:.2f} (N = {}) for {}", r->fastest.first,
                                   r->fastest.second, r->slowest.first, r->slowest.second,
                                   renderer));
      errorChange = std::max(errorChange, r->errorChange);
    }
    if (auto c = clusterPart(sweeps, studies, renderer); !c.empty()) clusters.push_back(c);
  }
  std::string out;
  if (!ratios.empty()) {
    out += fmt::format(
        " Over N = 16 ... 1024, angular regions multiply the frame time by {} (below 1 they save "
        "time) and change the error by at most {}",
        fmt::join(ratios, " and by "), percent(errorChange));
  }
  if (!clusters.empty()) {
    out += fmt::format("{}clustering the 1024 lights to Q = 128 takes {}", out.empty() ? " " : "; ",
                       fmt::join(clusters, " and "));
  }
  return out.empty() ? out : out + ".";
}

std::string hardestMapSentence(const std::vector<Sweep>& sweeps,
                               const std::vector<MapStudy>& studies) {
  const SweepSeries* s = findSeries(sweeps, "a", "OpenGL");
  if (s == nullptr) s = findSeries(sweeps, "a", "Embree");
  if (s == nullptr || studies.size() < 2) return "";
  const auto base = configAt(sweeps, "a", s->name, "256");
  if (!base) return "";
  const auto byError = [&](const MapStudy& a, const MapStudy& b) {
    return a.at(*base).relativeRms < b.at(*base).relativeRms;
  };
  const MapStudy& hardest = *std::ranges::max_element(studies, byError);
  const MapStudy& easiest = *std::ranges::min_element(studies, byError);
  const MapStudy& peakiest = *std::ranges::max_element(studies, {}, &MapStudy::topShareOfPower);
  return fmt::format(
      " The hardest map at N = 256 ({}) is {} ({} error against {} on {}){}.", s->name, hardest.map,
      percent(hardest.at(*base).relativeRms), percent(easiest.at(*base).relativeRms), easiest.map,
      &hardest == &peakiest
          ? fmt::format(", the one with the largest share of its power in its brightest 0.1 % ({})",
                        percent(hardest.topShareOfPower))
          : "");
}

}  // namespace

std::string studyFindings(const std::vector<Sweep>& sweeps, const std::vector<MapStudy>& studies) {
  if (studies.empty()) return "No map was studied.";
  return lightCountSentence(sweeps, studies) + gapSentence(sweeps, studies) +
         shadowSentence(sweeps, studies) + regionClusterSentence(sweeps, studies) +
         hardestMapSentence(sweeps, studies);
}

std::string benchmarkSection(const StudyContext& context, const std::vector<Sweep>& sweeps,
                             const std::vector<MapStudy>& studies, const std::string& tableName,
                             const std::string& plotName) {
  std::string md = fmt::format(
      "## Rendering: accuracy against time (vem_render_bench)\n\n"
      "`cmake --build build --target render-bench`: the default scene at {} x {} under {} real "
      "HDRIs, error against the Embree Monte Carlo reference (relative RMS of the image, "
      "geometric mean over the maps: {}) and median frame time (mean over the same maps), "
      "S = min(N, 64) shadow maps of 256 px, regions on. OpenGL: {}. Every sweep (shadowed "
      "lights, map resolution, regions, clustering), the maps one by one (the damaged one too) "
      "and the plot: [{}]({}).\n\n| N |",
      context.widthPx, context.heightPx, studies.size(), meanedMaps(studies),
      glDescription(context), tableName, tableName);
  const auto found = std::ranges::find(sweeps, std::string("a"), &Sweep::id);
  if (found == sweeps.end()) return md + "(The light-count sweep was not run.)\n\n";
  const Sweep& a = *found;
  std::string rule = "|---:|";
  for (const SweepSeries& series : a.series) {
    md += fmt::format(" {0} ms | {0} error |", series.name);
    rule += "---:|---:|";
  }
  md += fmt::format("\n{}\n", rule);
  for (std::size_t i = 0; i < a.series.front().points.size(); i += 2) {
    md += fmt::format("| {} |", a.series.front().points[i].label);
    for (const SweepSeries& series : a.series) {
      const StudyConfig& config = series.points[i].config;
      md += fmt::format(" {} | {} |", milliseconds(meanTimeMs(studies, config)),
                        percent(meanError(studies, config)));
    }
    md += "\n";
  }
  md +=
      fmt::format("\n{}{}\n\n", lightCountSentence(sweeps, studies), gapSentence(sweeps, studies));
  if (!plotName.empty()) {
    md += fmt::format("![render error against frame time]({})\n\n{}\n\n", plotName,
                      plotCaption(studies));
  }
  return md;
}

}  // namespace vem::bench
