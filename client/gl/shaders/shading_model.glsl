// Mirrors client/render/shading_model.cpp line for line: the BRDFs of client/scene/scene.h for the
// material in the uniforms below. Vectors unit, world frame; n turned toward wo.
uniform vec3 uDiffuseAlbedo;
uniform int uLobe;  // scene::Lobe: 0 Lambertian, 1 Phong, 2 Blinn, 3 GGX
uniform vec3 uSpecularAlbedo;
uniform float uExponent;
uniform float uRoughness;

const float kPi = 3.14159265358979323846;

// std::pow(x, e) for x >= 0 (GLSL's pow is undefined at x = 0).
float powNonNegative(float x, float e) {
  if (x > 0.0) return pow(x, e);
  return e == 0.0 ? 1.0 : 0.0;
}

vec3 reflectedDirection(vec3 n, vec3 wo) { return 2.0 * dot(n, wo) * n - wo; }

vec3 diffuseBrdf() { return uDiffuseAlbedo / kPi; }

vec3 phongLobe(vec3 n, vec3 wo, vec3 wi) {
  float cosR = max(0.0, dot(reflectedDirection(n, wo), wi));
  return uSpecularAlbedo * ((uExponent + 2.0) / (2.0 * kPi) * powNonNegative(cosR, uExponent));
}

vec3 blinnLobe(vec3 n, vec3 wo, vec3 wi) {
  vec3 h = normalize(wi + wo);
  float cosH = max(0.0, dot(n, h));
  return uSpecularAlbedo * ((uExponent + 8.0) / (8.0 * kPi) * powNonNegative(cosH, uExponent));
}

float ggxD(float cosH, float a2) {
  float d = cosH * cosH * (a2 - 1.0) + 1.0;
  return a2 / (kPi * d * d);
}

float smithG1(float cosV, float a2) {
  return 2.0 * cosV / (cosV + sqrt(a2 + (1.0 - a2) * cosV * cosV));
}

vec3 schlick(vec3 f0, float cosine) {
  float m = 1.0 - clamp(cosine, 0.0, 1.0);
  float m5 = m * m * m * m * m;
  return f0 + (vec3(1.0) - f0) * m5;
}

vec3 ggxLobe(vec3 n, vec3 wo, vec3 wi) {
  float cosI = dot(n, wi);
  float cosO = dot(n, wo);
  vec3 h = normalize(wi + wo);
  float a = uRoughness * uRoughness;
  float a2 = a * a;
  float d = ggxD(max(0.0, dot(n, h)), a2);
  float g = smithG1(cosI, a2) * smithG1(cosO, a2);
  return schlick(uSpecularAlbedo, dot(wo, h)) * (d * g / (4.0 * cosI * cosO));
}

vec3 specularBrdf(vec3 n, vec3 wo, vec3 wi) {
  if (dot(n, wi) <= 0.0 || dot(n, wo) <= 0.0) return vec3(0.0);
  if (uLobe == 1) return phongLobe(n, wo, wi);
  if (uLobe == 2) return blinnLobe(n, wo, wi);
  if (uLobe == 3) return ggxLobe(n, wo, wi);
  return vec3(0.0);
}

vec3 mirrorReflectance(vec3 n, vec3 wo) {
  if (uLobe == 3) return schlick(uSpecularAlbedo, dot(n, wo));
  return uLobe == 0 ? vec3(0.0) : uSpecularAlbedo;
}
