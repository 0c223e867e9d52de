// The light probe's yaw in the plate camera's world (plate_camera.h, probeYawRad) from one distant
// marker that both cameras see, such as a lamp across the room or the sun: its pixel in the plate
// image gives its direction in the plate's world through the calibrated intrinsics and pose
// (worldDirectionFromPlate), and its direction in the probe's world is read from the probe's map.
// Both worlds share +Y (each camera's "up" is the world's); only the turn about +Y is unknown.
//
// Conventions (docs/conventions.md, daemon/core/env_map.h): directions are unit vectors from the
// scene outward; azimuth phi from +X toward +Z, elevation above the horizon (90 deg - theta).
// dir_plateWorld = RotY(yaw) * dir_probeWorld with RotY glm::rotate's right-handed turn about +Y;
// in azimuths, phi_plate = phi_probe - yaw, so yaw = phi_probe - phi_plate (wrapped to (-pi, pi]).
//
// Parallax: the two cameras stand a baseline b apart, so a marker at distance d is seen from them
// in directions up to asin(b / d) apart (markerParallaxRad); the marker must be distant: 1.1 deg
// for b = 2 m, d = 100 m; the sun's is nil.
#pragma once

#include <optional>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

namespace vem::calib {

// RotY(yawRad) as glm::rotate builds it: the probe's world turned into the plate's.
[[nodiscard]] glm::dmat3 plateWorldFromProbeWorld(double yawRad);

// The unit direction of an azimuth and elevation (radians), vemcast's convention.
[[nodiscard]] glm::dvec3 directionFromAzimuthElevation(double azimuthRad, double elevationRad);
// The azimuth in (-pi, pi] and elevation in [-pi/2, pi/2] of a direction (any length > 0).
[[nodiscard]] double azimuthRad(const glm::dvec3& dir);
[[nodiscard]] double elevationRad(const glm::dvec3& dir);

// The yaw that turns the marker's probe-world azimuth into its plate-world azimuth, in (-pi, pi];
// nullopt when either direction is within 1 degree of straight up or down (no azimuth to read).
[[nodiscard]] std::optional<double> probeYawFromMarker(const glm::dvec3& markerPlateWorld,
                                                       const glm::dvec3& markerProbeWorld);

// The largest angle between the directions two cameras `baselineM` apart see a marker
// `distanceM` away in: asin(b / d) (pi / 2 when b >= d).
[[nodiscard]] double markerParallaxRad(double baselineM, double distanceM);

}  // namespace vem::calib
