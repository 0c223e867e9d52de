#include "calib/core/bracket_merge.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "util/contract.h"

namespace vem::calib {
namespace {

// The frames' tables in order of increasing exposure (exposureUs x gain): k = 0 is the shortest.
struct SortedFrames {
  std::vector<const std::uint16_t*> codes;
  std::vector<const BracketLut*> luts;
};

SortedFrames sortByExposure(std::span<const RawFrame> frames, std::span<const BracketLut> luts) {
  std::vector<std::size_t> order(frames.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return frames[a].exposureUs * frames[a].gain < frames[b].exposureUs * frames[b].gain;
  });
  SortedFrames sorted;
  for (const std::size_t k : order) {
    sorted.codes.push_back(frames[k].codes.data());
    sorted.luts.push_back(&luts[k]);
  }
  return sorted;
}

void checkInputs(std::span<const RawFrame> frames, std::span<const BracketLut> luts) {
  VEM_EXPECTS(!frames.empty() && frames.size() == luts.size());
  for (std::size_t k = 0; k < frames.size(); ++k) {
    VEM_EXPECTS(frames[k].width == frames[0].width && frames[k].height == frames[0].height);
    VEM_EXPECTS(frames[k].format == frames[0].format);
    VEM_EXPECTS(luts[k].channels == frames[k].format.channels);
    VEM_EXPECTS(luts[k].size == frames[k].format.maxCode() + 1u);
    VEM_EXPECTS(frames[k].codes.size() == frames[0].codes.size());
  }
}

// The reading of a sample that no frame weighs (each frame clipped or in the noise floor), and
// which count it adds to.
float unweighedReading(const SortedFrames& sorted, std::size_t sample, std::size_t entryBase,
                       MergedBracket& merged) {
  const std::size_t count = sorted.luts.size();
  std::size_t clipped = 0;
  std::size_t firstClipped = count;
  for (std::size_t k = 0; k < count; ++k) {
    const BracketLut& lut = *sorted.luts[k];
    if (double(sorted.codes[k][sample]) >= lut.clippedFromCode) {
      ++clipped;
      firstClipped = std::min(firstClipped, k);
    }
  }
  const std::size_t from = clipped == 0 ? count - 1 : firstClipped;
  if (clipped == count) {
    ++merged.clippedSamples;
  } else if (clipped == 0) {
    ++merged.blackSamples;
  } else {
    ++merged.gapSamples;
  }
  const BracketLut& lut = *sorted.luts[from];
  const std::uint32_t code = std::min<std::uint32_t>(sorted.codes[from][sample], lut.size - 1u);
  return lut.luminanceCdM2[entryBase + code];
}

// The weighted mean of every sample, `Channels` per pixel (a compile-time count, so the channel
// loop unrolls): per frame, two table loads and two adds.
template <std::size_t Channels>
void mergeSamples(const SortedFrames& sorted, MergedBracket& merged) {
  const std::size_t frameCount = sorted.luts.size();
  const std::uint32_t size = sorted.luts[0]->size;
  std::vector<const float*> weights;
  std::vector<const float*> weighted;
  for (const BracketLut* lut : sorted.luts) {
    weights.push_back(lut->weight.data());
    weighted.push_back(lut->weightedLuminance.data());
  }
  float* out = merged.luminanceCdM2.data();
  const std::size_t samples = merged.luminanceCdM2.size();
  for (std::size_t pixel = 0; pixel < samples; pixel += Channels) {
    for (std::size_t c = 0; c < Channels; ++c) {
      const std::size_t sample = pixel + c;
      float weightSum = 0.0F;
      float weightedSum = 0.0F;
      for (std::size_t k = 0; k < frameCount; ++k) {
        const std::size_t entry =
            c * size + std::min<std::uint32_t>(sorted.codes[k][sample], size - 1u);
        weightSum += weights[k][entry];
        weightedSum += weighted[k][entry];
      }
      out[sample] = weightSum > 0.0F ? weightedSum / weightSum
                                     : unweighedReading(sorted, sample, c * size, merged);
    }
  }
}

}  // namespace

double bracketWeight(const PhotometricCalibration& calibration, const BracketWeighting& weighting,
                     double code) {
  const double lo = calibration.blackLevelCode + weighting.blackMarginCode;
  const double hi = calibration.saturationCode - weighting.saturationMarginCode;
  if (code <= lo || code >= hi) return 0.0;
  return std::min(code - lo, hi - code) / (0.5 * (hi - lo));
}

BracketLut buildBracketLut(const PhotometricCalibration& calibration, PixelFormat format,
                           double exposureUs, double gain, const BracketWeighting& weighting) {
  const CodeToLuminanceLut readings =
      buildCodeToLuminanceLut(calibration, format, exposureUs, gain);
  BracketLut lut;
  lut.channels = readings.channels;
  lut.size = readings.size;
  lut.luminanceCdM2 = readings.luminanceCdM2;
  lut.noiseFloorTopCode = calibration.blackLevelCode + weighting.blackMarginCode;
  lut.clippedFromCode = calibration.saturationCode - weighting.saturationMarginCode;
  lut.exposureUs = exposureUs;
  lut.gain = gain;
  lut.weight.resize(lut.luminanceCdM2.size());
  lut.weightedLuminance.resize(lut.luminanceCdM2.size());
  for (std::size_t e = 0; e < lut.weight.size(); ++e) {
    const double w = bracketWeight(calibration, weighting, double(e % lut.size));
    lut.weight[e] = float(w);
    lut.weightedLuminance[e] = float(w * double(lut.luminanceCdM2[e]));
  }
  return lut;
}

void mergeBracket(std::span<const RawFrame> frames, std::span<const BracketLut> luts,
                  MergedBracket& merged) {
  checkInputs(frames, luts);
  const SortedFrames sorted = sortByExposure(frames, luts);
  merged.width = frames[0].width;
  merged.height = frames[0].height;
  merged.channels = frames[0].format.channels;
  merged.luminanceCdM2.resize(frames[0].codes.size());
  merged.clippedSamples = merged.blackSamples = merged.gapSamples = 0;
  if (merged.channels == 3) {
    mergeSamples<3>(sorted, merged);
  } else {
    mergeSamples<1>(sorted, merged);
  }
}

MergedBracket mergeBracket(std::span<const RawFrame> frames, std::span<const BracketLut> luts) {
  MergedBracket merged;
  mergeBracket(frames, luts, merged);
  return merged;
}

MergedBracket mergeBracket(std::span<const RawFrame> frames,
                           const PhotometricCalibration& calibration,
                           const BracketWeighting& weighting) {
  std::vector<BracketLut> luts;
  luts.reserve(frames.size());
  for (const RawFrame& frame : frames) {
    luts.push_back(
        buildBracketLut(calibration, frame.format, frame.exposureUs, frame.gain, weighting));
  }
  return mergeBracket(frames, luts);
}

BracketConsistency bracketConsistency(std::span<const RawFrame> frames,
                                      std::span<const BracketLut> luts) {
  checkInputs(frames, luts);
  const std::size_t channels = std::size_t(frames[0].format.channels);
  const std::uint32_t top = luts[0].size - 1u;
  std::vector<float> disagreements;
  for (std::size_t sample = 0; sample < frames[0].codes.size(); ++sample) {
    const std::size_t base = (sample % channels) * luts[0].size;
    for (std::size_t a = 0; a < frames.size(); ++a) {
      const std::size_t ea = base + std::min<std::uint32_t>(frames[a].codes[sample], top);
      if (luts[a].weight[ea] <= 0.0F) continue;
      for (std::size_t b = a + 1; b < frames.size(); ++b) {
        const std::size_t eb = base + std::min<std::uint32_t>(frames[b].codes[sample], top);
        if (luts[b].weight[eb] <= 0.0F) continue;
        const float la = luts[a].luminanceCdM2[ea];
        const float lb = luts[b].luminanceCdM2[eb];
        if (la + lb > 0.0F) disagreements.push_back(2.0F * std::abs(la - lb) / (la + lb));
      }
    }
  }
  BracketConsistency consistency;
  consistency.comparedPairs = disagreements.size();
  if (disagreements.empty()) return consistency;
  double sumSquares = 0.0;
  for (const float d : disagreements) sumSquares += double(d) * double(d);
  consistency.rmsPercent = 100.0 * std::sqrt(sumSquares / double(disagreements.size()));
  consistency.maxPercent =
      100.0 * double(*std::max_element(disagreements.begin(), disagreements.end()));
  const auto middle = disagreements.begin() + std::ptrdiff_t(disagreements.size() / 2);
  std::nth_element(disagreements.begin(), middle, disagreements.end());
  consistency.medianPercent = 100.0 * double(*middle);
  return consistency;
}

}  // namespace vem::calib
