#include "svg_plot.h"

#include <algorithm>
#include <cmath>
#include <fstream>

#include <fmt/format.h>

namespace vem::bench {
namespace {
constexpr double kLeft = 80, kRight = 20, kTop = 20, kBottom = 60;
constexpr double kLegendCharPx = 7;  // about the width of a 12 px sans-serif character
const char* const kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd",
                                "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};
constexpr std::size_t kColourCount = sizeof(kColours) / sizeof(kColours[0]);
}  // namespace

void writeLogLogSvg(const std::filesystem::path& path, const std::string& xLabel,
                    const std::string& yLabel, const std::vector<PlotSeries>& series,
                    PlotCanvas canvas) {
  const double kWidth = canvas.widthPx, kHeight = canvas.heightPx;
  std::size_t longestName = 0;
  for (const auto& s : series) longestName = std::max(longestName, s.name.size());
  const double legendX = kWidth - kRight - kLegendCharPx * double(longestName);
  double x0 = 1e300, x1 = 0, y0 = 1e300, y1 = 0;
  for (const auto& s : series)
    for (auto [x, y] : s.points) {
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
  // The right edge leaves room for the last point's label.
  const double lx0 = std::floor(std::log10(x0)), lx1 = std::ceil(std::log10(x1) + 0.1);
  const double ly0 = std::floor(std::log10(y0)), ly1 = std::ceil(std::log10(y1));
  const auto px = [&](double x) {
    return kLeft + (std::log10(x) - lx0) / (lx1 - lx0) * (kWidth - kLeft - kRight);
  };
  const auto py = [&](double y) {
    return kHeight - kBottom - (std::log10(y) - ly0) / (ly1 - ly0) * (kHeight - kTop - kBottom);
  };
  std::ofstream out(path);
  out << fmt::format(
      "<svg xmlns='http://www.w3.org/2000/svg' width='{}' height='{}' font-family='sans-serif' "
      "font-size='12'>\n",
      kWidth, kHeight);
  out << "<rect width='100%' height='100%' fill='white'/>\n";
  for (double e = lx0; e <= lx1; ++e)
    out << fmt::format(
        "<line x1='{0}' y1='{1}' x2='{0}' y2='{2}' stroke='#ddd'/><text x='{0}' y='{3}' "
        "text-anchor='middle'>1e{4}</text>\n",
        px(std::pow(10, e)), kTop, kHeight - kBottom, kHeight - kBottom + 16, int(e));
  for (double e = ly0; e <= ly1; ++e)
    out << fmt::format(
        "<line x1='{0}' y1='{1}' x2='{2}' y2='{1}' stroke='#ddd'/><text x='{3}' y='{4}' "
        "text-anchor='end'>1e{5}</text>\n",
        kLeft, py(std::pow(10, e)), kWidth - kRight, kLeft - 6, py(std::pow(10, e)) + 4, int(e));
  out << fmt::format("<text x='{}' y='{}' text-anchor='middle'>{}</text>\n",
                     (kLeft + kWidth - kRight) / 2, kHeight - 20, xLabel);
  out << fmt::format(
      "<text transform='translate(18,{}) rotate(-90)' text-anchor='middle'>{}</text>\n",
      (kTop + kHeight - kBottom) / 2, yLabel);
  for (std::size_t i = 0; i < series.size(); ++i) {
    std::string points;
    for (auto [x, y] : series[i].points) points += fmt::format("{:.1f},{:.1f} ", px(x), py(y));
    const char* colour = kColours[i % kColourCount];
    out << fmt::format("<polyline points='{}' fill='none' stroke='{}' stroke-width='2'/>\n", points,
                       colour);
    for (std::size_t k = 0; k < series[i].points.size(); ++k) {
      const auto [x, y] = series[i].points[k];
      out << fmt::format("<circle cx='{:.1f}' cy='{:.1f}' r='3' fill='{}'/>\n", px(x), py(y),
                         colour);
      if (k < series[i].labels.size())
        out << fmt::format("<text x='{:.1f}' y='{:.1f}' fill='{}' font-size='10'>{}</text>\n",
                           px(x) + 6, py(y) + (i == 0 ? -6 : 14), colour, series[i].labels[k]);
    }
    out << fmt::format("<text x='{}' y='{}' fill='{}'>{}</text>\n", legendX,
                       kTop + 16 + 16 * double(i), colour, series[i].name);
  }
  out << "</svg>\n";
}

}  // namespace vem::bench
