// writeAccuracyPlot of render_report.h: one series per renderer and sweep, each point the
// geometric mean of the relative RMS error and the mean frame time over the sound maps. A few
// points per series carry a label (the legend names the rest); regions off is its renderer's
// colour dashed with hollow markers, so that it shows where it lies on regions on.
#include <algorithm>
#include <cstdlib>
#include <array>

#include <fmt/format.h>

#include "bench/render/render_report.h"
#include "util/svg_plot.h"

namespace vem::bench {
namespace {

struct PlottedSeries {
  const char* sweep;
  const char* series;
  const char* name;    // in the legend
  const char* prefix;  // of the point labels
  const char* suffix;
  std::array<const char*, 5> labelled;  // the points that get a label (fewer labels); null: none
  int colour;
  PlotMarker marker;
  bool dashed;  // regions off: the same colour dashed, hollow markers around the "on" markers
  std::pair<double, double> labelOffsetPx;
};

constexpr std::pair<double, double> kAbove{6.0, -8.0};
constexpr std::pair<double, double> kBelow{6.0, 16.0};
constexpr std::pair<double, double> kLeftBelow{-44.0, 16.0};

const PlottedSeries kPlotted[] = {
    {"a", "OpenGL", "OpenGL, N lights", "N=", "", {"4", "16", "64", "256", "1024"}, 0,
     PlotMarker::Circle, false, kAbove},
    {"d", "OpenGL, regions off", "OpenGL, N lights, regions off", "", "", {}, 0,
     PlotMarker::Circle, true, kAbove},
    {"a", "Embree", "Embree, N lights", "N=", "", {"4", "16", "64", "256", "1024"}, 1,
     PlotMarker::Square, false, kLeftBelow},
    {"d", "Embree, regions off", "Embree, N lights, regions off", "", "", {}, 1,
     PlotMarker::Square, true, kBelow},
    {"b", "OpenGL", "OpenGL, S = 0 ... 256 maps (N=256)", "S=", "", {"0", "256"}, 2,
     PlotMarker::Triangle, false, kBelow},
    {"c", "OpenGL", "OpenGL, maps of 64 ... 1024 px (N=256)", "", " px", {"64", "1024"}, 3,
     PlotMarker::Diamond, false, kAbove},
    {"e", "OpenGL, N = 1024", "OpenGL, Q clusters of N=1024", "Q=", "", {"8", "32", "128"}, 4,
     PlotMarker::Circle, false, kAbove},
    {"e", "Embree, N = 1024", "Embree, Q clusters of N=1024", "Q=", "", {"8", "32", "128"}, 5,
     PlotMarker::Square, false, kBelow},
};

std::vector<PlotSeries> plotSeries(const std::vector<Sweep>& sweeps,
                                   const std::vector<MapStudy>& studies) {
  std::vector<PlotSeries> out;
  for (const PlottedSeries& wanted : kPlotted) {
    for (const Sweep& sweep : sweeps) {
      if (sweep.id != wanted.sweep) continue;
      for (const SweepSeries& series : sweep.series) {
        if (series.name != wanted.series) continue;
        PlotSeries plotted{wanted.name, {}, {}, wanted.colour, wanted.marker, wanted.dashed,
                           wanted.labelOffsetPx};
        for (const SweepPoint& point : series.points) {
          plotted.points.emplace_back(meanTimeMs(studies, point.config),
                                      meanError(studies, point.config));
          const bool labelled = std::ranges::any_of(
              wanted.labelled, [&](const char* l) { return l != nullptr && point.label == l; });
          plotted.labels.push_back(
              labelled ? fmt::format("{}{}{}", wanted.prefix, point.label, wanted.suffix) : "");
        }
        out.push_back(std::move(plotted));
      }
    }
  }
  return out;
}

}  // namespace

std::expected<void, std::string> writeAccuracyPlot(const std::filesystem::path& pngPath,
                                                   const std::vector<Sweep>& sweeps,
                                                   const std::vector<MapStudy>& studies) {
  std::filesystem::path svgPath = pngPath;
  svgPath.replace_extension(".svg");
  if (!writeLogLogSvg(svgPath,
                      {"Render error against the Monte Carlo reference vs frame time (320 x 240)",
                       "median frame time (ms)",
                       "image error, relative RMS over the maps (geometric mean)", true},
                      plotSeries(sweeps, studies), PlotCanvas{960, 640})) {
    return std::unexpected(fmt::format("{}: could not write the plot.", svgPath.string()));
  }
  const std::string command = fmt::format("rsvg-convert --format=png --output='{}' '{}'",
                                          pngPath.string(), svgPath.string());
  if (std::system(command.c_str()) != 0) {
    return std::unexpected(fmt::format(
        "`{}` failed: is rsvg-convert installed (Debian package librsvg2-bin, cmake/deps.sh)?",
        command));
  }
  return {};
}

}  // namespace vem::bench
