#include "calib/core/photometric_fit.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <fmt/format.h>

namespace vem::calib {
namespace {

std::unexpected<PhotometricFitFailure> refuse(PhotometricRefusal cause, std::string message,
                                              std::vector<PatchResult> patches = {}) {
  return std::unexpected(PhotometricFitFailure{cause, std::move(message), std::move(patches)});
}

// Least-squares line y = a + b x.
struct Line {
  double a = 0.0;
  double b = 0.0;
};

Line fitLine(std::span<const double> x, std::span<const double> y) {
  const double n = double(x.size());
  const double mx = std::accumulate(x.begin(), x.end(), 0.0) / n;
  const double my = std::accumulate(y.begin(), y.end(), 0.0) / n;
  double sxy = 0.0, sxx = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
  }
  const double b = sxy / sxx;
  return {my - b * mx, b};
}

// Least-squares gain through the black level: y - black = g x.
double fitGain(std::span<const double> x, std::span<const double> y, double black) {
  double sxy = 0.0, sxx = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxy += x[i] * (y[i] - black);
    sxx += x[i] * x[i];
  }
  return sxy / sxx;
}

std::optional<PhotometricFitFailure> checkUsable(std::span<const PatchMeasurement> patches,
                                                 const PhotometricFitOptions& options) {
  for (const PatchMeasurement& p : patches) {
    if (p.clippedFraction > options.maxClippedFraction) {
      return PhotometricFitFailure{
          PhotometricRefusal::PatchClipped,
          fmt::format("patch '{}' is saturated: {:.1f}% of its samples are at or above the "
                      "saturation code {:g} (at most {:g}% allowed); lower the exposure or drop it",
                      p.spec.name, 100.0 * p.clippedFraction, options.saturationCode,
                      100.0 * options.maxClippedFraction),
          {}};
    }
    if (p.underBlackFraction > options.maxClippedFraction) {
      return PhotometricFitFailure{
          PhotometricRefusal::PatchClipped,
          fmt::format("patch '{}' is under the black level: {:.1f}% of its samples are at or "
                      "below code {:g} (at most {:g}% allowed); light it more or drop it",
                      p.spec.name, 100.0 * p.underBlackFraction, options.blackLevelCode,
                      100.0 * options.maxClippedFraction),
          {}};
    }
  }
  return std::nullopt;
}

// Codes must increase with luminance in every channel (patches of equal luminance excepted).
std::optional<PhotometricFitFailure> checkIncreasing(std::span<const PatchMeasurement> patches) {
  std::vector<const PatchMeasurement*> sorted;
  for (const PatchMeasurement& p : patches) sorted.push_back(&p);
  std::ranges::sort(sorted, {}, [](const PatchMeasurement* p) { return p->spec.luminanceCdM2; });
  for (std::size_t i = 1; i < sorted.size(); ++i) {
    const PatchMeasurement& lo = *sorted[i - 1];
    const PatchMeasurement& hi = *sorted[i];
    if (hi.spec.luminanceCdM2 == lo.spec.luminanceCdM2) continue;
    for (int c = 0; c < hi.channels; ++c) {
      const auto ch = std::size_t(c);
      if (!(hi.meanCode[ch] > lo.meanCode[ch])) {
        return PhotometricFitFailure{
            PhotometricRefusal::NotIncreasing,
            fmt::format("codes do not increase with luminance: patch '{}' ({:g} cd/m2) reads "
                        "{:.1f} in channel {} but the darker patch '{}' ({:g} cd/m2) reads {:.1f}; "
                        "check the patch regions and luminances",
                        hi.spec.name, hi.spec.luminanceCdM2, hi.meanCode[ch], c, lo.spec.name,
                        lo.spec.luminanceCdM2, lo.meanCode[ch]),
            {}};
      }
    }
  }
  return std::nullopt;
}

PhotometricCalibration fitResponse(std::span<const PatchMeasurement> fitPatches, int channels,
                                   const PhotometricFitOptions& options) {
  PhotometricCalibration calibration;
  calibration.blackLevelCode = options.blackLevelCode;
  calibration.saturationCode = options.saturationCode;
  std::vector<double> x, y;
  LogResponse log;
  LinearResponse linear;
  for (int c = 0; c < 3; ++c) {
    const auto ch = std::size_t(std::min(c, channels - 1));  // a mono fit fills every channel
    x.clear();
    y.clear();
    for (const PatchMeasurement& p : fitPatches) {
      const double exposure = p.exposureUs * p.gain;
      x.push_back(options.model == FitModel::Log ? std::log(p.spec.luminanceCdM2)
                                                 : p.spec.luminanceCdM2 * exposure);
      y.push_back(p.meanCode[ch]);
    }
    if (options.model == FitModel::Log) {
      const Line line = fitLine(x, y);
      log.aCode[std::size_t(c)] = line.a;
      log.bCodePerLn[std::size_t(c)] = line.b;
    } else {
      linear.gainCodePerCdM2Us[std::size_t(c)] = fitGain(x, y, options.blackLevelCode);
    }
  }
  if (options.model == FitModel::Log) {
    calibration.response = log;
  } else {
    calibration.response = linear;
  }
  return calibration;
}

PatchResult evaluate(const PatchMeasurement& p, const PhotometricCalibration& calibration) {
  PatchResult result{p.spec.name, p.spec.check, p.spec.luminanceCdM2, p.meanCode, {}, {}};
  for (int c = 0; c < p.channels; ++c) {
    const auto ch = std::size_t(c);
    const double fitted = luminanceFromCode(calibration, c, p.meanCode[ch], p.exposureUs, p.gain);
    result.fittedLuminanceCdM2[ch] = fitted;
    result.errorPercent[ch] = 100.0 * (fitted / p.spec.luminanceCdM2 - 1.0);
  }
  return result;
}

}  // namespace

PatchMeasurement measurePatch(std::span<const RawFrame> frames, const PatchSpec& patch,
                              double blackLevelCode, double saturationCode) {
  PatchMeasurement m;
  m.spec = patch;
  m.channels = frames.front().format.channels;
  m.exposureUs = frames.front().exposureUs;
  m.gain = frames.front().gain;
  std::array<double, 3> sum{}, sumSq{};
  std::size_t samples = 0, clipped = 0, black = 0;
  for (const RawFrame& frame : frames) {
    for (int v = patch.y; v < patch.y + patch.height; ++v) {
      for (int u = patch.x; u < patch.x + patch.width; ++u) {
        for (int c = 0; c < m.channels; ++c) {
          const double code = frame.at(u, v, c);
          sum[std::size_t(c)] += code;
          sumSq[std::size_t(c)] += code * code;
          clipped += code >= saturationCode ? 1 : 0;
          black += code <= blackLevelCode ? 1 : 0;
        }
        ++samples;
      }
    }
  }
  const double n = double(samples);
  for (int c = 0; c < m.channels; ++c) {
    const auto ch = std::size_t(c);
    m.meanCode[ch] = sum[ch] / n;
    m.stdDevCode[ch] = std::sqrt(std::max(0.0, sumSq[ch] / n - m.meanCode[ch] * m.meanCode[ch]));
  }
  m.clippedFraction = double(clipped) / (n * m.channels);
  m.underBlackFraction = double(black) / (n * m.channels);
  return m;
}

std::expected<PhotometricFit, PhotometricFitFailure> fitPhotometric(
    std::span<const PatchMeasurement> patches, const PhotometricFitOptions& options) {
  std::vector<PatchMeasurement> fitPatches;
  for (const PatchMeasurement& p : patches) {
    if (!p.spec.check) fitPatches.push_back(p);
  }
  if (fitPatches.size() < 3) {
    return refuse(PhotometricRefusal::TooFewPatches,
                  fmt::format("only {} patch(es) are left for the fit (check patches excluded); "
                              "at least 3 are needed",
                              fitPatches.size()));
  }
  if (auto failure = checkUsable(patches, options)) return std::unexpected(*failure);
  const auto [darkest, brightest] = std::ranges::minmax(
      fitPatches, {}, [](const PatchMeasurement& p) { return p.spec.luminanceCdM2; });
  const double span = brightest.spec.luminanceCdM2 / darkest.spec.luminanceCdM2;
  if (!(span >= options.minLuminanceRatio)) {
    return refuse(PhotometricRefusal::LuminanceSpanTooSmall,
                  fmt::format("the fit patches span only {:.3g}x in luminance ('{}' to '{}'); at "
                              "least {:g}x is needed to fit the response's slope",
                              span, darkest.spec.name, brightest.spec.name,
                              options.minLuminanceRatio));
  }
  if (auto failure = checkIncreasing(patches)) return std::unexpected(*failure);

  PhotometricFit fit;
  fit.calibration = fitResponse(fitPatches, patches.front().channels, options);
  double sumSq = 0.0;
  int count = 0;
  for (const PatchMeasurement& p : patches) {
    PatchResult r = evaluate(p, fit.calibration);
    for (int c = 0; c < p.channels; ++c) {
      const double e = std::abs(r.errorPercent[std::size_t(c)]);
      if (p.spec.check) {
        fit.quality.maxCheckErrorPercent = std::max(fit.quality.maxCheckErrorPercent, e);
      } else {
        fit.quality.maxResidualPercent = std::max(fit.quality.maxResidualPercent, e);
        sumSq += e * e;
        ++count;
      }
    }
    fit.patches.push_back(std::move(r));
  }
  fit.quality.rmsResidualPercent = std::sqrt(sumSq / count);
  fit.quality.fitPatches = int(fitPatches.size());
  fit.quality.checkPatches = int(patches.size() - fitPatches.size());
  if (fit.quality.maxResidualPercent > options.maxResidualPercent) {
    return refuse(PhotometricRefusal::ResidualTooHigh,
                  fmt::format("the fit's largest patch residual is {:.2f}%, above the limit of "
                              "{:g}% (--max-residual): the response does not follow the model",
                              fit.quality.maxResidualPercent, options.maxResidualPercent),
                  fit.patches);
  }
  if (fit.quality.maxCheckErrorPercent > options.maxCheckErrorPercent) {
    return refuse(PhotometricRefusal::CheckErrorTooHigh,
                  fmt::format("a check patch is off by {:.2f}%, above the limit of {:g}% "
                              "(--max-check-error): the fit does not predict unseen patches",
                              fit.quality.maxCheckErrorPercent, options.maxCheckErrorPercent),
                  fit.patches);
  }
  return fit;
}

}  // namespace vem::calib
