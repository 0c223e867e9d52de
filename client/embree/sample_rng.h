// SampleRng: the reference renderer's counter-based random numbers. A generator is keyed by
// (seed, pixel, sample index) and then steps SplitMix64 (Steele, Lea and Flood 2014), so every
// sample's numbers are fixed by its key alone: images do not depend on threads or pass sizes.
#pragma once

#include <cstdint>

namespace vem::embree {

class SampleRng {
 public:
  SampleRng(std::uint64_t seed, std::uint64_t pixel, std::uint64_t sample)
      : state_(
            mix(seed ^ mix(pixel * 0x9E3779B97F4A7C15ULL ^ mix(sample + 0x632BE59BD9B4E019ULL)))) {}

  // Uniform in [0, 1), 53 bits.
  [[nodiscard]] double nextDouble() { return double(next() >> 11U) * 0x1.0p-53; }
  // Uniform in [0, 1), 24 bits (never rounds up to 1).
  [[nodiscard]] float nextFloat() { return float(next() >> 40U) * 0x1.0p-24F; }

 private:
  static std::uint64_t mix(std::uint64_t z) {
    z = (z ^ (z >> 30U)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27U)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31U);
  }
  std::uint64_t next() {
    state_ += 0x9E3779B97F4A7C15ULL;
    return mix(state_);
  }

  std::uint64_t state_;
};

}  // namespace vem::embree
