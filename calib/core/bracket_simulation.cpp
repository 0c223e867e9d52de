#include "calib/core/bracket_simulation.h"

#include <cmath>

#include "util/contract.h"

namespace vem::calib {
namespace {

constexpr int kLdrCodes = 256;

// The sRGB decoding function: linear below 0.04045, a 2.4 power above.
double srgbToLinear(double y) {
  return y <= 0.04045 ? y / 12.92 : std::pow((y + 0.055) / 1.055, 2.4);
}

// Relative exposure of normalised code y in [0, 1], before normalisation at the mid code.
double ldrExposure(double y) { return srgbToLinear(y) / (1.0 - 0.8 * std::pow(y, 8.0)); }

}  // namespace

TabulatedResponse ldrCameraResponse(double scaleCdM2) {
  std::vector<double> table(kLdrCodes);
  const double mid = ldrExposure(double(kLdrMidCode) / 255.0);
  for (int code = 0; code < kLdrCodes; ++code) {
    table[std::size_t(code)] = ldrExposure(double(code) / 255.0) / mid;
  }
  TabulatedResponse response;
  response.exposureByCode = {table, table, table};
  response.scaleCdM2 = scaleCdM2;
  return response;
}

PhotometricCalibration ldrCameraPhotometric(double scaleCdM2) {
  return PhotometricCalibration{ldrCameraResponse(scaleCdM2), 0.0, 255.0};
}

double scaleForCode(const TabulatedResponse& response, int code, double luminanceCdM2,
                    double exposureUs) {
  VEM_EXPECTS(code > 0 && std::size_t(code) < response.exposureByCode[0].size());
  return luminanceCdM2 * exposureUs / response.exposureByCode[0][std::size_t(code)];
}

SensorNoise ldrSensorNoise(std::uint64_t seed) { return SensorNoise{0.8, 0.004, seed}; }

std::vector<RawFrame> simulateBracket(const RadianceFunction& radiance,
                                      const CameraCalibration& truth,
                                      std::span<const double> exposuresUs,
                                      const SimulationOptions& options) {
  std::vector<RawFrame> frames;
  frames.reserve(exposuresUs.size());
  for (std::size_t k = 0; k < exposuresUs.size(); ++k) {
    SimulationOptions frameOptions = options;
    frameOptions.exposureUs = exposuresUs[k];
    frameOptions.noise.seed = options.noise.seed + 0x9e3779b97f4a7c15ull * (k + 1);
    frames.push_back(simulateFrame(radiance, truth, frameOptions));
  }
  return frames;
}

}  // namespace vem::calib
