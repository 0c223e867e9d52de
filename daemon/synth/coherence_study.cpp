#include "synth/coherence_study.h"

#include <algorithm>
#include <cmath>

#include "core/color.h"
#include "core/default_pattern.h"
#include "core/irradiance.h"
#include "core/sampling_tables.h"
#include "core/temporal_filter.h"
#include "util/contract.h"

namespace vem::synth {
namespace {

// One step of the (gated) moving average of the maps, pixel by pixel, into `average`.
void smoothImportance(const EnvMap& newest, double weight, double gate, EnvMap& average) {
  const std::size_t pixels = newest.rgb.size() / 3;
  for (std::size_t p = 0; p < pixels; ++p) {
    float* avg = &average.rgb[3 * p];
    const float* now = &newest.rgb[3 * p];
    double w = weight;
    if (gate > 0.0) {
      const double yNow = luminance(glm::dvec3(now[0], now[1], now[2]));
      const double yAvg = luminance(glm::dvec3(avg[0], avg[1], avg[2]));
      const double larger = std::max(std::abs(yNow), std::abs(yAvg));
      // A changed pixel, or a bad one (NaN compares false): the newest value.
      if (!(std::abs(yNow - yAvg) <= gate * larger)) w = 1.0;
    }
    for (int c = 0; c < 3; ++c) avg[c] = float(w * double(now[c]) + (1.0 - w) * double(avg[c]));
  }
}

// A box sum of radius r along one line of n values (wrapping when `wrap`, else clamping), into out.
void boxSumLine(const double* in, std::size_t stride, int n, int r, bool wrap, double* out,
                std::size_t outStride) {
  auto at = [&](int i) {
    i = wrap ? ((i % n) + n) % n : std::clamp(i, 0, n - 1);
    return in[std::size_t(i) * stride];
  };
  double sum = 0;
  for (int i = -r; i <= r; ++i) sum += at(i);
  for (int i = 0; i < n; ++i) {
    out[std::size_t(i) * outStride] = sum;
    sum += at(i + r + 1) - at(i - r);
  }
}

}  // namespace

EnvMap liftImportance(const EnvMap& map, double fraction, int radiusPx) {
  VEM_EXPECTS(fraction >= 0.0 && radiusPx >= 0);
  const int w = map.width, h = map.height;
  std::vector<double> y(std::size_t(w) * std::size_t(h)), rows(y.size()), box(y.size());
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) y[std::size_t(j) * std::size_t(w) + std::size_t(i)] =
        luminance(sanitizedRgb(map, i, j));
  }
  for (int j = 0; j < h; ++j) {
    const std::size_t row = std::size_t(j) * std::size_t(w);
    boxSumLine(&y[row], 1, w, radiusPx, true, &rows[row], 1);
  }
  for (int i = 0; i < w; ++i) {
    boxSumLine(&rows[std::size_t(i)], std::size_t(w), h, radiusPx, false, &box[std::size_t(i)],
               std::size_t(w));
  }
  const double area = double(2 * radiusPx + 1) * double(2 * radiusPx + 1);
  EnvMap lifted = map;
  for (std::size_t p = 0; p < y.size(); ++p) {
    const double add = fraction * box[p] / area - y[p];
    if (add > 0.0) {
      for (int c = 0; c < 3; ++c) {
        float& v = lifted.rgb[3 * p + std::size_t(c)];
        v = float((std::isfinite(v) && v >= 0.0F ? double(v) : 0.0) + add);
      }
    }
  }
  return lifted;
}

std::vector<std::vector<glm::dvec3>> exactIrradiance(std::span<const SequenceFrame> frames,
                                                     std::span<const glm::dvec3> normals) {
  std::vector<std::vector<glm::dvec3>> out;
  out.reserve(frames.size());
  for (const SequenceFrame& frame : frames) out.push_back(irradianceFromMap(frame.map, normals));
  return out;
}

std::vector<LightSet> sampleSequence(std::span<const SequenceFrame> frames, SamplerKind sampler,
                                     std::size_t lightCount, double importanceWeight,
                                     double importanceGate, double liftFraction,
                                     int liftRadiusPx) {
  VEM_EXPECTS(importanceWeight > 0.0 && importanceWeight <= 1.0 && importanceGate >= 0.0 &&
              liftFraction >= 0.0);
  std::vector<LightSet> out;
  out.reserve(frames.size());
  SamplingTables tables;
  EnvMap smoothed;
  LightCells cells;
  for (const SequenceFrame& frame : frames) {
    const auto pattern = defaultSamplingPattern(frame.map.layout).first(lightCount);
    if (cells.count != pattern.size()) cells = lightCellsFor(frame.map.layout, pattern, sampler);
    if (importanceWeight == 1.0 && liftFraction == 0.0) {
      tables = buildSamplingTables(frame.map, std::move(tables));
      out.push_back(generateLights(tables, pattern, sampler, cells));
      continue;
    }
    if (importanceWeight == 1.0 || smoothed.rgb.size() != frame.map.rgb.size()) {
      smoothed = frame.map;
    } else {
      smoothImportance(frame.map, importanceWeight, importanceGate, smoothed);
    }
    tables = buildSamplingTables(
        liftFraction > 0.0 ? liftImportance(smoothed, liftFraction, liftRadiusPx) : smoothed,
        std::move(tables));
    // The lights' colours come from their cells in the importance map, their power from the newest.
    LightSet set = generateLights(tables, pattern, sampler, cells);
    const double newest = luminance(radianceIntegralSr(frame.map));
    const double scale = set.luminanceSr > 0.0 ? newest / set.luminanceSr : 0.0;
    for (Light& light : set.lights) light.rgb *= float(scale);
    set.luminanceSr = newest;
    out.push_back(std::move(set));
  }
  return out;
}

std::vector<LightSet> filterSequence(std::span<const LightSet> sets, FilterPreset preset) {
  TemporalFilter filter(presetTaps(preset));
  std::vector<LightSet> out;
  out.reserve(sets.size());
  for (std::size_t k = 0; k < sets.size(); ++k) {
    FilterResult result = filter.push(k, sets[k]);
    VEM_EXPECTS(result.lights.has_value());  // consecutive sequence numbers are never stale
    out.push_back(std::move(*result.lights));
  }
  return out;
}

void CoherenceTally::add(const CoherenceTally& other) {
  stepsDeg.insert(stepsDeg.end(), other.stepsDeg.begin(), other.stepsDeg.end());
  lightsChangeSq += other.lightsChangeSq;
  exactChangeSq += other.exactChangeSq;
  excessChangeSq += other.excessChangeSq;
  exactSq += other.exactSq;
  errorSum += other.errorSum;
  frames += other.frames;
}

CoherenceTally tallySequence(std::span<const SequenceFrame> frames, std::span<const LightSet> sets,
                             std::span<const std::vector<glm::dvec3>> exact,
                             std::span<const glm::dvec3> normals) {
  VEM_EXPECTS(frames.size() == sets.size() && frames.size() == exact.size());
  CoherenceTally t;
  std::vector<double> previousLights;
  std::vector<double> previousExact;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const auto fromLights = irradianceFromLights(sets[k].lights, normals);
    t.errorSum += relativeRmsError(fromLights, exact[k]);
    ++t.frames;
    std::vector<double> lightsY = luminances(fromLights);
    std::vector<double> exactY = luminances(exact[k]);
    if (k > 0) {
      appendAngularStepsDeg(sets[k - 1], sets[k], frames[k].motionFromPrevious, t.stepsDeg);
      for (std::size_t n = 0; n < normals.size(); ++n) {
        const double dLights = lightsY[n] - previousLights[n];
        const double dExact = exactY[n] - previousExact[n];
        t.lightsChangeSq += dLights * dLights;
        t.exactChangeSq += dExact * dExact;
        t.excessChangeSq += (dLights - dExact) * (dLights - dExact);
        t.exactSq += exactY[n] * exactY[n];
      }
    }
    previousLights = std::move(lightsY);
    previousExact = std::move(exactY);
  }
  return t;
}

CoherenceFigures summarise(const CoherenceTally& t) {
  CoherenceFigures f;
  f.steps = summariseSteps(t.stepsDeg);
  if (t.exactSq > 0.0) {
    f.lightsFlicker = std::sqrt(t.lightsChangeSq / t.exactSq);
    f.exactFlicker = std::sqrt(t.exactChangeSq / t.exactSq);
    f.excessFlicker = std::sqrt(t.excessChangeSq / t.exactSq);
  }
  f.meanError = t.frames > 0 ? t.errorSum / double(t.frames) : 0.0;
  return f;
}

}  // namespace vem::synth
