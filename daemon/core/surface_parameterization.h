// How the Havran sampler's unit square covers the map's surface under uniform importance, through
// "cylinder coordinates" (s, w): s in [0, 1] the area fraction from the zenith,
// s = (1 - cos theta) / (1 - cos theta_max), and w in [0, 1) the azimuth fraction.
// - Hemisphere (the camera's polar map): the concentric map to the unit disk (rho, psi), then
//   s = rho^2 and w = psi / 2 pi, as in paper 004 section 3.1.
// - Sphere: the equal-area octahedral map (octahedral_map.h); a disk whose rim collapsed to the
// nadir
//   would be equal-area too, but its strata near the nadir are long slivers.
// Both are continuous and equal-area: uniform points in the square are uniform on the surface.
// The samplers then warp s and w through the map's cumulative tables; with a uniform map they land
// at surfaceDirection(s, w) up to the map's azimuth offset.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/env_map.h"
#include "core/octahedral_map.h"

namespace vem {

[[nodiscard]] CylinderPoint cylinderFromSquare(MapLayout layout, glm::dvec2 square);
[[nodiscard]] glm::dvec2 squareFromCylinder(MapLayout layout, CylinderPoint point);

// The unit direction of cylinder point (s, w) with azimuth 2 pi w measured from +X toward +Z, and
// back. Used to relax the pattern on the surface (sampling_pattern.h).
[[nodiscard]] glm::dvec3 surfaceDirection(MapLayout layout, CylinderPoint point);
[[nodiscard]] CylinderPoint cylinderFromSurfaceDirection(MapLayout layout, glm::dvec3 dir);

}  // namespace vem
