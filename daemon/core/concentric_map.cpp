#include "core/concentric_map.h"

#include <cmath>
#include <numbers>

namespace vem {
namespace {
constexpr double kQuarterPi = std::numbers::pi / 4;
}

DiskPoint diskFromSquare(glm::dvec2 square) {
  const double a = 2 * square.x - 1;
  const double b = 2 * square.y - 1;
  if (a == 0 && b == 0) return {};
  double rho = 0;
  double psi = 0;
  if (a * a > b * b) {
    rho = a;
    psi = kQuarterPi * (b / a);
  } else {
    rho = b;
    psi = 2 * kQuarterPi - kQuarterPi * (a / b);
  }
  if (rho < 0) {
    rho = -rho;
    psi += std::numbers::pi;
  }
  if (psi < 0) psi += 2 * std::numbers::pi;
  if (psi >= 2 * std::numbers::pi) psi -= 2 * std::numbers::pi;
  return {rho, psi};
}

glm::dvec2 squareFromDisk(DiskPoint disk) {
  double psi = disk.psi;
  if (psi > 7 * kQuarterPi) psi -= 2 * std::numbers::pi;  // now in (-pi/4, 7 pi/4]
  const double rho = disk.rho;
  double a = 0;
  double b = 0;
  if (psi <= kQuarterPi) {  // right wedge
    a = rho;
    b = rho * psi / kQuarterPi;
  } else if (psi <= 3 * kQuarterPi) {  // top wedge
    b = rho;
    a = rho * (2 * kQuarterPi - psi) / kQuarterPi;
  } else if (psi <= 5 * kQuarterPi) {  // left wedge
    a = -rho;
    b = -rho * (psi - std::numbers::pi) / kQuarterPi;
  } else {  // bottom wedge
    b = -rho;
    a = -rho * (6 * kQuarterPi - psi) / kQuarterPi;
  }
  return {0.5 * (a + 1), 0.5 * (b + 1)};
}

}  // namespace vem
