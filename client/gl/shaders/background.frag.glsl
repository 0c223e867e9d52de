// The cube map (level 0, linear within a face, as render/cube_map_sampling.h) in each pixel's
// primary-ray direction; alpha 0 marks the pixel as not covered. A cube made from a hemisphere
// map holds nothing below the horizon: black there, not the sky texels that linear filtering
// would blend half a texel below it (render::sampleBackground, render/cube_map_sampling.h).
uniform samplerCube uEnvironment;
uniform mat4 uWorldFromClip;
uniform vec3 uEye;
uniform vec2 uViewportPx;
uniform int uHemisphere;
out vec4 fragColor;
void main() {
  vec2 ndc = gl_FragCoord.xy / uViewportPx * 2.0 - 1.0;
  vec4 far = uWorldFromClip * vec4(ndc, 1.0, 1.0);
  vec3 dir = far.xyz / far.w - uEye;
  if (uHemisphere == 1 && dir.y < 0.0) {
    fragColor = vec4(0.0);
    return;
  }
  fragColor = vec4(textureLod(uEnvironment, dir, 0.0).rgb, 0.0);
}
