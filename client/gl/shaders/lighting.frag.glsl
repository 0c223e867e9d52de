// Per-pixel lighting from many directional lights (paper 004 sections 4.1, 4.2, 5.2). Light
// textures (light_textures.h): light i is texels 2i = (dir, shadow slot) and 2i+1 = (rgb, 0) of
// an RGBA32F buffer texture; a region list is a flat index buffer plus an offsets buffer (region
// r's lights are list[offsets[r] .. offsets[r + 1])), the region of a direction one read of an
// integer cube map (core/angular_regions.h's regionOfTexel). With uRatio, shading by ratio
// instead: ratioShading below, the model client/embree/light_renderer.h states.
in vec3 vPositionWorld;
in vec3 vNormalWorld;
out vec4 fragColor;

uniform vec3 uEye;
uniform int uSpecularFromDiffuse;  // glossy, not mirror-like, and no glossy pass
uniform int uGlossyPass;           // glossy, not mirror-like, and the frame has L/H sets
uniform int uMirror;               // mirror-like: the cube map instead of the lights

uniform samplerBuffer uDiffuseLights;
uniform usamplerBuffer uDiffuseList;
uniform usamplerBuffer uDiffuseOffsets;
uniform usamplerCube uDiffuseRegions;
uniform int uDiffuseCount;
uniform int uDiffuseUseRegions;

uniform samplerBuffer uLowLights;
uniform usamplerBuffer uLowList;
uniform usamplerBuffer uLowOffsets;
uniform usamplerCube uLowRegions;
uniform samplerBuffer uHighLights;
uniform usamplerBuffer uHighList;
uniform usamplerBuffer uHighOffsets;
uniform usamplerCube uHighRegions;
uniform float uCosCone;       // cos(gamma / 2)
uniform int uMaxConeLights;   // k

uniform samplerCube uEnvironment;
uniform int uHasEnvironment;

// Shading by ratio (issue 20; environment_lighting_textures.h). A diffuse light's second texel
// carries its peak fraction p_i in w.
uniform int uRatio;
uniform samplerCube uIrradiance;  // E(n)
uniform int uHasIrradiance;
uniform samplerCube uPrefiltered;  // the clipped environment (filtered sampling), or P(R)
// render::kFilteredSamples: filtered importance sampling of uPrefiltered, the clipped environment
// with its chain (render/environment_lighting.h); 0: the split sum, P(R) times the albedo table.
uniform int uFilteredSamples;
uniform float uFilteredFacePx;    // its level 0's face
uniform float uFilteredTopLevel;  // its last level
uniform int uSpecularByRatio;      // the material has a specular environment
uniform float uAlbedoScale[32];    // render::kAlbedoTableSize entries of rho = F0 scale + bias
uniform float uAlbedoBias[32];
uniform float uMinEffectiveLights;
// Soft shadows in the maps (render/shadow_draws.h): by slot, (weight rgb, draws from this slot).
uniform samplerBuffer uShadowDrawWeights;
uniform int uShadowDraws;  // the frame's soft lights have draws
// What a mirror-like mesh's reflected rays hit (mirror_occlusion.h).
uniform samplerCube uMirrorDistance;  // distance from uMirrorCentre to the other meshes
uniform int uMirrorOccluded;          // this mesh has a distance cube
uniform vec3 uMirrorCentre;
uniform float uMirrorRadius;
uniform float uSceneDiameter;
uniform float uSpecularLookupBlend;  // render::specularLookupBlend: P is read toward mix(n, R, b)

const vec3 kLuminance = vec3(0.2126, 0.7152, 0.0722);  // Rec. 709 (core/color.h)

ivec2 regionRange(usamplerCube regions, usamplerBuffer offsets, vec3 dir) {
  int region = int(textureLod(regions, dir, 0.0).r);
  return ivec2(int(texelFetch(offsets, region).r), int(texelFetch(offsets, region + 1).r));
}

vec3 diffuseLighting(vec3 n, vec3 wo, vec3 p) {
  ivec2 range = ivec2(0, uDiffuseCount);
  if (uDiffuseUseRegions != 0) range = regionRange(uDiffuseRegions, uDiffuseOffsets, n);
  vec3 sum = vec3(0.0);
  for (int k = range.x; k < range.y; ++k) {
    int i = uDiffuseUseRegions != 0 ? int(texelFetch(uDiffuseList, k).r) : k;
    vec4 dirSlot = texelFetch(uDiffuseLights, 2 * i);
    float cosNL = dot(n, dirSlot.xyz);
    if (cosNL <= 0.0) continue;
    vec3 f = diffuseBrdf();
    if (uSpecularFromDiffuse != 0) f += specularBrdf(n, wo, dirSlot.xyz);
    vec3 rgb = texelFetch(uDiffuseLights, 2 * i + 1).rgb;
    sum += f * rgb * cosNL * visibility(int(dirSlot.w), p, cosNL);
  }
  return sum;
}

// Mirrors core's glossyLightsFor(): L lights strictly inside the cone C(R) (the first k, scaled
// by m / k when m > k lie inside), then H lights outside C and above R's horizon.
vec3 glossyLighting(vec3 n, vec3 wo, vec3 p) {
  vec3 r = normalize(reflectedDirection(n, wo));
  ivec2 low = regionRange(uLowRegions, uLowOffsets, r);
  vec3 cone = vec3(0.0);
  int inCone = 0;
  for (int k = low.x; k < low.y; ++k) {
    int i = int(texelFetch(uLowList, k).r);
    vec4 dirSlot = texelFetch(uLowLights, 2 * i);
    if (dot(r, dirSlot.xyz) <= uCosCone) continue;
    ++inCone;
    if (inCone > uMaxConeLights) continue;
    float cosNL = max(0.0, dot(n, dirSlot.xyz));
    vec3 rgb = texelFetch(uLowLights, 2 * i + 1).rgb;
    cone += specularBrdf(n, wo, dirSlot.xyz) * rgb * cosNL *
            visibility(int(dirSlot.w), p, cosNL);
  }
  if (inCone > uMaxConeLights) cone *= float(inCone) / float(uMaxConeLights);
  ivec2 high = regionRange(uHighRegions, uHighOffsets, r);
  vec3 outside = vec3(0.0);
  for (int k = high.x; k < high.y; ++k) {
    int i = int(texelFetch(uHighList, k).r);
    vec4 dirSlot = texelFetch(uHighLights, 2 * i);
    float cosR = dot(r, dirSlot.xyz);
    if (cosR <= 0.0 || cosR > uCosCone) continue;
    float cosNL = max(0.0, dot(n, dirSlot.xyz));
    vec3 rgb = texelFetch(uHighLights, 2 * i + 1).rgb;
    outside += specularBrdf(n, wo, dirSlot.xyz) * rgb * cosNL *
               visibility(int(dirSlot.w), p, cosNL);
  }
  return cone + outside;
}

// Per channel S / U; 1 where U is 0 (nothing known to block), the luminance ratio for a channel
// far below the others (light_renderer.cpp's ratioOf).
vec3 ratioOf(vec3 shadowed, vec3 unshadowed) {
  float largest = max(unshadowed.r, max(unshadowed.g, unshadowed.b));
  if (!(largest > 0.0)) return vec3(1.0);
  float overall = dot(kLuminance, shadowed) / max(dot(kLuminance, unshadowed), 1e-30);
  vec3 ratio;
  for (int c = 0; c < 3; ++c) {
    ratio[c] = unshadowed[c] > 1e-6 * largest ? shadowed[c] / unshadowed[c] : overall;
  }
  return ratio;
}

// render::directionalAlbedo: linear between entries at mu_i = (i + 0.5) / 32, clamped.
vec3 directionalAlbedo(float cosNormalEye) {
  float x = clamp(cosNormalEye * 32.0 - 0.5, 0.0, 31.0);
  int i0 = int(x);
  int i1 = min(i0 + 1, 31);
  float w = x - float(i0);
  float scale = mix(uAlbedoScale[i0], uAlbedoScale[i1], w);
  float bias = mix(uAlbedoBias[i0], uAlbedoBias[i1], w);
  return uSpecularAlbedo * scale + vec3(bias);
}

// render/tangent_frame.h's tangentFrameAround: t, b with t x b = z.
void frameAround(vec3 z, out vec3 t, out vec3 b) {
  vec3 helper = abs(z.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
  t = normalize(cross(helper, z));
  b = cross(z, t);
}

// environment_lighting.cpp's around: a direction at polar cosine cosTheta and azimuth phi about z.
vec3 aroundAxis(vec3 z, float cosTheta, float phi) {
  vec3 t;
  vec3 b;
  frameAround(z, t, b);
  float sinTheta = sqrt(max(0.0, 1.0 - cosTheta * cosTheta));
  return normalize(sinTheta * cos(phi) * t + sinTheta * sin(phi) * b + cosTheta * z);
}

// environment_lighting.cpp's sampleVisibleGgx: GGX by its distribution of visible normals.
vec4 sampleVisibleGgx(vec3 n, vec3 wo, float u1, float u2) {
  float a = uRoughness * uRoughness;
  float a2 = a * a;
  vec3 t;
  vec3 b;
  frameAround(n, t, b);
  float cosO = dot(n, wo);
  if (cosO <= 0.0) return vec4(n, 0.0);
  vec3 v = normalize(vec3(a * dot(wo, t), a * dot(wo, b), cosO));
  float lengthSquared = v.x * v.x + v.y * v.y;
  vec3 t1 = lengthSquared > 0.0 ? vec3(-v.y, v.x, 0.0) / sqrt(lengthSquared) : vec3(1.0, 0.0, 0.0);
  vec3 t2 = cross(v, t1);
  float r = sqrt(u1);
  float phi = 2.0 * kPi * u2;
  float p1 = r * cos(phi);
  float s = 0.5 * (1.0 + v.z);
  float p2 = (1.0 - s) * sqrt(max(0.0, 1.0 - p1 * p1)) + s * r * sin(phi);
  vec3 nh = p1 * t1 + p2 * t2 + sqrt(max(0.0, 1.0 - p1 * p1 - p2 * p2)) * v;
  vec3 hLocal = normalize(vec3(a * nh.x, a * nh.y, max(0.0, nh.z)));
  vec3 h = hLocal.x * t + hLocal.y * b + hLocal.z * n;
  float woH = dot(wo, h);
  if (woH <= 0.0) return vec4(h, 0.0);
  float density = smithG1(cosO, a2) * ggxD(max(0.0, dot(n, h)), a2) / (4.0 * cosO);
  return vec4(2.0 * woH * h - wo, density);
}

// environment_lighting.cpp's sampleLobe, line for line: xyz one importance sample of the
// material's lobe at (u1, u2), w its density over solid angle (0: skip it).
vec4 sampleLobe(vec3 n, vec3 wo, float u1, float u2) {
  float phi = 2.0 * kPi * u2;
  if (uLobe == 1) {
    float cosTheta = pow(u1, 1.0 / (uExponent + 1.0));
    return vec4(aroundAxis(reflectedDirection(n, wo), cosTheta, phi),
                (uExponent + 1.0) / (2.0 * kPi) * powNonNegative(cosTheta, uExponent));
  }
  if (uLobe == 3) return sampleVisibleGgx(n, wo, u1, u2);
  float cosH = pow(u1, 1.0 / (uExponent + 2.0));
  float pdfHalf = (uExponent + 2.0) / (2.0 * kPi) * powNonNegative(cosH, uExponent + 1.0);
  vec3 h = aroundAxis(n, cosH, phi);
  float woH = dot(wo, h);
  if (woH <= 0.0) return vec4(h, 0.0);
  return vec4(2.0 * woH * h - wo, pdfHalf / (4.0 * woH));
}

// The base-2 radical inverse of k (the Hammersley set's second coordinate).
float radicalInverse2(uint k) {
  k = (k << 16u) | (k >> 16u);
  k = ((k & 0x55555555u) << 1u) | ((k & 0xAAAAAAAAu) >> 1u);
  k = ((k & 0x33333333u) << 2u) | ((k & 0xCCCCCCCCu) >> 2u);
  k = ((k & 0x0F0F0F0Fu) << 4u) | ((k & 0xF0F0F0F0u) >> 4u);
  k = ((k & 0x00FF00FFu) << 8u) | ((k & 0xFF00FF00u) >> 8u);
  return float(k) * 2.3283064365386963e-10;
}

// environment_lighting.cpp's filteredSpecular: filtered importance sampling of uPrefiltered.
vec3 filteredSpecular(vec3 n, vec3 wo) {
  float texelSr = 4.0 * kPi / (6.0 * uFilteredFacePx * uFilteredFacePx);
  vec3 sum = vec3(0.0);
  for (int k = 0; k < uFilteredSamples; ++k) {
    float u1 = (float(k) + 0.5) / float(uFilteredSamples);
    vec4 s = sampleLobe(n, wo, u1, radicalInverse2(uint(k)));
    float cosI = dot(n, s.xyz);
    if (s.w <= 0.0 || cosI <= 0.0) continue;
    float lod = clamp(0.5 * log2(1.0 / (float(uFilteredSamples) * s.w * texelSr)), 0.0,
                      uFilteredTopLevel);
    sum += specularBrdf(n, wo, s.xyz) * textureLod(uPrefiltered, s.xyz, lod).rgb * (cosI / s.w);
  }
  return sum / float(uFilteredSamples);
}

// The shadowed and unshadowed sums of shading by ratio (light_renderer.cpp's RatioSums).
struct RatioSums {
  vec3 unshadowedD;
  vec3 shadowedD;
  vec3 unshadowedS;
  vec3 shadowedS;
  vec3 peakS;
  float sumY;
  float sumY2;
};

// A light's diffuse term along its own direction, with visibility v.
void addDiffuse(inout RatioSums s, vec3 rgb, float cosNL, float v) {
  vec3 wd = rgb * cosNL;
  s.unshadowedD += wd;
  s.shadowedD += v * wd;
}

// A light's specular term (cosNL > 0), with visibility v, its clipped peak light by light.
void addSpecular(inout RatioSums s, vec3 n, vec3 wo, vec3 dir, vec4 rgbPeak, float cosNL,
                 float v) {
  vec3 full = specularBrdf(n, wo, dir) * rgbPeak.rgb * cosNL;
  s.peakS += (v * rgbPeak.w) * full;
  vec3 ws = (1.0 - rgbPeak.w) * full;
  s.unshadowedS += ws;
  s.shadowedS += v * ws;
  float y = dot(kLuminance, ws);
  s.sumY += y;
  s.sumY2 += y * y;
}

// A soft light's diffuse term from its `draws` maps from `slot` on (render/shadow_draws.h), each
// weighed by its weight times its own cosine; returns the visible share of those weights (1 when
// no draw faces the surface).
float addDrawnDiffuse(inout RatioSums s, int slot, int draws, vec3 n, vec3 p) {
  vec3 drawnU = vec3(0.0);
  vec3 drawnS = vec3(0.0);
  for (int j = 0; j < draws; ++j) {
    vec3 d = texelFetch(uShadowCasterDirs, slot + j).xyz;
    float c = dot(n, d);
    if (c <= 0.0) continue;  // this draw lies below the surface
    vec3 w = texelFetch(uShadowDrawWeights, slot + j).rgb * c;
    drawnU += w;
    drawnS += visibility(slot + j, p, c) * w;
  }
  s.unshadowedD += drawnU;
  s.shadowedD += drawnS;
  float drawnY = dot(kLuminance, drawnU);
  return drawnY > 0.0 ? dot(kLuminance, drawnS) / drawnY : 1.0;
}

// The unshadowed environment scaled by the lights' shadowed-to-unshadowed ratios, plus the
// clipped peaks light by light, over the diffuse lights of n's region (light_renderer.cpp's
// ratioSumsOf and composeByRatio, term for term). A soft light with draws sums its k maps' draws
// where Embree sums one draw per pixel; its specular term takes the draws' visible share. Frames
// without draws take a loop without them (a uniform branch: llvmpipe's frame was a third slower
// with the draws' test inside the one loop).
vec3 ratioShading(vec3 n, vec3 wo, vec3 p) {
  ivec2 range = ivec2(0, uDiffuseCount);
  if (uDiffuseUseRegions != 0) range = regionRange(uDiffuseRegions, uDiffuseOffsets, n);
  RatioSums s = RatioSums(vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), 0.0, 0.0);
  if (uShadowDraws != 0) {
    for (int k = range.x; k < range.y; ++k) {
      int i = uDiffuseUseRegions != 0 ? int(texelFetch(uDiffuseList, k).r) : k;
      vec4 dirSlot = texelFetch(uDiffuseLights, 2 * i);
      vec4 rgbPeak = texelFetch(uDiffuseLights, 2 * i + 1);
      float cosNL = dot(n, dirSlot.xyz);
      int slot = int(dirSlot.w);
      int draws = slot >= 0 ? int(texelFetch(uShadowDrawWeights, slot).a) : 0;
      float v;
      if (draws > 0) {
        v = addDrawnDiffuse(s, slot, draws, n, p);
        if (cosNL <= 0.0) continue;
      } else {
        if (cosNL <= 0.0) continue;
        v = visibility(slot, p, cosNL);
        addDiffuse(s, rgbPeak.rgb, cosNL, v);
      }
      if (uSpecularByRatio != 0) addSpecular(s, n, wo, dirSlot.xyz, rgbPeak, cosNL, v);
    }
  } else {
    for (int k = range.x; k < range.y; ++k) {
      int i = uDiffuseUseRegions != 0 ? int(texelFetch(uDiffuseList, k).r) : k;
      vec4 dirSlot = texelFetch(uDiffuseLights, 2 * i);
      float cosNL = dot(n, dirSlot.xyz);
      if (cosNL <= 0.0) continue;
      float v = visibility(int(dirSlot.w), p, cosNL);
      vec4 rgbPeak = texelFetch(uDiffuseLights, 2 * i + 1);
      addDiffuse(s, rgbPeak.rgb, cosNL, v);
      if (uSpecularByRatio != 0) addSpecular(s, n, wo, dirSlot.xyz, rgbPeak, cosNL, v);
    }
  }
  vec3 ratioD = ratioOf(s.shadowedD, s.unshadowedD);
  vec3 radiance = vec3(0.0);
  if (uHasIrradiance != 0) radiance = diffuseBrdf() * textureLod(uIrradiance, n, 0.0).rgb * ratioD;
  if (uSpecularByRatio != 0) {
    float effective = s.sumY2 > 0.0 ? s.sumY * s.sumY / s.sumY2 : 0.0;
    float t = clamp(effective / uMinEffectiveLights, 0.0, 1.0);
    vec3 ratioS = mix(ratioD, ratioOf(s.shadowedS, s.unshadowedS), t);
    vec3 unshadowedSpecular;
    if (uFilteredSamples > 0) {
      unshadowedSpecular = filteredSpecular(n, wo);
    } else {
      vec3 d = normalize(mix(n, reflectedDirection(n, wo), uSpecularLookupBlend));
      unshadowedSpecular = textureLod(uPrefiltered, d, 0.0).rgb * directionalAlbedo(dot(n, wo));
    }
    radiance += unshadowedSpecular * ratioS + s.peakS;
  }
  return radiance;
}

// Whether the scene blocks the ray p + t r (r unit): marched in kMirrorMarchSteps steps growing
// geometrically from 1 % of the mirror's radius to the scene's diameter beyond it, blocked at the
// first point farther from the mirror's centre than the surface its distance cube holds in that
// direction (mirror_occlusion.h).
const int kMirrorMarchSteps = 48;
bool reflectionBlocked(vec3 p, vec3 r) {
  if (uMirrorOccluded == 0) return false;
  float t = 0.01 * uMirrorRadius;
  float growth =
      pow((uSceneDiameter + 2.0 * uMirrorRadius) / t, 1.0 / float(kMirrorMarchSteps - 1));
  for (int k = 0; k < kMirrorMarchSteps; ++k) {
    vec3 d = p + t * r - uMirrorCentre;
    if (length(d) > textureLod(uMirrorDistance, d, 0.0).r) return true;
    t *= growth;
  }
  return false;
}

void main() {
  vec3 wo = normalize(uEye - vPositionWorld);
  vec3 n = normalize(vNormalWorld);
  if (dot(n, wo) < 0.0) n = -n;  // two-sided surfaces
  vec3 radiance;
  if (uRatio != 0) {
    radiance = ratioShading(n, wo, vPositionWorld);
  } else {
    radiance = diffuseLighting(n, wo, vPositionWorld);
    if (uGlossyPass != 0) radiance += glossyLighting(n, wo, vPositionWorld);
  }
  if (uMirror != 0 && uHasEnvironment != 0) {
    vec3 r = reflectedDirection(n, wo);
    if (!reflectionBlocked(vPositionWorld, normalize(r))) {
      radiance += mirrorReflectance(n, wo) * textureLod(uEnvironment, r, 0.0).rgb;
    }
  }
  fragColor = vec4(radiance, 1.0);
}
