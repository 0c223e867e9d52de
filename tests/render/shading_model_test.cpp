// The shading model (render/shading_model.h) against closed forms: white-furnace integrals of each
// lobe times the cosine over the hemisphere, reciprocity, and the mirror reflectance.
#include "client/render/shading_model.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>
#include <glm/glm.hpp>

namespace vem::render {
namespace {

constexpr double kPi = std::numbers::pi;
const glm::vec3 kUp(0.0F, 1.0F, 0.0F);

glm::vec3 directionAt(double cosTheta, double phi) {
  const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
  return glm::vec3(glm::dvec3(sinTheta * std::cos(phi), cosTheta, sinTheta * std::sin(phi)));
}

// Integral of f(wi, wo) (n . wi) over the upper hemisphere (midpoint rule in cos theta and phi),
// green channel: the directional albedo toward wo.
double hemisphereAlbedo(const scene::Material& m, glm::vec3 wo, bool withDiffuse,
                        int steps = 1200) {
  double sum = 0.0;
  const double dc = 1.0 / steps;
  const double dphi = 2.0 * kPi / (2 * steps);
  for (int i = 0; i < steps; ++i) {
    const double c = (i + 0.5) * dc;
    for (int j = 0; j < 2 * steps; ++j) {
      const glm::vec3 wi = directionAt(c, (j + 0.5) * dphi);
      glm::vec3 f = specularBrdf(m, kUp, wo, wi);
      if (withDiffuse) {
        f += diffuseBrdf(m);
      }
      sum += double(f.y) * c;
    }
  }
  return sum * dc * dphi;
}

scene::Material lobeMaterial(scene::Lobe lobe, float specular, float exponent, float roughness) {
  scene::Material m;
  m.diffuseAlbedo = glm::vec3(0.0F);
  m.lobe = lobe;
  m.specularAlbedo = glm::vec3(specular);
  m.exponent = exponent;
  m.roughness = roughness;
  return m;
}

TEST(ShadingModel, LambertianDiffuseIntegratesToItsAlbedo) {
  scene::Material m;
  m.diffuseAlbedo = glm::vec3(0.3F, 0.5F, 0.7F);
  EXPECT_NEAR(hemisphereAlbedo(m, kUp, true, 400), 0.5, 1e-4);
  EXPECT_NEAR(double(diffuseBrdf(m).x), 0.3 / kPi, 1e-7);
}

TEST(ShadingModel, PhongNormalisationReflectsItsAlbedoAtNormalIncidence) {
  for (const float exponent : {1.0F, 10.0F, 100.0F}) {
    const scene::Material m = lobeMaterial(scene::Lobe::Phong, 0.6F, exponent, 1.0F);
    EXPECT_NEAR(hemisphereAlbedo(m, kUp, false), 0.6, 0.003) << "exponent " << exponent;
  }
}

// Energy: no Phong lobe reflects more than its specular albedo and no GGX lobe with F0 = 1 (a white
// furnace) more than all of it, from any view direction.
TEST(ShadingModel, NoLobeCreatesEnergyFromAnyViewDirection) {
  const scene::Material lobes[] = {
      lobeMaterial(scene::Lobe::Phong, 1.0F, 5.0F, 1.0F),
      lobeMaterial(scene::Lobe::Phong, 1.0F, 80.0F, 1.0F),
      lobeMaterial(scene::Lobe::Ggx, 1.0F, 0.0F, 0.4F),
      lobeMaterial(scene::Lobe::Ggx, 1.0F, 0.0F, 1.0F),
  };
  for (const scene::Material& m : lobes) {
    for (const double cosView : {1.0, 0.7, 0.3, 0.05}) {
      const double albedo = hemisphereAlbedo(m, directionAt(cosView, 0.4), false, 600);
      EXPECT_LE(albedo, 1.0 + 2e-3) << scene::lobeName(m.lobe) << " e " << m.exponent << " r "
                                    << m.roughness << " cos " << cosView;
      EXPECT_GT(albedo, 0.0);
    }
  }
}

// A smooth GGX lobe with F0 = 1 loses little energy at normal incidence (Smith G shadows only a
// little); a broken D or G normalisation gives far more or far less.
TEST(ShadingModel, GgxWhiteFurnaceIsNearOneWhenSmooth) {
  const scene::Material m = lobeMaterial(scene::Lobe::Ggx, 1.0F, 0.0F, 0.4F);
  const double albedo = hemisphereAlbedo(m, kUp, false);
  EXPECT_GT(albedo, 0.95);
  EXPECT_LE(albedo, 1.0 + 1e-3);
}

// Blinn's (e + 8) / (8 pi) normalisation (scene.h) is the usual approximation, not exact: at normal
// incidence the lobe reflects ks (e + 8) / 2 (k + 2^-(k + 1)) / ((k + 1) (k + 2)), k = e / 2, which
// exceeds ks for e > 4 by at most 7.4 % (near e = 11) and tends to ks (1 + 2 / e). A wrong
// exponent or constant misses this closed form.
TEST(ShadingModel, BlinnNormalisationMatchesItsClosedFormAtNormalIncidence) {
  for (const float exponent : {1.0F, 4.0F, 11.0F, 40.0F}) {
    const scene::Material m = lobeMaterial(scene::Lobe::Blinn, 0.5F, exponent, 1.0F);
    const double k = double(exponent) / 2.0;
    const double closed = 0.5 * (double(exponent) + 8.0) / 2.0 * (k + std::pow(2.0, -(k + 1.0))) /
                          ((k + 1) * (k + 2));
    EXPECT_NEAR(hemisphereAlbedo(m, kUp, false), closed, 1e-3) << "exponent " << exponent;
    EXPECT_LE(closed, 0.5 * 1.075);
  }
}

TEST(ShadingModel, BlinnStaysWithinItsApproximationBoundFromAnyViewDirection) {
  for (const float exponent : {4.0F, 11.0F, 60.0F}) {
    const scene::Material m = lobeMaterial(scene::Lobe::Blinn, 1.0F, exponent, 1.0F);
    for (const double cosView : {1.0, 0.7, 0.3, 0.05}) {
      EXPECT_LE(hemisphereAlbedo(m, directionAt(cosView, 0.4), false, 600), 1.075)
          << "exponent " << exponent << " cos " << cosView;
    }
  }
}

TEST(ShadingModel, GlossyLobesAreReciprocal) {
  const scene::Material lobes[] = {
      lobeMaterial(scene::Lobe::Phong, 0.7F, 20.0F, 1.0F),
      lobeMaterial(scene::Lobe::Blinn, 0.7F, 20.0F, 1.0F),
      lobeMaterial(scene::Lobe::Ggx, 0.7F, 0.0F, 0.5F),
  };
  const glm::vec3 a = directionAt(0.8, 0.3);
  const glm::vec3 b = directionAt(0.6, 0.3 + kPi * 0.9);
  for (const scene::Material& m : lobes) {
    const glm::vec3 fab = specularBrdf(m, kUp, a, b);
    const glm::vec3 fba = specularBrdf(m, kUp, b, a);
    EXPECT_GT(fab.y, 0.0F) << scene::lobeName(m.lobe);
    EXPECT_NEAR(double(fab.y), double(fba.y), 1e-5 * double(fab.y)) << scene::lobeName(m.lobe);
  }
}

TEST(ShadingModel, SpecularVanishesBelowTheSurfaceAndForLambertian) {
  const scene::Material phong = lobeMaterial(scene::Lobe::Phong, 0.7F, 2.0F, 1.0F);
  const glm::vec3 wo = directionAt(0.5, 0.0);
  EXPECT_EQ(specularBrdf(phong, kUp, wo, directionAt(-0.2, kPi)).y, 0.0F);
  EXPECT_EQ(specularBrdf(phong, kUp, directionAt(-0.5, 0.0), directionAt(0.5, kPi)).y, 0.0F);
  scene::Material lambert;
  lambert.specularAlbedo = glm::vec3(1.0F);
  EXPECT_EQ(specularBrdf(lambert, kUp, wo, directionAt(0.5, kPi)).y, 0.0F);
}

TEST(ShadingModel, PhongPeaksOnTheMirrorDirection) {
  const scene::Material m = lobeMaterial(scene::Lobe::Phong, 1.0F, 50.0F, 1.0F);
  const glm::vec3 wo = directionAt(0.6, 0.2);
  const glm::vec3 r = reflectedDirection(kUp, wo);
  EXPECT_NEAR(double(glm::dot(r, directionAt(0.6, 0.2 + kPi))), 1.0, 1e-6);
  EXPECT_NEAR(double(specularBrdf(m, kUp, wo, r).y), 52.0 / (2.0 * kPi), 1e-4);
}

TEST(ShadingModel, MirrorReflectanceFollowsSchlickForGgx) {
  const scene::Material ggx = lobeMaterial(scene::Lobe::Ggx, 0.04F, 0.0F, 0.01F);
  EXPECT_NEAR(double(mirrorReflectance(ggx, kUp, kUp).y), 0.04, 1e-6);
  EXPECT_GT(mirrorReflectance(ggx, kUp, directionAt(0.02, 0.0)).y, 0.8F);
  const scene::Material phong = lobeMaterial(scene::Lobe::Phong, 0.9F, 5000.0F, 1.0F);
  EXPECT_NEAR(double(mirrorReflectance(phong, kUp, directionAt(0.1, 0.0)).y), 0.9, 1e-6);
}

}  // namespace
}  // namespace vem::render
