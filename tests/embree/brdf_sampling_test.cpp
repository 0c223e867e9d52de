// brdf_sampling.h: each density integrates to one and matches its sampler (the estimate of the
// directional albedo with f cos / pdf agrees with a numerical integral).
#include "client/embree/brdf_sampling.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include "client/embree/sample_rng.h"
#include "embree/embree_fixtures.h"

namespace vem::embree {
namespace {

scene::Material lobeMaterial(scene::Lobe lobe, float exponent, float roughness) {
  scene::Material m = testing::lambertian(0.3F);
  m.lobe = lobe;
  m.specularAlbedo = glm::vec3(0.6F);
  m.exponent = exponent;
  m.roughness = roughness;
  return m;
}

glm::vec3 sphereDirection(double cosTheta, double phi) {
  const double s = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
  return glm::vec3(glm::dvec3(s * std::cos(phi), cosTheta, s * std::sin(phi)));
}

double integrateOverSphere(const std::function<double(glm::vec3)>& g, int steps) {
  double sum = 0.0;
  for (int i = 0; i < steps; ++i) {
    for (int j = 0; j < 2 * steps; ++j) {
      sum +=
          g(sphereDirection(-1.0 + 2.0 * (i + 0.5) / steps, std::numbers::pi * (j + 0.5) / steps));
    }
  }
  return sum * (2.0 / steps) * (std::numbers::pi / steps);
}

const scene::Material kMaterials[] = {
    testing::lambertian(0.5F),
    lobeMaterial(scene::Lobe::Phong, 30.0F, 1.0F),
    lobeMaterial(scene::Lobe::Blinn, 30.0F, 1.0F),
    lobeMaterial(scene::Lobe::Ggx, 0.0F, 0.5F),
};

TEST(BrdfSampling, EveryDensityIntegratesToOne) {
  const glm::vec3 wo = glm::normalize(glm::vec3(0.5F, 0.8F, 0.1F));
  for (const scene::Material& m : kMaterials) {
    const BrdfLobes lobes{&m, true, glm::vec3(0.0F, 1.0F, 0.0F), wo};
    const double total =
        integrateOverSphere([&](glm::vec3 wi) { return double(brdfPdfSr(lobes, wi)); }, 1000);
    EXPECT_NEAR(total, 1.0, 5e-3) << scene::lobeName(m.lobe);
  }
}

// A sampler that does not draw from its stated density biases the reference: f cos / pdf
// averaged over its samples must give the albedo that direct integration gives.
TEST(BrdfSampling, SamplerDrawsFromItsDensity) {
  const glm::vec3 n(0.0F, 1.0F, 0.0F);
  const glm::vec3 wo = glm::normalize(glm::vec3(0.5F, 0.8F, 0.1F));
  for (const scene::Material& m : kMaterials) {
    const BrdfLobes lobes{&m, true, n, wo};
    const auto integrand = [&](glm::vec3 wi) {
      return double(brdfValue(lobes, wi).y) * std::max(0.0, double(glm::dot(n, wi)));
    };
    const double exact = integrateOverSphere(integrand, 1000);
    double sum = 0.0;
    constexpr int kSamples = 200000;
    for (int k = 0; k < kSamples; ++k) {
      SampleRng rng(7, 0, std::uint64_t(k));
      const glm::vec3 wi =
          sampleBrdfDirection(lobes, {rng.nextFloat(), rng.nextFloat(), rng.nextFloat()});
      const double pdf = double(brdfPdfSr(lobes, wi));
      ASSERT_GT(pdf, 0.0);
      sum += integrand(wi) / pdf;
    }
    EXPECT_NEAR(sum / kSamples, exact, 0.01 * exact) << scene::lobeName(m.lobe);
  }
}

}  // namespace
}  // namespace vem::embree
