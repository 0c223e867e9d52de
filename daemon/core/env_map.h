// EnvMap: an HDR environment map as the lighting core sees it, and its pixel geometry.
//
// Conventions (docs/conventions.md repeats them):
// - World frame: right-handed, +Y up. A direction is a unit vector from the scene outward.
// - Angles: theta is measured from the zenith +Y; phi is the azimuth, and
//     dir = (sin theta cos phi, cos theta, sin theta sin phi),
//   so phi = 0 faces +X and phi = pi/2 faces +Z.
// - MapLayout::Sphere is an equirectangular W x H map of the full sphere (HDRI files): the centre
// of
//   pixel (x, y) has u = (x + 0.5) / W, theta = pi (y + 0.5) / H, phi = 2 pi (u - 0.5).
//   Row 0 is the zenith; the centre column faces +X; the left and right edges are phi = -pi = +pi.
// - MapLayout::Hemisphere is the camera's polar map of the upper hemisphere: W columns over
//   phi in [0, 2 pi), H rows over theta in [0, pi/2]; pixel (x, y) has its centre at
//   phi = 2 pi (x + 0.5) / W, theta = (pi / 2) (y + 0.5) / H. Row 0 is the zenith, the last row the
//   horizon; the left and right edges are phi = 0.
// - Pixels hold linear RGB radiance in the map's units (relative, or cd/m^2 per channel-luminance
//   once calibrated), row-major, three floats per pixel.
//
// Both layouts share one parameterisation used by the samplers: the column coordinate
// xc in [0, W] (xc = x + 0.5 at a pixel centre) gives psi = 2 pi xc / W in [0, 2 pi); the row
// coordinate yc in [0, H] gives theta. phi = psi - pi (Sphere) or phi = psi (Hemisphere).
#pragma once

#include <cstddef>
#include <vector>

#include <glm/vec3.hpp>

namespace vem {

enum class MapLayout { Sphere, Hemisphere };

[[nodiscard]] const char* layoutName(MapLayout layout);

struct EnvMap {
  MapLayout layout = MapLayout::Sphere;
  int width = 0;           // columns, over the azimuth
  int height = 0;          // rows, over theta from the zenith
  std::vector<float> rgb;  // width * height * 3 floats, row-major, row 0 at the zenith

  [[nodiscard]] static EnvMap filled(MapLayout layout, int width, int height, glm::vec3 value);

  [[nodiscard]] std::size_t pixelCount() const { return std::size_t(width) * std::size_t(height); }
  [[nodiscard]] glm::vec3 at(int x, int y) const;
  void set(int x, int y, glm::vec3 value);
};

// Largest theta the layout covers: pi (Sphere) or pi / 2 (Hemisphere).
[[nodiscard]] double thetaMaxRad(MapLayout layout);
// Solid angle the layout covers: 4 pi or 2 pi.
[[nodiscard]] double coveredSolidAngleSr(MapLayout layout);

[[nodiscard]] glm::dvec3 directionFromAngles(double thetaRad, double phiRad);
// Azimuth phi of the column coordinate xc in [0, W].
[[nodiscard]] double phiFromColumnCoord(MapLayout layout, int width, double xc);
// Polar angle theta of the row coordinate yc in [0, H].
[[nodiscard]] double thetaFromRowCoord(MapLayout layout, int height, double yc);
[[nodiscard]] glm::dvec3 pixelCentreDirection(const EnvMap& map, int x, int y);
// Exact solid angle of one pixel of row y: (2 pi / W) (cos theta_top - cos theta_bottom).
[[nodiscard]] double pixelSolidAngleSr(MapLayout layout, int width, int height, int y);

}  // namespace vem
