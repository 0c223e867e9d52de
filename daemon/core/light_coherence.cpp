#include "core/light_coherence.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/color.h"

namespace vem {
namespace {

bool lit(const Light& light) { return luminance(light.rgb) > 0.0; }

// The angle between two unit vectors, accurate also for tiny angles (atan2 of |a x b| and a . b,
// where acos of the dot product loses everything below about 1e-4 rad in float input).
double angleDeg(const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 c(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
  const double sine = std::sqrt(c.x * c.x + c.y * c.y + c.z * c.z);
  const double cosine = a.x * b.x + a.y * b.y + a.z * b.z;
  return std::atan2(sine, cosine) * 180.0 / std::numbers::pi;
}

glm::dvec3 unit(const glm::vec3& v) {
  const glm::dvec3 d(v);
  const double length = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
  return length > 0.0 ? d / length : d;
}

}  // namespace

void appendAngularStepsDeg(const LightSet& previous, const LightSet& current,
                           const glm::dmat3& motion, std::vector<double>& stepsDeg) {
  // Sets from the sampler and the filter list lights in id order; index the previous set by id so
  // that any order works.
  std::uint32_t largestId = 0;
  for (const Light& light : previous.lights) largestId = std::max(largestId, light.id);
  std::vector<const Light*> byId(std::size_t(largestId) + 1, nullptr);
  for (const Light& light : previous.lights) byId[light.id] = &light;
  for (const Light& now : current.lights) {
    if (now.id > largestId || !lit(now)) continue;
    const Light* before = byId[now.id];
    if (before == nullptr || !lit(*before)) continue;
    stepsDeg.push_back(angleDeg(motion * unit(before->dir), unit(now.dir)));
  }
}

StepSummary summariseSteps(std::vector<double> stepsDeg) {
  StepSummary s;
  s.count = stepsDeg.size();
  if (stepsDeg.empty()) return s;
  std::sort(stepsDeg.begin(), stepsDeg.end());
  // Nearest rank: the smallest value with at least p of the steps at or below it.
  const auto rank = [&](double p) {
    const auto k = std::size_t(std::ceil(p * double(stepsDeg.size())));
    return stepsDeg[std::clamp<std::size_t>(k, 1, stepsDeg.size()) - 1];
  };
  s.medianDeg = rank(0.5);
  s.p99Deg = rank(0.99);
  s.maxDeg = stepsDeg.back();
  const auto large = std::size_t(stepsDeg.end() -
                                 std::upper_bound(stepsDeg.begin(), stepsDeg.end(), kLargeStepDeg));
  s.fractionLarge = double(large) / double(stepsDeg.size());
  return s;
}

std::vector<double> luminances(std::span<const glm::dvec3> rgb) {
  std::vector<double> y;
  y.reserve(rgb.size());
  for (const glm::dvec3& v : rgb) y.push_back(luminance(v));
  return y;
}

}  // namespace vem
