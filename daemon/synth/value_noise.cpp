#include "synth/value_noise.h"

#include <cmath>
#include <numeric>
#include <utility>

#include <glm/common.hpp>

namespace vem::synth {
namespace {

// splitmix64: the sequence depends only on the seed.
std::uint64_t nextRandom(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

constexpr double kLimit = 0x1p52;
constexpr glm::dvec2 kOctaveShift(17.37, 31.71);

// floor() for |x| < 2^62 without a call into libm (x86-64 has no inline floor before SSE4.1).
double floorOf(double x) {
  const double truncated = double(std::int64_t(x));
  return truncated > x ? truncated - 1.0 : truncated;
}

double fade(double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }

}  // namespace

ValueNoise::ValueNoise(std::uint64_t seed) {
  std::uint64_t state = seed;
  std::array<std::uint8_t, 256> order{};
  std::iota(order.begin(), order.end(), std::uint8_t(0));
  for (std::size_t i = order.size() - 1; i > 0; --i) {  // Fisher-Yates
    std::swap(order[i], order[nextRandom(state) % (i + 1)]);
  }
  for (std::size_t i = 0; i < perm_.size(); ++i) perm_[i] = order[i % 256];
  for (float& value : values_) value = float(double(nextRandom(state) >> 11) * 0x1.0p-53);
}

double ValueNoise::at(glm::dvec2 point) const {
  // Far beyond any use (the field repeats every 256 cells), but keeps the conversions defined.
  point = glm::clamp(point, glm::dvec2(-kLimit), glm::dvec2(kLimit));
  const double fx = floorOf(point.x);
  const double fy = floorOf(point.y);
  const int x = int(std::int64_t(fx) & 255);  // two's complement: the cell modulo 256
  const int y = int(std::int64_t(fy) & 255);
  const double tx = fade(point.x - fx);
  const double ty = fade(point.y - fy);
  const double v00 = lattice(x, y);
  const double v10 = lattice(x + 1, y);
  const double v01 = lattice(x, y + 1);
  const double v11 = lattice(x + 1, y + 1);
  const double bottom = v00 + (v10 - v00) * tx;
  const double top = v01 + (v11 - v01) * tx;
  return bottom + (top - bottom) * ty;
}

double ValueNoise::fractal(glm::dvec2 point, int octaves) const {
  double sum = 0.0;
  double amplitude = 1.0;
  double total = 0.0;
  for (int i = 0; i < octaves; ++i) {
    sum += amplitude * at(point + kOctaveShift * double(i));
    total += amplitude;
    amplitude *= 0.5;
    point *= 2.0;
  }
  return total > 0.0 ? sum / total : 0.0;
}

}  // namespace vem::synth
