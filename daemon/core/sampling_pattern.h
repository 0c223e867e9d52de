// The sampling pattern: points in the unit square whose index is a light's identity across frames
// (paper 004 section 3.2). Point i starts as the 2D Halton point of index i + 1 (bases 2 and 3; the
// origin, index 0, is skipped) and is relaxed toward blue noise by Lloyd's method.
//
// Progressive relaxation, so that every prefix is itself a relaxed set and the first k points never
// depend on how many follow: points are relaxed in doubling levels [2^(L-1), 2^L), each level
// moving only its own points to the centroids of their Voronoi cells (cells among all points of
// index < 2^L) while earlier levels stay fixed. Centroids are estimated from `samplesPerPoint`
// evenly spread samples per point, nearest sites found through a kd-tree (nanoflann).
//
// Where the cells are measured:
// - RelaxationDomain::Square: in the unit square itself (paper 004 relaxes there);
// - RelaxationDomain::Surface: on the map's surface (sphere or hemisphere) reached through the
//   sampler's equal-area parameterisation (surface_parameterization.h), with geodesic-like
//   (chordal) distances, so the pattern is blue noise where the lights live; the points are mapped
//   back to the square afterwards. This is the default: measured in docs/sampling.md, it gives the
//   Havran sampler lower irradiance error than square relaxation.
// The patterns the lights use are precomputed at build time (default_pattern.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

#include "core/env_map.h"

namespace vem {

// Radical inverse of `index` in `base`: the van der Corput sequence.
[[nodiscard]] double radicalInverse(std::uint32_t base, std::uint64_t index);
// Halton point of pattern index i: (radicalInverse(2, i + 1), radicalInverse(3, i + 1)).
[[nodiscard]] glm::dvec2 haltonPoint(std::uint64_t patternIndex);
[[nodiscard]] std::vector<glm::dvec2> haltonPoints(std::size_t count);

enum class RelaxationDomain { Square, Surface };

struct LloydOptions {
  RelaxationDomain domain = RelaxationDomain::Surface;
  MapLayout layout = MapLayout::Sphere;  // the surface, for RelaxationDomain::Surface
  int iterations = 6;                    // Lloyd steps per level
  int samplesPerPoint = 16;              // density samples per point for the centroids
};

// The first `count` points of the progressive relaxed pattern. For count = 2^m the result is a
// prefix of the result for any larger power of two (bit for bit).
[[nodiscard]] std::vector<glm::dvec2> relaxedHaltonPattern(std::size_t count,
                                                           LloydOptions options = {});

}  // namespace vem
