#include "client/embree/brdf_sampling.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/glm.hpp>

#include "client/render/shading_model.h"
#include "core/color.h"

namespace vem::embree {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

float ggxAlpha2(const scene::Material& m) {
  const float a = m.roughness * m.roughness;
  return a * a;
}

// Density over half vectors h (about n) of the Blinn and GGX lobes.
float halfVectorPdf(const scene::Material& m, float cosH) {
  if (cosH <= 0.0F) {
    return 0.0F;
  }
  if (m.lobe == scene::Lobe::Blinn) {
    return (m.exponent + 1.0F) / (2.0F * kPi) * std::pow(cosH, m.exponent);
  }
  const float a2 = ggxAlpha2(m);
  const float d = cosH * cosH * (a2 - 1.0F) + 1.0F;
  return a2 / (kPi * d * d) * cosH;
}

// cos theta of a half vector drawn from halfVectorPdf.
float sampleHalfCosine(const scene::Material& m, float u) {
  if (m.lobe == scene::Lobe::Blinn) {
    return std::pow(1.0F - u, 1.0F / (m.exponent + 1.0F));
  }
  const float a2 = ggxAlpha2(m);
  return std::sqrt((1.0F - u) / (1.0F + (a2 - 1.0F) * u));
}

glm::vec3 sampleSpecular(const BrdfLobes& l, float u1, float u2) {
  const scene::Material& m = *l.material;
  if (m.lobe == scene::Lobe::Phong) {
    const float c = std::pow(1.0F - u1, 1.0F / (m.exponent + 1.0F));
    return directionAbout(render::reflectedDirection(l.n, l.wo), c, 2.0F * kPi * u2);
  }
  const glm::vec3 h = directionAbout(l.n, sampleHalfCosine(m, u1), 2.0F * kPi * u2);
  return glm::normalize(2.0F * glm::dot(l.wo, h) * h - l.wo);
}

float specularPdf(const BrdfLobes& l, glm::vec3 wi) {
  const scene::Material& m = *l.material;
  if (m.lobe == scene::Lobe::Phong) {
    const float c = glm::dot(render::reflectedDirection(l.n, l.wo), wi);
    return c > 0.0F ? (m.exponent + 1.0F) / (2.0F * kPi) * std::pow(c, m.exponent) : 0.0F;
  }
  const glm::vec3 sum = wi + l.wo;
  const float length = glm::length(sum);
  if (length < 1e-7F) {
    return 0.0F;
  }
  // wi mirrors wo about h and about -h alike; only the one above the surface has density.
  glm::vec3 h = sum / length;
  if (glm::dot(l.n, h) < 0.0F) {
    h = -h;
  }
  const float woH = std::abs(glm::dot(l.wo, h));
  return woH > 0.0F ? halfVectorPdf(m, glm::dot(l.n, h)) / (4.0F * woH) : 0.0F;
}

}  // namespace

glm::vec3 directionAbout(glm::vec3 axis, float cosTheta, float phiRad) {
  // Duff et al. 2017, "Building an orthonormal basis, revisited".
  const float sign = std::copysign(1.0F, axis.z);
  const float a = -1.0F / (sign + axis.z);
  const float b = axis.x * axis.y * a;
  const glm::vec3 t(1.0F + sign * axis.x * axis.x * a, sign * b, -sign * axis.x);
  const glm::vec3 s(b, sign + axis.y * axis.y * a, -axis.y);
  const float c = std::clamp(cosTheta, -1.0F, 1.0F);
  const float sinTheta = std::sqrt(std::max(0.0F, 1.0F - c * c));
  return glm::normalize(c * axis + sinTheta * (std::cos(phiRad) * t + std::sin(phiRad) * s));
}

float specularSelectProbability(const BrdfLobes& l) {
  if (!l.withSpecular || !l.material->glossy()) {
    return 0.0F;
  }
  const auto spec = float(luminance(l.material->specularAlbedo));
  const auto diffuse = float(luminance(l.material->diffuseAlbedo));
  return spec + diffuse > 0.0F ? spec / (spec + diffuse) : 0.0F;
}

glm::vec3 sampleBrdfDirection(const BrdfLobes& l, glm::vec3 u) {
  if (u.x < specularSelectProbability(l)) {
    return sampleSpecular(l, u.y, u.z);
  }
  return directionAbout(l.n, std::sqrt(1.0F - u.y), 2.0F * kPi * u.z);
}

float brdfPdfSr(const BrdfLobes& l, glm::vec3 wi) {
  const float p = specularSelectProbability(l);
  const float cosine = std::max(0.0F, glm::dot(l.n, wi)) / kPi;
  return p > 0.0F ? (1.0F - p) * cosine + p * specularPdf(l, wi) : cosine;
}

glm::vec3 brdfValue(const BrdfLobes& l, glm::vec3 wi) {
  glm::vec3 f = render::diffuseBrdf(*l.material);
  if (l.withSpecular) {
    f += render::specularBrdf(*l.material, l.n, l.wo, wi);
  }
  return f;
}

}  // namespace vem::embree
