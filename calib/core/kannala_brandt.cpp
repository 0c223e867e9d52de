#include "calib/core/kannala_brandt.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vem::calib {

double KannalaBrandtLens::radiusPx(double thetaRad) const {
  const double t2 = thetaRad * thetaRad;
  // Horner in theta^2: theta (k1 + t2 (k2 + t2 (k3 + t2 (k4 + t2 k5)))).
  return thetaRad * (kPx[0] + t2 * (kPx[1] + t2 * (kPx[2] + t2 * (kPx[3] + t2 * kPx[4]))));
}

double KannalaBrandtLens::radiusDerivativePx(double thetaRad) const {
  const double t2 = thetaRad * thetaRad;
  return kPx[0] + t2 * (3.0 * kPx[1] + t2 * (5.0 * kPx[2] + t2 * (7.0 * kPx[3] + t2 * 9.0 * kPx[4])));
}

std::optional<double> KannalaBrandtLens::thetaFromRadius(double radius) const {
  if (!(radius >= 0.0)) return std::nullopt;
  const double rMax = radiusPx(maxThetaRad);
  // A direction at exactly maxThetaRad projects to rMax up to rounding: accept that much slack.
  if (radius > rMax * (1.0 + 1e-12)) return std::nullopt;
  if (radius >= rMax) return maxThetaRad;
  // r is increasing on [0, maxTheta] (lensDefect): Newton from the linear guess, kept inside a
  // bracket that shrinks with every step, so it cannot leave the monotone range.
  double lo = 0.0;
  double hi = maxThetaRad;
  double theta = std::clamp(radius / kPx[0], lo, hi);
  for (int i = 0; i < 50; ++i) {
    const double f = radiusPx(theta) - radius;
    if (f > 0.0) {
      hi = theta;
    } else {
      lo = theta;
    }
    const double d = radiusDerivativePx(theta);
    double next = theta - f / d;
    if (std::abs(next - theta) < 1e-14) return next;  // converged (before any bisection step)
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    theta = next;
  }
  return theta;
}

std::optional<glm::dvec2> KannalaBrandtLens::sensorFromCamera(const glm::dvec3& dirCamera) const {
  const double rho = std::hypot(dirCamera.x, dirCamera.y);
  const double theta = std::atan2(rho, dirCamera.z);
  if (!(theta <= maxThetaRad)) return std::nullopt;
  if (rho == 0.0) return principalPointPx;
  const double r = radiusPx(theta);
  return glm::dvec2(principalPointPx.x + r * dirCamera.x / rho,
                    principalPointPx.y + aspect * r * dirCamera.y / rho);
}

std::optional<glm::dvec3> KannalaBrandtLens::cameraFromSensor(const glm::dvec2& sensorPx) const {
  const double du = sensorPx.x - principalPointPx.x;
  const double dv = (sensorPx.y - principalPointPx.y) / aspect;
  const double r = std::hypot(du, dv);
  if (r == 0.0) return glm::dvec3(0.0, 0.0, 1.0);
  const std::optional<double> theta = thetaFromRadius(r);
  if (!theta) return std::nullopt;
  const double s = std::sin(*theta) / r;
  return glm::dvec3(s * du, s * dv, std::cos(*theta));
}

std::optional<const char*> lensDefect(const KannalaBrandtLens& lens) {
  for (double k : lens.kPx) {
    if (!std::isfinite(k)) return "a coefficient k is not a finite number";
  }
  if (!(lens.kPx[0] > 0.0)) return "k1 must be positive (pixels per radian at the centre)";
  if (!(lens.aspect > 0.0) || !std::isfinite(lens.aspect)) return "aspect must be positive";
  if (!std::isfinite(lens.principalPointPx.x) || !std::isfinite(lens.principalPointPx.y)) {
    return "the principal point is not finite";
  }
  if (!(lens.maxThetaRad > 0.0 && lens.maxThetaRad <= std::numbers::pi)) {
    return "max_theta must lie in (0, 180] degrees";
  }
  constexpr int kSteps = 512;
  for (int i = 0; i <= kSteps; ++i) {
    const double theta = lens.maxThetaRad * i / kSteps;
    if (!(lens.radiusDerivativePx(theta) > 0.0)) {
      return "r(theta) stops increasing before max_theta: the lens would fold the image";
    }
  }
  return std::nullopt;
}

KannalaBrandtLens equidistantLens(int width, int height, double fovDeg, double circleRadiusPx) {
  KannalaBrandtLens lens;
  lens.maxThetaRad = 0.5 * fovDeg * std::numbers::pi / 180.0;
  lens.kPx = {circleRadiusPx / lens.maxThetaRad, 0.0, 0.0, 0.0, 0.0};
  lens.principalPointPx = {0.5 * (width - 1), 0.5 * (height - 1)};
  lens.aspect = 1.0;
  return lens;
}

}  // namespace vem::calib
