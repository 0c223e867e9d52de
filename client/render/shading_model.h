// Shading model: the BRDFs of scene/scene.h and what one directional light contributes, on the
// CPU. The Embree renderer calls these functions; the OpenGL renderer's fragment shader
// (client/gl/shaders) mirrors them line for line, and tests compare the two.
//
// Conventions: all vectors unit, in the world frame; wo points from the surface toward the eye, wi
// from the surface toward the light; n is the shading normal, already turned toward wo (two-sided
// surfaces). A light's rgb is its irradiance contribution (core/light.h), so the radiance it sends
// toward wo is  f(wi, wo) rgb max(0, n . wi) V  with V its visibility (0 or 1).
#pragma once

#include <glm/vec3.hpp>

#include "client/scene/scene.h"

namespace vem::render {

// The diffuse part of f: diffuseAlbedo / pi.
[[nodiscard]] glm::vec3 diffuseBrdf(const scene::Material& material);
// The specular lobe of f (0 for Lambertian), without the diffuse part.
[[nodiscard]] glm::vec3 specularBrdf(const scene::Material& material, glm::vec3 n, glm::vec3 wo,
                                     glm::vec3 wi);
// The GGX normal distribution D at cosHalf = n . h, for alpha^2 = alphaSquared (alpha =
// roughness^2): alpha^2 / (pi ((n . h)^2 (alpha^2 - 1) + 1)^2); the integral of D (n . h) over
// the hemisphere of h is 1.
[[nodiscard]] float ggxDistribution(float cosHalf, float alphaSquared);
// Smith's masking G1 for GGX at cosV = n . v (> 0): 2 cosV / (cosV + sqrt(alpha^2 + (1 - alpha^2)
// cosV^2)); the GGX lobe's G is G1(n . wi) G1(n . wo).
[[nodiscard]] float smithG1(float cosV, float alphaSquared);
// wo mirrored about n: 2 (n . wo) n - wo.
[[nodiscard]] glm::vec3 reflectedDirection(glm::vec3 n, glm::vec3 wo);
// The fraction of a uniform environment a mirror-like material reflects toward wo (its directional
// albedo, used to weight the cube map's reflection): specularAlbedo for Phong/Blinn, Schlick's
// F(n . wo) for GGX.
[[nodiscard]] glm::vec3 mirrorReflectance(const scene::Material& material, glm::vec3 n,
                                          glm::vec3 wo);

}  // namespace vem::render
