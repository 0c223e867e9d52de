#include "calibration_compare.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <variant>

#include <fmt/format.h>
#include <fmt/ostream.h>
#include <glm/geometric.hpp>

namespace vem::calibtool {
namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;
constexpr int kThetaSteps = 48;  // directions: theta from 0 to the edge ...
constexpr int kPsiSteps = 72;    // ... times psi round the axis
constexpr int kPixelGrid = 96;   // pixels: a kPixelGrid^2 grid over the image circle's square
constexpr double kExposureUs = 1000.0;

// Accumulates max and RMS of a difference.
struct Spread {
  double max = 0.0;
  double sumSq = 0.0;
  int count = 0;
  void add(double d) {
    max = std::max(max, std::abs(d));
    sumSq += d * d;
    ++count;
  }
  [[nodiscard]] double rms() const { return count > 0 ? std::sqrt(sumSq / count) : 0.0; }
};

void row(std::ostream& out, const std::string& name, const std::string& fitted,
         const std::string& truth, const std::string& difference) {
  fmt::print(out, "  {:<28} {:>14} {:>14} {:>14}\n", name, fitted, truth, difference);
}

void numberRow(std::ostream& out, const std::string& name, double fitted, double truth,
               const char* unit, int decimals) {
  row(out, name, fmt::format("{:.{}f}{}", fitted, decimals, unit),
      fmt::format("{:.{}f}{}", truth, decimals, unit),
      fmt::format("{:+.{}f}{}", fitted - truth, decimals, unit));
}

const char* channelName(int channel, int channels) {
  if (channels == 1) return "mono";
  return channel == 0 ? "R" : channel == 1 ? "G" : "B";
}

void printResponseParameters(std::ostream& out, const calib::PhotometricCalibration& fitted,
                             const calib::PhotometricCalibration& truth, int channels) {
  numberRow(out, "black level", fitted.blackLevelCode, truth.blackLevelCode, "", 1);
  numberRow(out, "saturation", fitted.saturationCode, truth.saturationCode, "", 1);
  const auto* fitLog = std::get_if<calib::LogResponse>(&fitted.response);
  const auto* truthLog = std::get_if<calib::LogResponse>(&truth.response);
  const auto* fitLinear = std::get_if<calib::LinearResponse>(&fitted.response);
  const auto* truthLinear = std::get_if<calib::LinearResponse>(&truth.response);
  for (int c = 0; c < channels; ++c) {
    const std::string ch = channelName(c, channels);
    if (fitLog && truthLog) {
      numberRow(out, ch + " a (code at 1 cd/m2)", fitLog->aCode[c], truthLog->aCode[c], "", 2);
      numberRow(out, ch + " b (codes per ln)", fitLog->bCodePerLn[c], truthLog->bCodePerLn[c], "",
                3);
    } else if (fitLinear && truthLinear) {
      row(out, ch + " gain (code/(cd/m2 us))",
          fmt::format("{:.5g}", fitLinear->gainCodePerCdM2Us[c]),
          fmt::format("{:.5g}", truthLinear->gainCodePerCdM2Us[c]),
          fmt::format("{:+.3f} %", 100.0 * (fitLinear->gainCodePerCdM2Us[c] /
                                                 truthLinear->gainCodePerCdM2Us[c] -
                                             1.0)));
    }
  }
}

void printLensParameters(std::ostream& out, const calib::KannalaBrandtLens& fitted,
                         const calib::KannalaBrandtLens& truth) {
  numberRow(out, "principal point x", fitted.principalPointPx.x, truth.principalPointPx.x, " px",
            3);
  numberRow(out, "principal point y", fitted.principalPointPx.y, truth.principalPointPx.y, " px",
            3);
  numberRow(out, "aspect", fitted.aspect, truth.aspect, "", 5);
  for (std::size_t i = 0; i < fitted.kPx.size(); ++i) {
    row(out, fmt::format("k{}", i + 1), fmt::format("{:.5g}", fitted.kPx[i]),
        fmt::format("{:.5g}", truth.kPx[i]), fmt::format("{:+.3g}", fitted.kPx[i] - truth.kPx[i]));
  }
  numberRow(out, "field of view", 2.0 * fitted.maxThetaRad * kDegPerRad,
            2.0 * truth.maxThetaRad * kDegPerRad, " deg", 2);
}

}  // namespace

LensDifference compareLenses(const calib::KannalaBrandtLens& fitted,
                             const calib::KannalaBrandtLens& truth) {
  LensDifference d;
  const double edge = std::min(fitted.maxThetaRad, truth.maxThetaRad);
  Spread px;
  for (int i = 0; i <= kThetaSteps; ++i) {
    const double theta = edge * i / kThetaSteps;
    for (int j = 0; j < (i == 0 ? 1 : kPsiSteps); ++j) {
      const double psi = 2.0 * std::numbers::pi * j / kPsiSteps;
      const glm::dvec3 dir(std::sin(theta) * std::cos(psi), std::sin(theta) * std::sin(psi),
                           std::cos(theta));
      const auto a = fitted.sensorFromCamera(dir);
      const auto b = truth.sensorFromCamera(dir);
      if (a && b) px.add(glm::length(*a - *b));
    }
  }
  // Pixels inside both image circles (each lens's circle: r(maxTheta) about its principal point).
  const double radius = std::min(fitted.radiusPx(fitted.maxThetaRad), truth.radiusPx(truth.maxThetaRad));
  Spread deg;
  for (int i = 0; i < kPixelGrid; ++i) {
    for (int j = 0; j < kPixelGrid; ++j) {
      const glm::dvec2 offset(radius * (2.0 * (i + 0.5) / kPixelGrid - 1.0),
                              radius * (2.0 * (j + 0.5) / kPixelGrid - 1.0));
      const glm::dvec2 pixel = truth.principalPointPx + offset;
      const auto a = fitted.cameraFromSensor(pixel);
      const auto b = truth.cameraFromSensor(pixel);
      if (!a || !b) continue;
      deg.add(std::acos(std::clamp(glm::dot(*a, *b), -1.0, 1.0)) * kDegPerRad);
    }
  }
  d.maxPx = px.max;
  d.rmsPx = px.rms();
  d.directions = px.count;
  d.maxDeg = deg.max;
  d.rmsDeg = deg.rms();
  d.pixels = deg.count;
  return d;
}

ResponseDifference compareResponses(const calib::PhotometricCalibration& fitted,
                                    const calib::PhotometricCalibration& truth,
                                    PixelFormat format) {
  ResponseDifference d;
  d.firstCode = int(std::floor(std::max(fitted.blackLevelCode, truth.blackLevelCode))) + 1;
  d.lastCode = int(std::ceil(std::min(fitted.saturationCode, truth.saturationCode))) - 1;
  d.channels = format.channels;
  Spread percent;
  for (int c = 0; c < format.channels; ++c) {
    for (int code = d.firstCode; code <= d.lastCode; ++code) {
      const double lf = calib::luminanceFromCode(fitted, c, code, kExposureUs, 1.0);
      const double lt = calib::luminanceFromCode(truth, c, code, kExposureUs, 1.0);
      if (lt > 0.0 && std::isfinite(lf) && std::isfinite(lt)) percent.add(100.0 * (lf - lt) / lt);
    }
  }
  d.maxPercent = percent.max;
  d.rmsPercent = percent.rms();
  return d;
}

void printComparison(std::ostream& out, const calib::CameraCalibration& fitted,
                     const std::string& fittedPath, const calib::CameraCalibration& truth,
                     const std::string& truthPath) {
  fmt::print(out, "{} compared with {} (the truth)\n", fittedPath, truthPath);
  row(out, "value", "fitted", "truth", "difference");
  const int channels = fitted.camera.pixelFormat.channels;
  if (fitted.photometric && truth.photometric) {
    fmt::print(out, "photometric: {} response, truth {}\n",
               calib::responseModelName(fitted.photometric->response),
               calib::responseModelName(truth.photometric->response));
    printResponseParameters(out, *fitted.photometric, *truth.photometric, channels);
    const ResponseDifference r =
        compareResponses(*fitted.photometric, *truth.photometric, fitted.camera.pixelFormat);
    row(out, "luminance, max", "", "", fmt::format("{:.3f} %", r.maxPercent));
    row(out, "luminance, rms", "", "", fmt::format("{:.3f} %", r.rmsPercent));
    fmt::print(out, "  (luminance read from codes {} to {}, every channel, at 1000 us, gain 1)\n",
               r.firstCode, r.lastCode);
  } else {
    fmt::print(out, "photometric: {}\n", fitted.photometric ? "the truth has none"
                                                            : "the fitted file has none");
  }
  if (fitted.lens && truth.lens) {
    fmt::print(out, "geometric: Kannala-Brandt lens\n");
    printLensParameters(out, *fitted.lens, *truth.lens);
    const LensDifference l = compareLenses(*fitted.lens, *truth.lens);
    row(out, "projection, max", "", "", fmt::format("{:.3f} px", l.maxPx));
    row(out, "projection, rms", "", "", fmt::format("{:.3f} px", l.rmsPx));
    row(out, "direction, max", "", "", fmt::format("{:.4f} deg", l.maxDeg));
    row(out, "direction, rms", "", "", fmt::format("{:.4f} deg", l.rmsDeg));
    fmt::print(out,
               "  (projection: {} directions from the axis to the field of view's edge through both "
               "lenses;\n   direction: {} pixels of the image circle read through both)\n",
               l.directions, l.pixels);
  } else {
    fmt::print(out, "geometric: {}\n", fitted.lens ? "the truth has none" : "the fitted file has none");
  }
}

}  // namespace vem::calibtool
