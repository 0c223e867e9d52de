// Shadow-map atlas lookup (paper 004 section 5.2.1): the light's slot picks its tile of the atlas
// (slot % grid across, slot / grid up) and its caster (a light without a map of its own uses the
// nearest caster's, render/shading_lights.h); the view is rebuilt from the caster's direction
// (light_view.glsl), then a slope-scaled depth bias and 3 x 3 bilinear PCF taps clamped inside
// the tile.
uniform sampler2DShadow uShadowAtlas;
uniform int uShadowGrid;        // tiles per atlas side
uniform int uShadowCapacity;    // slots the atlas holds (grid^2 or fewer)
uniform float uShadowMapPx;     // tile side, texels
uniform float uShadowAtlasPx;   // atlas side, texels
uniform samplerBuffer uShadowCasterDirs;  // slot -> the caster's direction (xyz)

// 1 lit, 0 shadowed; slot < 0 (or beyond the atlas) is unshadowed. The view spans the casters'
// bounding sphere (scene::shadowCasterBounds): a point outside it across the light's view has no
// caster between it and the light (lit); one beyond its far plane is compared at the far plane
// (behind every caster), one before its near plane at the near plane (before every caster).
float visibility(int slot, vec3 pointWorld, float cosNL) {
  if (slot < 0 || slot >= uShadowCapacity) return 1.0;
  vec3 casterDir = texelFetch(uShadowCasterDirs, slot).xyz;
  vec3 c = lightClipPosition(casterDir, pointWorld);
  if (any(greaterThan(abs(c.xy), vec2(1.0)))) return 1.0;
  float tanNL = sqrt(max(0.0, 1.0 - cosNL * cosNL)) / max(cosNL, 1e-4);
  float bias = (1.5 + 2.5 * min(tanNL, 10.0)) / uShadowMapPx;  // depth in [0,1] over 2 radii
  float depth = clamp(c.z * 0.5 + 0.5, 0.0, 1.0) - bias;
  vec2 tile = vec2(float(slot % uShadowGrid), float(slot / uShadowGrid));
  vec2 inTile = c.xy * 0.5 + 0.5;
  float texel = 1.0 / uShadowMapPx;
  float lit = 0.0;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      vec2 q = clamp(inTile + vec2(float(dx), float(dy)) * texel, vec2(0.5 * texel),
                     vec2(1.0 - 0.5 * texel));
      vec2 uv = (tile + q) * (uShadowMapPx / uShadowAtlasPx);
      lit += texture(uShadowAtlas, vec3(uv, depth));
    }
  }
  return lit / 9.0;
}
