#include "calib/core/photometric_model.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace vem::calib {
namespace {

template <class... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};

// Relative exposure at a fractional code of a table: linear between neighbouring codes.
double tableExposure(const std::vector<double>& table, double code) {
  const double last = double(table.size() - 1);
  const double c = std::clamp(code, 0.0, last);
  const auto i = std::size_t(std::floor(c));
  if (double(i) >= last) return table.back();
  const double f = c - double(i);
  return table[i] + f * (table[i + 1] - table[i]);
}

// The fractional code whose table exposure is `exposure` (the table increases over the codes
// that carry information; flat stretches at the ends resolve to their first code).
double tableCode(const std::vector<double>& table, double exposure) {
  const auto it = std::lower_bound(table.begin(), table.end(), exposure);
  if (it == table.begin()) return 0.0;
  if (it == table.end()) return double(table.size() - 1);
  const auto i = std::size_t(std::distance(table.begin(), it));
  const double lo = table[i - 1];
  const double hi = table[i];
  return double(i - 1) + (hi > lo ? (exposure - lo) / (hi - lo) : 0.0);
}

}  // namespace

const char* responseModelName(const ResponseModel& model) {
  return std::visit(Overloaded{[](const LogResponse&) { return "log"; },
                               [](const LinearResponse&) { return "linear"; },
                               [](const TabulatedResponse&) { return "table"; }},
                    model);
}

double luminanceFromCode(const PhotometricCalibration& calibration, int channel, double code,
                         double exposureUs, double gain) {
  if (code <= calibration.blackLevelCode) return 0.0;
  const double c = std::min(code, calibration.saturationCode);
  const auto ch = std::size_t(channel);
  return std::visit(
      Overloaded{
          [&](const LogResponse& r) { return std::exp((c - r.aCode[ch]) / r.bCodePerLn[ch]); },
          [&](const LinearResponse& r) {
            return (c - calibration.blackLevelCode) /
                   (r.gainCodePerCdM2Us[ch] * exposureUs * gain);
          },
          [&](const TabulatedResponse& r) {
            return tableExposure(r.exposureByCode[ch], c) * r.scaleCdM2 / (exposureUs * gain);
          }},
      calibration.response);
}

double codeFromLuminance(const PhotometricCalibration& calibration, int channel,
                         double luminanceCdM2, double exposureUs, double gain) {
  const auto ch = std::size_t(channel);
  const double black = calibration.blackLevelCode;
  const double code = std::visit(
      Overloaded{[&](const LogResponse& r) {
                   return luminanceCdM2 > 0.0
                              ? r.aCode[ch] + r.bCodePerLn[ch] * std::log(luminanceCdM2)
                              : black;
                 },
                 [&](const LinearResponse& r) {
                   return black + r.gainCodePerCdM2Us[ch] * luminanceCdM2 * exposureUs * gain;
                 },
                 [&](const TabulatedResponse& r) {
                   return tableCode(r.exposureByCode[ch],
                                    luminanceCdM2 * exposureUs * gain / r.scaleCdM2);
                 }},
      calibration.response);
  return std::clamp(code, black, calibration.saturationCode);
}

CodeToLuminanceLut buildCodeToLuminanceLut(const PhotometricCalibration& calibration,
                                           PixelFormat format, double exposureUs, double gain) {
  CodeToLuminanceLut lut;
  lut.channels = format.channels;
  lut.size = format.maxCode() + 1u;
  lut.exposureUs = exposureUs;
  lut.gain = gain;
  lut.luminanceCdM2.resize(std::size_t(lut.channels) * lut.size);
  for (int c = 0; c < lut.channels; ++c) {
    float* row = lut.luminanceCdM2.data() + std::size_t(c) * lut.size;
    for (std::uint32_t code = 0; code < lut.size; ++code) {
      row[code] = float(luminanceFromCode(calibration, c, double(code), exposureUs, gain));
    }
  }
  return lut;
}

}  // namespace vem::calib
