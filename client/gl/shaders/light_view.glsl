// Mirrors client/gl/light_clip.h: a light's orthographic view of the shadow casters' bounding
// sphere (centre uSceneCentre, radius uShadowRadius = shadowFrameRadius(bounds), bounds =
// scene::shadowCasterBounds), rebuilt from the
// light's direction alone (paper 004 section 5.2.1: gluLookAt in the shader).
uniform vec3 uSceneCentre;
uniform float uShadowRadius;

vec3 lightUpHint(vec3 dirToLight) {
  return abs(dirToLight.y) > 0.99 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
}

// World point -> the light's clip (= NDC, orthographic) coordinates, each in [-1, 1] inside the
// bounding sphere; z = -1 nearest the light.
vec3 lightClipPosition(vec3 dirToLight, vec3 pointWorld) {
  float r = uShadowRadius;
  vec3 eye = uSceneCentre + dirToLight * r;
  vec3 f = -dirToLight;
  vec3 s = normalize(cross(f, lightUpHint(dirToLight)));
  vec3 u = cross(s, f);
  vec3 d = pointWorld - eye;
  return vec3(dot(s, d) / r, dot(u, d) / r, dot(f, d) / r - 1.0);
}
