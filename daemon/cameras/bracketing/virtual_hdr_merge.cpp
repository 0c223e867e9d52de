#include "cameras/bracketing/virtual_hdr_merge.h"

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "util/contract.h"

namespace vem::cameras {
namespace {

// log2 of a positive normal float: exponent + log2(mantissa), the latter from a table of
// kLogEntries + 1 values over [1, 2], linearly interpolated (error below 5e-8).
constexpr int kLogBits = 12;
constexpr std::uint32_t kLogEntries = 1u << kLogBits;

const std::array<float, kLogEntries + 1>& log2Table() {
  static const auto table = [] {
    std::array<float, kLogEntries + 1> t{};
    for (std::uint32_t i = 0; i <= kLogEntries; ++i) {
      t[i] = float(std::log2(1.0 + double(i) / double(kLogEntries)));
    }
    return t;
  }();
  return table;
}

double fastLog2(float value, const std::array<float, kLogEntries + 1>& table) {
  const auto bits = std::bit_cast<std::uint32_t>(value);
  const int exponent = int((bits >> 23) & 0xffu) - 127;
  const std::uint32_t mantissa = bits & 0x7fffffu;
  const std::uint32_t index = mantissa >> (23 - kLogBits);
  const float t =
      float(mantissa & ((1u << (23 - kLogBits)) - 1u)) * (1.0F / float(1u << (23 - kLogBits)));
  return double(exponent) + double(table[index] + (table[index + 1] - table[index]) * t);
}

const calib::BracketLut& lutFor(const RawFrame& frame, std::size_t slot,
                                const calib::PhotometricCalibration& ldr,
                                const calib::BracketWeighting& weighting,
                                std::vector<calib::BracketLut>& luts) {
  if (luts.size() <= slot) luts.resize(slot + 1);
  calib::BracketLut& lut = luts[slot];
  if (lut.size != frame.format.maxCode() + 1u || lut.channels != frame.format.channels ||
      lut.exposureUs != frame.exposureUs || lut.gain != frame.gain) {
    lut = calib::buildBracketLut(ldr, frame.format, frame.exposureUs, frame.gain, weighting);
  }
  return lut;
}

}  // namespace

void mergeBracketRadiance(std::span<const RawFrame> frames,
                          const calib::PhotometricCalibration& ldr,
                          const calib::BracketWeighting& weighting, BracketMergeScratch& scratch) {
  VEM_EXPECTS(!frames.empty());
  // Slot k serves the k-th frame of every group: in a steady bracket its exposure repeats.
  for (std::size_t k = 0; k < frames.size(); ++k)
    lutFor(frames[k], k, ldr, weighting, scratch.luts);
  calib::mergeBracket(frames, std::span(scratch.luts).first(frames.size()), scratch.merged);
}

VirtualHdrMergeStats encodeVirtualHdr(const calib::MergedBracket& merged,
                                      const VirtualHdrSensor& sensor, RawFrame& out) {
  VEM_EXPECTS(merged.channels == sensor.format.channels);
  out.width = merged.width;
  out.height = merged.height;
  out.format = sensor.format;
  out.codes.resize(merged.luminanceCdM2.size());
  const auto& table = log2Table();
  const std::size_t channels = std::size_t(merged.channels);
  // code = a + b ln L = a + (b ln 2) log2 L, in float-free double per sample.
  std::array<double, 3> a{};
  std::array<double, 3> bLog2{};
  for (std::size_t c = 0; c < 3; ++c) {
    a[c] = sensor.response.aCode[c] + 0.5;  // + 0.5: truncation below rounds to nearest
    bLog2[c] = sensor.response.bCodePerLn[c] * std::numbers::ln2;
  }
  VirtualHdrMergeStats stats;
  stats.samples = merged.luminanceCdM2.size();
  stats.unweighedSamples = merged.clippedSamples + merged.blackSamples + merged.gapSamples;
  constexpr double kTop = double(kVirtualTopCode);
  for (std::size_t s = 0; s < merged.luminanceCdM2.size(); ++s) {
    const float luminance = merged.luminanceCdM2[s];
    const std::size_t c = s % channels;
    // Below the smallest normal float (and 0, negatives, NaN): below any sensor's minimum.
    const double code = luminance >= 0x1p-126F ? a[c] + bLog2[c] * fastLog2(luminance, table) : 0.0;
    if (code < 1.0) {
      out.codes[s] = 0;
      ++stats.darkSamples;
    } else if (code >= kTop) {
      out.codes[s] = kVirtualTopCode;
      ++stats.saturatedSamples;
    } else {
      out.codes[s] = std::uint16_t(code);
    }
  }
  return stats;
}

VirtualHdrMergeStats mergeToVirtualHdr(std::span<const RawFrame> frames,
                                       const calib::PhotometricCalibration& ldr,
                                       const calib::BracketWeighting& weighting,
                                       const VirtualHdrSensor& sensor, BracketMergeScratch& scratch,
                                       RawFrame& out) {
  mergeBracketRadiance(frames, ldr, weighting, scratch);
  return encodeVirtualHdr(scratch.merged, sensor, out);
}

}  // namespace vem::cameras
