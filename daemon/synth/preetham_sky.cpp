#include "synth/preetham_sky.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "util/contract.h"

namespace vem::synth {
namespace {

constexpr int kThetaTableSize = 1024;
constexpr int kGammaTableSize = 2048;

// Linear interpolation of a table sampled uniformly over [0, 1].
double lookup(const std::vector<float>& table, double v) {
  const double f = std::clamp(v, 0.0, 1.0) * double(table.size() - 1);
  const int i = std::min(int(f), int(table.size()) - 2);  // int: a cheaper conversion than size_t
  const double t = f - double(i);
  const float* entry = table.data() + i;
  return double(entry[0]) * (1.0 - t) + double(entry[1]) * t;
}

// Appendix A.2: the zenith chromaticity, [T^2 T 1] M [theta^3 theta^2 theta 1]^T.
double zenithChromaticity(const double (&m)[3][4], double turbidity, double thetaSun) {
  const double th[4] = {thetaSun * thetaSun * thetaSun, thetaSun * thetaSun, thetaSun, 1.0};
  const double tv[3] = {turbidity * turbidity, turbidity, 1.0};
  double sum = 0.0;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c) sum += tv[r] * m[r][c] * th[c];
  }
  return sum;
}

constexpr double kZenithX[3][4] = {{0.00166, -0.00375, 0.00209, 0.0},
                                   {-0.02903, 0.06377, -0.03202, 0.00394},
                                   {0.11693, -0.21196, 0.06052, 0.25886}};
constexpr double kZenithY[3][4] = {{0.00275, -0.00610, 0.00317, 0.0},
                                   {-0.04214, 0.08970, -0.04153, 0.00516},
                                   {0.15346, -0.26756, 0.06670, 0.26688}};

}  // namespace

glm::dvec3 rgbFromXyY(double x, double y, double luminance) {
  if (!(y > 0.0) || !(luminance > 0.0)) return glm::dvec3(0.0);
  const double bigX = x * luminance / y;
  const double bigZ = (1.0 - x - y) * luminance / y;
  const glm::dvec3 rgb(3.2406 * bigX - 1.5372 * luminance - 0.4986 * bigZ,
                       -0.9689 * bigX + 1.8758 * luminance + 0.0415 * bigZ,
                       0.0557 * bigX - 0.2040 * luminance + 1.0570 * bigZ);
  return glm::max(rgb, glm::dvec3(0.0));
}

PreethamSky::PreethamSky(double turbidity) : turbidity_(turbidity) {
  VEM_EXPECTS(turbidity >= 1.7 && turbidity <= 10.0);
  const double t = turbidity;
  // Appendix A.2: the Perez coefficients of Y, x and y.
  perez_[0] = {0.1787 * t - 1.4630, -0.3554 * t + 0.4275, -0.0227 * t + 5.3251, 0.1206 * t - 2.5771,
               -0.0670 * t + 0.3703};
  perez_[1] = {-0.0193 * t - 0.2592, -0.0665 * t + 0.0008, -0.0004 * t + 0.2125,
               -0.0641 * t - 0.8989, -0.0033 * t + 0.0452};
  perez_[2] = {-0.0167 * t - 0.2608, -0.0950 * t + 0.0092, -0.0079 * t + 0.2102,
               -0.0441 * t - 1.6537, -0.0109 * t + 0.0529};
  for (std::size_t q = 0; q < 3; ++q) {
    const Perez& p = perez_[q];
    thetaFactor_[q].resize(kThetaTableSize);
    for (int i = 0; i < kThetaTableSize; ++i) {
      const double cosTheta = double(i) / (kThetaTableSize - 1);
      thetaFactor_[q][std::size_t(i)] =
          float(cosTheta > 0.0 ? 1.0 + p.a * std::exp(p.b / cosTheta) : 1.0);
    }
    gammaFactor_[q].resize(kGammaTableSize);
    for (int i = 0; i < kGammaTableSize; ++i) {
      const double gamma = 2.0 * std::asin(double(i) / (kGammaTableSize - 1));
      const double cosGamma = std::cos(gamma);
      gammaFactor_[q][std::size_t(i)] =
          float(1.0 + p.c * std::exp(p.d * gamma) + p.e * cosGamma * cosGamma);
    }
  }
}

double PreethamSky::perezExact(int quantity, double cosTheta, double gammaRad) const {
  const Perez& p = perez_[std::size_t(quantity)];
  const double cosGamma = std::cos(gammaRad);
  const double thetaPart = cosTheta > 0.0 ? 1.0 + p.a * std::exp(p.b / cosTheta) : 1.0;
  return thetaPart * (1.0 + p.c * std::exp(p.d * gammaRad) + p.e * cosGamma * cosGamma);
}

PreethamSky::SunTerms PreethamSky::sunTerms(const glm::dvec3& sunDir,
                                            double zenithLuminanceCdM2) const {
  VEM_EXPECTS(sunDir.y > 0.0);
  SunTerms terms;
  terms.sunDir = sunDir;
  terms.zenithLuminanceCdM2 = zenithLuminanceCdM2;
  const double thetaSun = std::acos(std::clamp(sunDir.y, -1.0, 1.0));
  terms.zenithValue = {zenithLuminanceCdM2, zenithChromaticity(kZenithX, turbidity_, thetaSun),
                       zenithChromaticity(kZenithY, turbidity_, thetaSun)};
  for (int q = 0; q < 3; ++q) {
    terms.invZenithF[std::size_t(q)] = 1.0 / perezExact(q, 1.0, thetaSun);
  }
  return terms;
}

glm::dvec3 PreethamSky::rgbFromF(const SunTerms& sun, const std::array<double, 3>& f) const {
  const double luminanceCdM2 = sun.zenithValue[0] * f[0] * sun.invZenithF[0];
  const double x = sun.zenithValue[1] * f[1] * sun.invZenithF[1];
  const double y = sun.zenithValue[2] * f[2] * sun.invZenithF[2];
  return rgbFromXyY(x, y, luminanceCdM2);
}

glm::dvec3 PreethamSky::radiance(const SunTerms& sun, const glm::dvec3& dir) const {
  const double cosTheta = std::max(dir.y, 0.0);
  // sin(gamma / 2) = |dir - sun| / 2 for unit vectors.
  const double sinHalfGamma = std::sqrt(std::max(0.0, 0.5 * (1.0 - glm::dot(dir, sun.sunDir))));
  std::array<double, 3> f{};
  for (std::size_t q = 0; q < 3; ++q) {
    f[q] = lookup(thetaFactor_[q], cosTheta) * lookup(gammaFactor_[q], sinHalfGamma);
  }
  return rgbFromF(sun, f);
}

glm::dvec3 PreethamSky::radianceExact(const SunTerms& sun, const glm::dvec3& dir) const {
  const double cosTheta = std::max(dir.y, 0.0);
  const double gamma = std::acos(std::clamp(glm::dot(dir, sun.sunDir), -1.0, 1.0));
  std::array<double, 3> f{};
  for (int q = 0; q < 3; ++q) f[std::size_t(q)] = perezExact(q, cosTheta, gamma);
  return rgbFromF(sun, f);
}

}  // namespace vem::synth
