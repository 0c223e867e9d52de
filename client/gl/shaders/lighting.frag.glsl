// Per-pixel lighting from many directional lights (paper 004 sections 4.1, 4.2, 5.2). Light
// textures (light_textures.h): light i is texels 2i = (dir, shadow slot) and 2i+1 = (rgb, 0) of
// an RGBA32F buffer texture; a region list is a flat index buffer plus an offsets buffer (region
// r's lights are list[offsets[r] .. offsets[r + 1])), the region of a direction one read of an
// integer cube map (core/angular_regions.h's regionOfTexel).
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

void main() {
  vec3 wo = normalize(uEye - vPositionWorld);
  vec3 n = normalize(vNormalWorld);
  if (dot(n, wo) < 0.0) n = -n;  // two-sided surfaces
  vec3 radiance = diffuseLighting(n, wo, vPositionWorld);
  if (uGlossyPass != 0) radiance += glossyLighting(n, wo, vPositionWorld);
  if (uMirror != 0 && uHasEnvironment != 0) {
    vec3 r = reflectedDirection(n, wo);
    radiance += mirrorReflectance(n, wo) * textureLod(uEnvironment, r, 0.0).rgb;
  }
  fragColor = vec4(radiance, 1.0);
}
