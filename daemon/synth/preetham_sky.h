// The clear-sky model of Preetham, Shirley and Smits, "A Practical Analytic Model for Daylight"
// (SIGGRAPH 1999), section 2.2 and appendix A.2: the sky's luminance Y and chromaticity (x, y) at a
// view direction are the zenith's times the Perez distribution F(theta, gamma) / F(0, theta_sun),
//     F(theta, gamma) = (1 + A exp(B / cos theta)) (1 + C exp(D gamma) + E cos^2 gamma),
// with coefficients A..E linear in the turbidity T, and the zenith chromaticity a polynomial in T
// and the sun's zenith angle. theta is the view's angle from the zenith, gamma its angle from the
// sun.
//
// Departure from the paper: the zenith luminance is not Preetham's formula (kcd/m^2 of a real sky)
// but a parameter of the caller (synthetic scenes scale the whole sky to fit a camera's range).
// Both factors of F depend on T only, so they are tabulated once (the first over cos theta, the
// second over sin(gamma / 2)) and interpolated linearly: a direction then costs two table reads per
// quantity, no exp or acos (relative error below 1e-4 against the closed form).
//
// Conventions: world frame of daemon/core/env_map.h (+Y up); directions are unit vectors; radiance
// in linear Rec. 709 RGB whose luminance (core/color.h) is Y. Directions below the horizon read as
// the horizon (the caller puts a ground there).
#pragma once

#include <array>
#include <vector>

#include <glm/vec3.hpp>

namespace vem::synth {

class PreethamSky {
 public:
  // turbidity in [1.7, 10] (2: very clear, 3: clear, 6: hazy).
  explicit PreethamSky(double turbidity);

  // What one sun position fixes: the zenith's chromaticity and F(0, theta_sun) per quantity.
  struct SunTerms {
    glm::dvec3 sunDir{0.0, 1.0, 0.0};
    double zenithLuminanceCdM2 = 1.0;
    std::array<double, 3> zenithValue{};  // Y (cd/m^2), x, y at the zenith
    std::array<double, 3> invZenithF{};   // 1 / F(0, theta_sun) for Y, x, y
  };
  // sunDir unit, above the horizon (sunDir.y > 0).
  [[nodiscard]] SunTerms sunTerms(const glm::dvec3& sunDir, double zenithLuminanceCdM2) const;

  // Sky radiance (cd/m^2 per channel) toward `dir`, from the tables.
  [[nodiscard]] glm::dvec3 radiance(const SunTerms& sun, const glm::dvec3& dir) const;
  // The same from the closed form (exp, acos): the tables' reference, for tests.
  [[nodiscard]] glm::dvec3 radianceExact(const SunTerms& sun, const glm::dvec3& dir) const;

  [[nodiscard]] double turbidity() const { return turbidity_; }

 private:
  struct Perez {
    double a, b, c, d, e;
  };
  [[nodiscard]] double perezExact(int quantity, double cosTheta, double gammaRad) const;
  [[nodiscard]] glm::dvec3 rgbFromF(const SunTerms& sun, const std::array<double, 3>& f) const;

  double turbidity_;
  std::array<Perez, 3> perez_;                     // Y, x, y
  std::array<std::vector<float>, 3> thetaFactor_;  // over cos theta in [0, 1]
  std::array<std::vector<float>, 3> gammaFactor_;  // over sin(gamma / 2) in [0, 1]
};

// Linear Rec. 709 RGB of CIE xyY (negative channels, outside the gamut, clamped to 0).
[[nodiscard]] glm::dvec3 rgbFromXyY(double x, double y, double luminance);

}  // namespace vem::synth
