#include "core/fir_design.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <numbers>

#include <liquid/liquid.h>  // after <complex>: liquid then uses std::complex<double>

#include "util/contract.h"

namespace vem {
namespace {

using Complex = std::complex<double>;

// Sums whose magnitude is below this fraction of sum |w| count as zero (no DC gain to normalise).
constexpr double kMinRelativeSum = 1e-9;
// minimumPhase keeps its result only if every gain matches the input's to this (gains are <= ~1).
constexpr double kMinPhaseGainTolerance = 1e-5;
constexpr int kGainCheckPoints = 512;
constexpr int kScanPoints = 2048;

std::string formatHz(double hz) {
  char text[32];
  std::snprintf(text, sizeof text, "%g Hz", hz);
  return text;
}

// H(f) = sum_k w_k exp(-i 2 pi f k) and, when asked, its derivative factor sum_k k w_k exp(...).
Complex response(const FirTaps& taps, double cyclesPerFrame, bool weightByDelay) {
  Complex sum{0.0, 0.0};
  const double omega = 2.0 * std::numbers::pi * cyclesPerFrame;
  for (std::size_t k = 0; k < taps.size(); ++k) {
    const double weight = taps.weights()[k] * (weightByDelay ? double(k) : 1.0);
    sum += std::polar(weight, -omega * double(k));
  }
  return sum;
}

bool gainsMatch(const FirTaps& a, const FirTaps& b) {
  for (int i = 0; i <= kGainCheckPoints; ++i) {
    const double f = 0.5 * i / kGainCheckPoints;
    if (!(std::abs(gainAt(a, f) - gainAt(b, f)) <= kMinPhaseGainTolerance)) return false;
  }
  return true;
}

// Lowest frequency (cycles per frame) where the gain falls to 1/sqrt(2); 0.5 if it never does.
double halfPowerCyclesPerFrame(const FirTaps& taps) {
  const double target = std::numbers::sqrt2 / 2.0;
  double below = 0.0;
  for (int i = 1; i <= kScanPoints; ++i) {
    const double f = 0.5 * i / kScanPoints;
    if (gainAt(taps, f) > target) {
      below = f;
      continue;
    }
    double above = f;
    for (int step = 0; step < 60; ++step) {
      const double mid = 0.5 * (below + above);
      if (gainAt(taps, mid) > target) {
        below = mid;
      } else {
        above = mid;
      }
    }
    return 0.5 * (below + above);
  }
  return 0.5;
}

}  // namespace

std::optional<FirTaps> FirTaps::normalised(std::span<const double> weights) {
  if (weights.empty()) return std::nullopt;
  double sum = 0.0;
  double sumAbs = 0.0;
  for (double w : weights) {
    if (!std::isfinite(w)) return std::nullopt;
    sum += w;
    sumAbs += std::abs(w);
  }
  if (!(std::abs(sum) > kMinRelativeSum * sumAbs)) return std::nullopt;
  std::vector<double> scaled(weights.begin(), weights.end());
  for (double& w : scaled) w /= sum;
  return FirTaps(std::move(scaled));
}

std::optional<std::string> describeInvalid(const LowPassSpec& spec) {
  const BandEdgesHz& e = spec.edges;
  if (!(std::isfinite(e.rateHz) && e.rateHz > 0.0)) {
    return "the capture rate must be a positive number of Hz, got " + formatHz(e.rateHz);
  }
  if (spec.tapCount < 3 || spec.tapCount > kMaxDesignTaps || spec.tapCount % 2 == 0) {
    return "the tap count must be odd, from 3 to " + std::to_string(kMaxDesignTaps) + ", got " +
           std::to_string(spec.tapCount);
  }
  if (!(e.passHz > 0.0)) return "the pass edge must be above 0 Hz, got " + formatHz(e.passHz);
  if (!(e.passHz < e.stopHz)) {
    return "the pass edge (" + formatHz(e.passHz) + ") must lie below the stop edge (" +
           formatHz(e.stopHz) + ")";
  }
  if (!(e.stopHz < 0.5 * e.rateHz)) {
    return "the stop edge (" + formatHz(e.stopHz) + ") must lie below half the capture rate (" +
           formatHz(0.5 * e.rateHz) + ")";
  }
  return std::nullopt;
}

std::optional<std::vector<double>> designEquiripple(const LowPassSpec& spec) {
  if (describeInvalid(spec)) return std::nullopt;
  const BandEdgesHz& e = spec.edges;
  float bands[4] = {0.0F, float(e.passHz / e.rateHz), float(e.stopHz / e.rateHz), 0.5F};
  float desired[2] = {1.0F, 0.0F};
  float weights[2] = {1.0F, 1.0F};
  liquid_firdespm_wtype weighting[2] = {LIQUID_FIRDESPM_FLATWEIGHT, LIQUID_FIRDESPM_FLATWEIGHT};
  std::vector<float> taps(std::size_t(spec.tapCount), 0.0F);
  if (firdespm_run(unsigned(spec.tapCount), 2, bands, desired, weights, weighting,
                   LIQUID_FIRDESPM_BANDPASS, taps.data()) != LIQUID_OK) {
    return std::nullopt;
  }
  if (!std::ranges::all_of(taps, [](float w) { return std::isfinite(w); })) return std::nullopt;
  return std::vector<double>(taps.begin(), taps.end());
}

std::optional<FirTaps> designLowPass(const LowPassSpec& spec) {
  const std::optional<std::vector<double>> raw = designEquiripple(spec);
  if (!raw) return std::nullopt;
  return FirTaps::normalised(*raw);
}

// The taps are the coefficients of p(x) = sum_k w_k x^k with x = 1/z; a zero of H(z) inside the
// unit circle is a root of p with |x| > 1. Reflecting x -> 1/conj(x) scales |H| on the circle by a
// constant, which the normalisation removes.
std::optional<FirTaps> minimumPhase(const FirTaps& taps) {
  std::vector<double> poly = taps.weights();
  if (poly.size() == 1) return taps;
  if (poly.front() == 0.0 || poly.back() == 0.0) return std::nullopt;
  const unsigned rootCount = unsigned(poly.size() - 1);
  std::vector<Complex> roots(rootCount);
  if (poly_findroots(poly.data(), unsigned(poly.size()), roots.data()) != LIQUID_OK) {
    return std::nullopt;
  }
  for (Complex& root : roots) {
    if (std::abs(root) < 1.0) root = 1.0 / std::conj(root);
  }
  std::vector<Complex> expanded(poly.size());
  if (polyc_expandroots(roots.data(), rootCount, expanded.data()) != LIQUID_OK) return std::nullopt;
  std::vector<double> real(poly.size());
  std::ranges::transform(expanded, real.begin(), [](Complex c) { return c.real(); });
  std::optional<FirTaps> result = FirTaps::normalised(real);
  if (!result || !gainsMatch(*result, taps)) return std::nullopt;
  return result;
}

FirTaps presetTaps(FilterPreset preset) {
  switch (preset) {
    case FilterPreset::None: return FirTaps::normalised(std::array{1.0}).value();
    case FilterPreset::Paper9: return FirTaps::normalised(kPaperTapsRaw).value();
    case FilterPreset::Equiripple5: return designLowPass(kEquiripple5Spec).value();
    case FilterPreset::MinPhase9: return minimumPhase(presetTaps(FilterPreset::Paper9)).value();
  }
  VEM_UNREACHABLE("presetTaps: every FilterPreset is handled above");
}

const char* presetName(FilterPreset preset) {
  switch (preset) {
    case FilterPreset::None: return "none";
    case FilterPreset::Paper9: return "paper9";
    case FilterPreset::Equiripple5: return "equiripple5";
    case FilterPreset::MinPhase9: return "minphase9";
  }
  return "?";
}

std::optional<FilterPreset> presetFromName(std::string_view name) {
  for (FilterPreset preset : kAllPresets) {
    if (name == presetName(preset)) return preset;
  }
  return std::nullopt;
}

double gainAt(const FirTaps& taps, double cyclesPerFrame) {
  return std::abs(response(taps, cyclesPerFrame, false));
}

// With H = sum w_k e^{-i omega k}, -d arg H / d omega = Re(sum k w_k e^{-i omega k} / H);
// not finite at a zero of H.
double groupDelayFramesAt(const FirTaps& taps, double cyclesPerFrame) {
  return (response(taps, cyclesPerFrame, true) / response(taps, cyclesPerFrame, false)).real();
}

FilterCharacteristics characteriseFilter(const FirTaps& taps, const BandEdgesHz& edges) {
  FilterCharacteristics c;
  c.delayFrames = groupDelayFramesAt(taps, 0.0);
  c.delayMs = c.delayFrames * 1000.0 / edges.rateHz;
  const double pass = edges.passHz / edges.rateHz;
  const double stop = edges.stopHz / edges.rateHz;
  double delayMin = c.delayFrames;
  double delayMax = c.delayFrames;
  for (int i = 0; i <= kScanPoints; ++i) {
    const double delay = groupDelayFramesAt(taps, pass * i / kScanPoints);
    delayMin = std::min(delayMin, delay);
    delayMax = std::max(delayMax, delay);
    c.stopGainMax = std::max(c.stopGainMax, gainAt(taps, stop + (0.5 - stop) * i / kScanPoints));
  }
  c.delaySpreadFrames = delayMax - delayMin;
  c.halfPowerHz = halfPowerCyclesPerFrame(taps) * edges.rateHz;
  c.passGain = gainAt(taps, pass);
  double sumSquares = 0.0;
  double step = 0.0;
  for (double w : taps.weights()) {
    sumSquares += w * w;
    step += w;
    c.stepOvershoot = std::max(c.stepOvershoot, step - 1.0);
    c.stepUndershoot = std::max(c.stepUndershoot, -step);
  }
  c.jitterRmsGain = std::sqrt(sumSquares);
  return c;
}

}  // namespace vem
