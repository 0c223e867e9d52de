// writeAccuracyPlot of render_report.h: one series per renderer and sweep, each point the
// geometric mean of the relative RMS error and the mean frame time over the maps.
#include <cstdlib>

#include <fmt/format.h>

#include "bench/render/render_report.h"
#include "bench/svg_plot.h"

namespace vem::bench {
namespace {

struct PlottedSeries {
  const char* sweep;
  const char* series;
  const char* name;    // in the legend
  const char* prefix;  // of the point labels
  const char* suffix;
};

constexpr PlottedSeries kPlotted[] = {
    {"a", "OpenGL", "OpenGL, N lights", "N=", ""},
    {"a", "Embree", "Embree, N lights", "N=", ""},
    {"d", "OpenGL, regions off", "OpenGL, N, regions off", "N=", ""},
    {"d", "Embree, regions off", "Embree, N, regions off", "N=", ""},
    {"b", "OpenGL", "OpenGL, S maps (N=256)", "S=", ""},
    {"c", "OpenGL", "OpenGL, map px (N=256)", "", "px"},
    {"e", "OpenGL, N = 1024", "OpenGL, clusters (N=1024)", "Q=", ""},
    {"e", "Embree, N = 1024", "Embree, clusters (N=1024)", "Q=", ""},
};

std::vector<PlotSeries> plotSeries(const std::vector<Sweep>& sweeps,
                                   const std::vector<MapStudy>& studies) {
  std::vector<PlotSeries> out;
  for (const PlottedSeries& wanted : kPlotted) {
    for (const Sweep& sweep : sweeps) {
      if (sweep.id != wanted.sweep) continue;
      for (const SweepSeries& series : sweep.series) {
        if (series.name != wanted.series) continue;
        PlotSeries plotted{wanted.name, {}, {}};
        for (const SweepPoint& point : series.points) {
          plotted.points.emplace_back(meanTimeMs(studies, point.config),
                                      meanError(studies, point.config));
          plotted.labels.push_back(
              fmt::format("{}{}{}", wanted.prefix, point.label, wanted.suffix));
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
  writeLogLogSvg(svgPath, "median frame time (ms)", "relative RMS error against the reference",
                 plotSeries(sweeps, studies), PlotCanvas{900, 600});
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
