#include "util/svg_plot.h"

#include <algorithm>
#include <cmath>
#include <fstream>

#include <fmt/format.h>

namespace vem {
namespace {
constexpr double kLeft = 80, kRight = 40, kTop = 44, kBottom = 60;
constexpr double kLegendCharPx = 7.5;  // a little over the width of a 12 px sans-serif character
const char* const kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd",
                                "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};
constexpr std::size_t kColourCount = sizeof(kColours) / sizeof(kColours[0]);

// The 1, 2, 5 ticks of each decade from 10^lo to 10^hi.
std::vector<double> ticks(double lo, double hi) {
  std::vector<double> out;
  for (double e = lo; e <= hi; ++e) {
    for (const double m : {1.0, 2.0, 5.0}) {
      const double v = m * std::pow(10.0, e);
      if (std::log10(v) <= hi + 1e-9) out.push_back(v);
    }
  }
  return out;
}

std::string number(double v) {
  return v >= 1.0 ? fmt::format("{:.0f}", v) : fmt::format("{:g}", v);
}

std::string marker(PlotMarker kind, double x, double y, const char* colour, bool hollow) {
  const std::string paint = hollow ? fmt::format("fill='white' stroke='{}' stroke-width='1.5'", colour)
                                   : fmt::format("fill='{}'", colour);
  const double r = hollow ? 5.5 : 3.5;
  switch (kind) {
    case PlotMarker::Square:
      return fmt::format("<rect x='{:.1f}' y='{:.1f}' width='{:.1f}' height='{:.1f}' {}/>\n", x - r,
                         y - r, 2 * r, 2 * r, paint);
    case PlotMarker::Triangle:
      return fmt::format("<polygon points='{:.1f},{:.1f} {:.1f},{:.1f} {:.1f},{:.1f}' {}/>\n", x,
                         y - 1.2 * r, x - 1.1 * r, y + 0.8 * r, x + 1.1 * r, y + 0.8 * r, paint);
    case PlotMarker::Diamond:
      return fmt::format(
          "<polygon points='{:.1f},{:.1f} {:.1f},{:.1f} {:.1f},{:.1f} {:.1f},{:.1f}' {}/>\n", x,
          y - 1.3 * r, x + 1.3 * r, y, x, y + 1.3 * r, x - 1.3 * r, y, paint);
    case PlotMarker::Circle:
      break;
  }
  return fmt::format("<circle cx='{:.1f}' cy='{:.1f}' r='{:.1f}' {}/>\n", x, y, r, paint);
}

}  // namespace

bool writeLogLogSvg(const std::filesystem::path& path, const PlotText& text,
                    const std::vector<PlotSeries>& series, PlotCanvas canvas) {
  const double kWidth = canvas.widthPx, kHeight = canvas.heightPx;
  std::size_t longestName = 0;
  for (const auto& s : series) longestName = std::max(longestName, s.name.size());
  const double legendX = kWidth - kRight - kLegendCharPx * double(longestName) - 30;
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
  out << fmt::format("<text x='{}' y='22' text-anchor='middle' font-size='15' "
                     "font-weight='bold'>{}</text>\n",
                     (kLeft + kWidth - kRight) / 2, text.title);
  for (const double v : ticks(lx0, lx1)) {
    const bool decade = std::abs(std::log10(v) - std::round(std::log10(v))) < 1e-9;
    out << fmt::format(
        "<line x1='{0:.1f}' y1='{1}' x2='{0:.1f}' y2='{2}' stroke='{4}'/><text x='{0:.1f}' y='{3}' "
        "text-anchor='middle'>{5}</text>\n",
        px(v), kTop, kHeight - kBottom, kHeight - kBottom + 16, decade ? "#ccc" : "#eee",
        number(v));
  }
  for (const double v : ticks(ly0, ly1)) {
    const bool decade = std::abs(std::log10(v) - std::round(std::log10(v))) < 1e-9;
    out << fmt::format(
        "<line x1='{0}' y1='{1:.1f}' x2='{2}' y2='{1:.1f}' stroke='{5}'/><text x='{3}' y='{4:.1f}' "
        "text-anchor='end'>{6}</text>\n",
        kLeft, py(v), kWidth - kRight, kLeft - 6, py(v) + 4, decade ? "#ccc" : "#eee",
        text.yPercent ? number(100.0 * v) + " %" : number(v));
  }
  out << fmt::format("<text x='{}' y='{}' text-anchor='middle'>{}</text>\n",
                     (kLeft + kWidth - kRight) / 2, kHeight - 20, text.xLabel);
  out << fmt::format(
      "<text transform='translate(18,{}) rotate(-90)' text-anchor='middle'>{}</text>\n",
      (kTop + kHeight - kBottom) / 2, text.yLabel);
  std::string legend;
  for (std::size_t i = 0; i < series.size(); ++i) {
    const PlotSeries& s = series[i];
    std::string points;
    for (auto [x, y] : s.points) points += fmt::format("{:.1f},{:.1f} ", px(x), py(y));
    const char* colour =
        kColours[(s.colour >= 0 ? std::size_t(s.colour) : i) % kColourCount];
    out << fmt::format("<polyline points='{}' fill='none' stroke='{}' stroke-width='2'{}/>\n",
                       points, colour, s.dashed ? " stroke-dasharray='7,4'" : "");
    for (std::size_t k = 0; k < s.points.size(); ++k) {
      const auto [x, y] = s.points[k];
      out << marker(s.marker, px(x), py(y), colour, s.dashed);
      if (k < s.labels.size() && !s.labels[k].empty())
        out << fmt::format("<text x='{:.1f}' y='{:.1f}' fill='{}' font-size='11'>{}</text>\n",
                           px(x) + s.labelOffsetPx.first, py(y) + s.labelOffsetPx.second, colour,
                           s.labels[k]);
    }
    const double ly = kTop + 20 + 18 * double(i);
    legend += fmt::format(
        "<line x1='{:.1f}' y1='{:.1f}' x2='{:.1f}' y2='{:.1f}' stroke='{}' stroke-width='2'{}/>",
        legendX, ly - 4, legendX + 24, ly - 4, colour, s.dashed ? " stroke-dasharray='7,4'" : "");
    legend += marker(s.marker, legendX + 12, ly - 4, colour, s.dashed);
    legend += fmt::format("<text x='{:.1f}' y='{:.1f}' fill='{}'>{}</text>\n", legendX + 30, ly,
                          colour, s.name);
  }
  // The legend over a white box, so that lines under it do not cross its text.
  out << fmt::format(
      "<rect x='{:.1f}' y='{}' width='{:.1f}' height='{:.1f}' fill='white' stroke='#bbb'/>\n",
      legendX - 8, kTop + 4, kWidth - kRight - legendX + 6, 18 * double(series.size()) + 10);
  out << legend << "</svg>\n";
  out.close();
  return bool(out);
}

}  // namespace vem
