// Value noise: a deterministic, smooth random field over the plane for procedural clouds.
// Each integer lattice point (x, y) gets a value in [0, 1) from a permutation table shuffled by the
// seed (values[perm[perm[x mod 256] + y mod 256]], Perlin's hashing), so the field repeats every
// 256 cells along each axis; between lattice points the four corners are blended with the quintic
// fade 6t^5 - 15t^4 + 10t^3 (continuous value and slope). fractal() sums octaves of halving
// amplitude and doubling frequency (fBm), each shifted so their lattices do not line up, normalised
// back to [0, 1). The same point and seed always give the same value.
#pragma once

#include <array>
#include <cstdint>

#include <glm/vec2.hpp>

namespace vem::synth {

class ValueNoise {
 public:
  explicit ValueNoise(std::uint64_t seed);

  [[nodiscard]] double at(glm::dvec2 point) const;
  [[nodiscard]] double fractal(glm::dvec2 point, int octaves) const;

 private:
  [[nodiscard]] double lattice(int x, int y) const {
    return double(values_[perm_[std::size_t(perm_[std::size_t(x & 255)] + (y & 255))]]);
  }

  std::array<std::uint8_t, 512> perm_{};  // a permutation of 0 .. 255, twice
  std::array<float, 256> values_{};
};

}  // namespace vem::synth
