// Mirrors render::toneMap and render::srgbEncode (client/render/tone_mapping.cpp): Reinhard's
// global operator with white point, then sRGB, from the float lighting buffer to 8-bit display.
uniform sampler2D uLinear;
uniform float uScale;   // key / worldLuminance
uniform float uWhite2;  // whiteLuminance^2
out vec4 fragColor;

bool usable(float v) { return !isnan(v) && !isinf(v); }

vec3 toneMap(vec3 rgb) {
  float y = 0.2126 * rgb.r + 0.7152 * rgb.g + 0.0722 * rgb.b;
  if (!usable(y) || y <= 0.0 || !usable(rgb.r) || !usable(rgb.g) || !usable(rgb.b)) {
    return vec3(0.0);
  }
  float ls = uScale * y;
  float ld = ls * (1.0 + ls / uWhite2) / (1.0 + ls);
  return clamp(rgb * (ld / y), vec3(0.0), vec3(1.0));
}

float srgbEncode(float linear01) {
  float c = clamp(linear01, 0.0, 1.0);
  return c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1.0 / 2.4) - 0.055;
}

void main() {
  vec3 display = toneMap(texelFetch(uLinear, ivec2(gl_FragCoord.xy), 0).rgb);
  fragColor = vec4(srgbEncode(display.r), srgbEncode(display.g), srgbEncode(display.b), 1.0);
}
