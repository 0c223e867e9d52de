// SensorCodeTable: a camera's response (calib/core/photometric_model.h) at one exposure and gain,
// tabulated so that a luminance becomes its code with one table read and no log: the synthetic
// camera's per-pixel path.
//
// The table is indexed by the luminance's float bit pattern: its exponent and the top 8 bits of its
// mantissa, i.e. 256 bins per octave from 2^-40 to 2^40 cd/m^2 (20481 edges per channel). Each
// edge holds codeFromLuminance() there; within a bin the code is interpolated linearly in
// luminance, exact for linear responses and within 5e-4 codes of the log response for a 12-bit
// log sensor (b ~ 210 codes per ln unit). Bins where that interpolation would be off by more than
// 0.01 codes at their quarter points (the kinks where the response meets the black level or
// saturation, the steps of a tabulated response) are marked and computed exactly instead.
// Below 2^-40 (and for 0, negatives and NaN) the code is that of 0 cd/m^2; above 2^40, that of
// 2^40. Codes are noiseless and unquantised, clamped to [black level, saturation] as
// codeFromLuminance's are.
#pragma once

#include <array>
#include <bit>
#include <cstdint>
#include <vector>

#include "calib/core/photometric_model.h"
#include "frames/raw_frame.h"

namespace vem::synth {

class SensorCodeTable {
 public:
  static constexpr int kShift = 15;  // 23 mantissa bits - 8 kept: 256 bins per octave
  static constexpr float kLowestCdM2 = 0x1p-40F;
  static constexpr float kHighestCdM2 = 0x1p+40F;

  SensorCodeTable(const calib::PhotometricCalibration& photometric, PixelFormat format,
                  double exposureUs, double gain);

  // Inline: the synthetic camera calls it for every pixel and channel.
  [[nodiscard]] float idealCode(int channel, float luminanceCdM2) const {
    const auto c = std::size_t(channel);
    if (!(luminanceCdM2 >= kLowestCdM2)) return darkCode_[c];
    if (luminanceCdM2 >= kHighestCdM2) return brightCode_[c];
    const std::uint32_t bits = std::bit_cast<std::uint32_t>(luminanceCdM2);
    const std::size_t bin = (bits >> kShift) - kLowestKey;
    const float t = float(bits & ((1u << kShift) - 1u)) * kFractionScale;
    if (exactBins_[c][bin] != 0) return exactCode(channel, luminanceCdM2);
    const float* edges = edges_[c].data();
    return edges[bin] + (edges[bin + 1] - edges[bin]) * t;
  }
  [[nodiscard]] double exposureUs() const { return exposureUs_; }
  [[nodiscard]] double gain() const { return gain_; }

 private:
  static constexpr std::uint32_t kLowestKey = std::bit_cast<std::uint32_t>(kLowestCdM2) >> kShift;
  static constexpr std::uint32_t kHighestKey = std::bit_cast<std::uint32_t>(kHighestCdM2) >> kShift;
  static constexpr float kFractionScale = 1.0F / float(1u << kShift);

  [[nodiscard]] float exactCode(int channel, float luminanceCdM2) const;

  calib::PhotometricCalibration photometric_;
  double exposureUs_;
  double gain_;
  std::array<std::vector<float>, 3> edges_;             // per channel, at the bins' lower edges
  std::array<std::vector<std::uint8_t>, 3> exactBins_;  // 1: computed, not interpolated
  std::array<float, 3> darkCode_{};                     // below the table
  std::array<float, 3> brightCode_{};                   // above it
};

}  // namespace vem::synth
