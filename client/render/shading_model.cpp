// The BRDFs of scene/scene.h. The GLSL fragment shader mirrors these formulas; each one is written
// out here in full so the two can be compared line by line.
//
//   diffuse:  kd / pi
//   Phong:    ks (e + 2) / (2 pi) max(0, R . wi)^e,  R = 2 (n . wo) n - wo
//             (integrates against n . wi to exactly ks when R = n, less elsewhere)
//   Blinn:    ks (e + 8) / (8 pi) max(0, n . h)^e,   h = normalize(wi + wo)
//   GGX:      D G F / (4 (n . wi) (n . wo)) with
//             a = roughness^2,
//             D = a^2 / (pi ((n . h)^2 (a^2 - 1) + 1)^2),
//             G = G1(n . wi) G1(n . wo), the separable Smith form (not height-correlated):
//                 G1(c) = 2 c / (c + sqrt(a^2 + (1 - a^2) c^2)),
//             F = F0 + (1 - F0) (1 - (wo . h))^5 (Schlick), F0 = ks.
// Every specular lobe is 0 when wi or wo lies on or below the surface (n . wi <= 0 or n . wo <= 0):
// the renderers multiply by max(0, n . wi) anyway, and GGX divides by both cosines.
#include "client/render/shading_model.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/glm.hpp>

namespace vem::render {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

glm::vec3 phongLobe(const scene::Material& m, glm::vec3 n, glm::vec3 wo, glm::vec3 wi) {
  const float cosR = std::max(0.0F, glm::dot(reflectedDirection(n, wo), wi));
  return m.specularAlbedo * ((m.exponent + 2.0F) / (2.0F * kPi) * std::pow(cosR, m.exponent));
}

glm::vec3 blinnLobe(const scene::Material& m, glm::vec3 n, glm::vec3 wo, glm::vec3 wi) {
  const glm::vec3 h = glm::normalize(wi + wo);
  const float cosH = std::max(0.0F, glm::dot(n, h));
  return m.specularAlbedo * ((m.exponent + 8.0F) / (8.0F * kPi) * std::pow(cosH, m.exponent));
}

glm::vec3 schlick(glm::vec3 f0, float cosine) {
  const float m = 1.0F - std::clamp(cosine, 0.0F, 1.0F);
  const float m5 = m * m * m * m * m;
  return f0 + (glm::vec3(1.0F) - f0) * m5;
}

glm::vec3 ggxLobe(const scene::Material& m, glm::vec3 n, glm::vec3 wo, glm::vec3 wi) {
  const float cosI = glm::dot(n, wi);
  const float cosO = glm::dot(n, wo);
  const glm::vec3 h = glm::normalize(wi + wo);
  const float a = m.roughness * m.roughness;
  const float a2 = a * a;
  const float d = ggxDistribution(std::max(0.0F, glm::dot(n, h)), a2);
  const float g = smithG1(cosI, a2) * smithG1(cosO, a2);
  return schlick(m.specularAlbedo, glm::dot(wo, h)) * (d * g / (4.0F * cosI * cosO));
}

}  // namespace

float smithG1(float cosV, float a2) {
  return 2.0F * cosV / (cosV + std::sqrt(a2 + (1.0F - a2) * cosV * cosV));
}

glm::vec3 diffuseBrdf(const scene::Material& material) { return material.diffuseAlbedo / kPi; }

float ggxDistribution(float cosHalf, float alphaSquared) {
  const float d = cosHalf * cosHalf * (alphaSquared - 1.0F) + 1.0F;
  return alphaSquared / (kPi * d * d);
}

glm::vec3 specularBrdf(const scene::Material& material, glm::vec3 n, glm::vec3 wo, glm::vec3 wi) {
  if (glm::dot(n, wi) <= 0.0F || glm::dot(n, wo) <= 0.0F) {
    return glm::vec3(0.0F);
  }
  switch (material.lobe) {
    case scene::Lobe::Phong: return phongLobe(material, n, wo, wi);
    case scene::Lobe::Blinn: return blinnLobe(material, n, wo, wi);
    case scene::Lobe::Ggx: return ggxLobe(material, n, wo, wi);
    case scene::Lobe::Lambertian: break;
  }
  return glm::vec3(0.0F);
}

glm::vec3 reflectedDirection(glm::vec3 n, glm::vec3 wo) { return 2.0F * glm::dot(n, wo) * n - wo; }

glm::vec3 mirrorReflectance(const scene::Material& material, glm::vec3 n, glm::vec3 wo) {
  if (material.lobe == scene::Lobe::Ggx) {
    return schlick(material.specularAlbedo, glm::dot(n, wo));
  }
  return material.lobe == scene::Lobe::Lambertian ? glm::vec3(0.0F) : material.specularAlbedo;
}

}  // namespace vem::render
