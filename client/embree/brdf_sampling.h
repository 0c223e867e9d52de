// Importance sampling of f(wi, wo) (n . wi) for the Monte Carlo reference (reference_renderer.h):
// each sampling routine beside its density, both over solid angle (sr^-1) on the whole sphere.
//
// The density is a mixture: with probability 1 - pSpecular the cosine lobe about n
// ((n . wi) / pi), with probability pSpecular the specular lobe of render/shading_model.h:
//   Phong: (e + 1) / (2 pi) (R . wi)^e about R (the lobe without the cosine), R . wi > 0;
//   Blinn: half vectors h with (e + 1) / (2 pi) (n . h)^e, wi = wo mirrored about h;
//   GGX:   half vectors h with D(h) (n . h), alpha = roughness^2, wi likewise;
//   both then have density p(h) / (4 |wo . h|) over wi, h the half vector with n . h >= 0.
// pSpecular is the specular albedo's share of the material's Rec. 709 luminance (0 for Lambertian
// materials or when the specular part is left out). Directions below the surface are possible
// (their f is 0); n is the shading normal turned toward wo, vectors unit, world frame.
#pragma once

#include <glm/vec3.hpp>

#include "client/scene/scene.h"

namespace vem::embree {

struct BrdfLobes {
  const scene::Material* material = nullptr;
  bool withSpecular = true;  // false: the diffuse part alone (mirror-like materials)
  glm::vec3 n{0.0F, 1.0F, 0.0F};
  glm::vec3 wo{0.0F, 1.0F, 0.0F};
};

[[nodiscard]] float specularSelectProbability(const BrdfLobes& lobes);
// u in [0, 1)^3: u.x picks the lobe, u.y and u.z place the direction. Unit result.
[[nodiscard]] glm::vec3 sampleBrdfDirection(const BrdfLobes& lobes, glm::vec3 u);
[[nodiscard]] float brdfPdfSr(const BrdfLobes& lobes, glm::vec3 wi);
// f(wi, wo) of the parts sampled (diffuse, plus the specular lobe when withSpecular).
[[nodiscard]] glm::vec3 brdfValue(const BrdfLobes& lobes, glm::vec3 wi);

// A unit direction at cosine cosTheta from `axis` (unit) and azimuth phi about it.
[[nodiscard]] glm::vec3 directionAbout(glm::vec3 axis, float cosTheta, float phiRad);

}  // namespace vem::embree
