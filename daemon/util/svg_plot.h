// A small log-log line plot written as SVG, for the benchmark reports and `vemtool coherence` (no
// plotting library in Debian's C++ packages fits a report better than a few lines of SVG). A title
// names what is plotted; ticks are plain numbers on a 1-2-5 scale (per cent on a per-cent axis),
// not powers of ten.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace vem {

enum class PlotMarker { Circle, Square, Triangle, Diamond };

struct PlotSeries {
  std::string name;
  std::vector<std::pair<double, double>> points;  // (x, y), both > 0
  // Optional, one per point (e.g. "N=64"); an empty label draws none, so a crowded series can
  // label only a few points.
  std::vector<std::string> labels;
  int colour = -1;                      // index into the palette; -1: the series' index
  PlotMarker marker = PlotMarker::Circle;
  bool dashed = false;                  // dashed line and hollow, larger markers: a series that
                                        // may lie on another stays visible around it
  std::pair<double, double> labelOffsetPx{6.0, -6.0};  // from the point to the label's start
};

// The canvas in SVG pixels; the legend sits in the top right corner.
struct PlotCanvas {
  double widthPx = 640;
  double heightPx = 420;
};

struct PlotText {
  std::string title;   // above the plot: what is plotted against what, naming the error
  std::string xLabel;  // with its unit
  std::string yLabel;
  bool yPercent = false;  // y values are fractions, shown as per cent ("5 %")
};

// Up to 8 colours (then they repeat). False when the file could not be written.
[[nodiscard]] bool writeLogLogSvg(const std::filesystem::path& path, const PlotText& text,
                    const std::vector<PlotSeries>& series, PlotCanvas canvas = {});

}  // namespace vem
