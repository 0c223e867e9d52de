// Merging an exposure bracket into one HDR image (Debevec & Malik 1997, "Recovering High Dynamic
// Range Radiance Maps from Photographs", section 2.2, equation 6; paper 002 merges its phone
// brackets this way): K raw frames of one scene, taken through one camera response at different
// exposures, become one luminance image, each sample the weighted mean of what the frames read:
//     L = sum_k w(z_k) L_k(z_k) / sum_k w(z_k),
// where L_k(z) = luminanceFromCode(z, exposureUs_k, gain_k) (photometric_model.h).
//
// Conventions and units:
// - Output: floats in the frames' own layout (sensor pixels, row-major, channels interleaved as in
//   raw_frame.h), luminance in cd/m^2 per channel; with a relative response (scaleCdM2 = 1) the
//   unit is relative exposure per microsecond and gain, the same for every frame.
// - Weights: a hat over codes, zero outside (lo, hi) where lo = blackLevelCode + blackMarginCode
//   (the noise floor) and hi = saturationCode - saturationMarginCode (clipped codes):
//       w(z) = min(z - lo, hi - z) / ((hi - lo) / 2),  peak 1 mid-way.
//   Clipped and noise-floor codes carry no information about the scene and get no weight at all.
//   The default margins suit 8-bit sensors.
// - Samples (one pixel, one channel) that no frame weighs: clipped in every frame, they read as the
//   shortest exposure's saturated value (the tightest lower bound) and count as clippedSamples; in
//   the noise floor in every frame, as the longest exposure's value (blackSamples); otherwise
//   (noise floor in the short frames, clipped in the long ones: the exposures are too far apart) as
//   the shortest clipped frame's value (gapSamples).
// - Speed: each frame gets a table of weight and weight x luminance per code, built once per
//   exposure and gain (buildBracketLut); merging is then two loads and two adds per frame and
//   sample, no exp or log per pixel (1280 x 1024 RGB8 x 3 frames: about 11 ms on one core).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "calib/core/photometric_model.h"
#include "frames/raw_frame.h"

namespace vem::calib {

struct BracketWeighting {
  double blackMarginCode = 4.0;       // codes <= black level + this weigh 0
  double saturationMarginCode = 4.0;  // codes >= saturation - this weigh 0
};

// The hat weight of `code` (fractional codes allowed), in [0, 1].
[[nodiscard]] double bracketWeight(const PhotometricCalibration& calibration,
                                   const BracketWeighting& weighting, double code);

// One frame's tables, channel-major like CodeToLuminanceLut: [channel * size + code].
struct BracketLut {
  int channels = 1;
  std::uint32_t size = 0;                // 2^bits
  std::vector<float> weight;             // w(code)
  std::vector<float> weightedLuminance;  // w(code) * L(code)
  std::vector<float> luminanceCdM2;      // L(code), for samples no frame weighs
  double noiseFloorTopCode = 0.0;        // lo: codes at or below are in the noise floor
  double clippedFromCode = 0.0;          // hi: codes at or above are clipped
  double exposureUs = 0.0;
  double gain = 0.0;
};

[[nodiscard]] BracketLut buildBracketLut(const PhotometricCalibration& calibration,
                                         PixelFormat format, double exposureUs, double gain,
                                         const BracketWeighting& weighting);

struct MergedBracket {
  int width = 0;
  int height = 0;
  int channels = 1;
  std::vector<float> luminanceCdM2;  // width * height * channels
  std::size_t clippedSamples = 0;    // clipped in every frame
  std::size_t blackSamples = 0;      // in the noise floor in every frame
  std::size_t gapSamples = 0;        // each frame clipped or in the noise floor, not all alike
};

// Frames of one size and format (at least one); luts[k] is frames[k]'s table (same format, the
// frame's exposure and gain). The frames may come in any order of exposure.
[[nodiscard]] MergedBracket mergeBracket(std::span<const RawFrame> frames,
                                         std::span<const BracketLut> luts);

// The same into `merged`, resized as needed: a caller merging frame group after frame group into
// one MergedBracket allocates once.
void mergeBracket(std::span<const RawFrame> frames, std::span<const BracketLut> luts,
                  MergedBracket& merged);

// The same, building each frame's table from its exposure and gain.
[[nodiscard]] MergedBracket mergeBracket(std::span<const RawFrame> frames,
                                         const PhotometricCalibration& calibration,
                                         const BracketWeighting& weighting);

// How well the frames agree once through the response: for every sample and every pair of frames
// that both weigh it, |L_a - L_b| / ((L_a + L_b) / 2). A correct response gives the noise level
// (a few percent); a wrong one, or wrong exposure times, give much more.
struct BracketConsistency {
  double medianPercent = 0.0;
  double rmsPercent = 0.0;
  double maxPercent = 0.0;
  std::size_t comparedPairs = 0;  // 0 when no sample is weighed by two frames
};

[[nodiscard]] BracketConsistency bracketConsistency(std::span<const RawFrame> frames,
                                                    std::span<const BracketLut> luts);

}  // namespace vem::calib
