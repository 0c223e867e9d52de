// The equal-area octahedral map between the unit square and the sphere (Clarberg 2008, "Fast
// equal-area mapping of the (hemi)sphere using SIMD"): the sphere parameterisation the Havran
// sampler uses for full-sphere maps. Continuous, equal-area, bijective on the open square, with far
// less distortion near the south pole than a disk whose whole rim collapses to the nadir.
//
// Square (u, v) in [0, 1]^2, a = 2u - 1, b = 2v - 1, d = |a| + |b|: the inner diamond d <= 1 is
// the upper hemisphere (centre = zenith), the four corner triangles the lower one (corners =
// nadir); opposite halves of each square edge fold onto the same meridian. Rather than a point on
// the sphere this returns the sampler's cylinder coordinates: the area fraction from the zenith s =
// (1 - cos theta) / 2 in [0, 1] and the azimuth fraction w = azimuth / 2 pi in [0, 1) (azimuth 0
// along the square's +a half-axis, increasing toward +b).
#pragma once

#include <glm/vec2.hpp>

namespace vem {

struct CylinderPoint {
  double s = 0.0;  // area fraction from the zenith, [0, 1]
  double w = 0.0;  // azimuth fraction, [0, 1)
};

[[nodiscard]] CylinderPoint cylinderFromSquareOctahedral(glm::dvec2 square);
[[nodiscard]] glm::dvec2 squareFromCylinderOctahedral(CylinderPoint point);

}  // namespace vem
