#include "synth/sensor_code_table.h"

#include <cmath>

namespace vem::synth {

SensorCodeTable::SensorCodeTable(const calib::PhotometricCalibration& photometric,
                                 PixelFormat format, double exposureUs, double gain)
    : photometric_(photometric), exposureUs_(exposureUs), gain_(gain) {
  constexpr double kTolerance = 0.01;  // codes
  for (int c = 0; c < format.channels; ++c) {
    const auto code = [&](double luminance) {
      return calib::codeFromLuminance(photometric, c, luminance, exposureUs, gain);
    };
    std::vector<float>& edges = edges_[std::size_t(c)];
    edges.resize(kHighestKey - kLowestKey + 1);
    const auto edgeLuminance = [](std::size_t edge) {
      return double(std::bit_cast<float>((kLowestKey + std::uint32_t(edge)) << kShift));
    };
    for (std::size_t edge = 0; edge < edges.size(); ++edge) {
      edges[edge] = float(code(edgeLuminance(edge)));
    }
    std::vector<std::uint8_t>& exact = exactBins_[std::size_t(c)];
    exact.assign(edges.size(), 0);
    for (std::size_t bin = 0; bin + 1 < edges.size(); ++bin) {
      const double low = edgeLuminance(bin);
      const double high = edgeLuminance(bin + 1);
      for (const double t : {0.25, 0.5, 0.75}) {
        const double interpolated = double(edges[bin]) + double(edges[bin + 1] - edges[bin]) * t;
        if (std::abs(interpolated - code(low + (high - low) * t)) > kTolerance) exact[bin] = 1;
      }
    }
    darkCode_[std::size_t(c)] = float(code(0.0));
    brightCode_[std::size_t(c)] = edges.back();
  }
}

float SensorCodeTable::exactCode(int channel, float luminanceCdM2) const {
  return float(
      calib::codeFromLuminance(photometric_, channel, double(luminanceCdM2), exposureUs_, gain_));
}

}  // namespace vem::synth
