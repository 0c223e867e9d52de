// A small log-log line plot written as SVG (no plotting library in Debian's C++ packages fits a
// benchmark report better than a few lines of SVG).
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace vem::bench {

struct PlotSeries {
  std::string name;
  std::vector<std::pair<double, double>> points;  // (x, y), both > 0
  std::vector<std::string> labels;                // optional, one per point (e.g. "N=64")
};

// The canvas in SVG pixels; the legend sits in the top right corner.
struct PlotCanvas {
  double widthPx = 640;
  double heightPx = 420;
};

// Up to 8 series get distinct colours (then they repeat).
void writeLogLogSvg(const std::filesystem::path& path, const std::string& xLabel,
                    const std::string& yLabel, const std::vector<PlotSeries>& series,
                    PlotCanvas canvas = {});

}  // namespace vem::bench
