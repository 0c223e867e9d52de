// A picture (8-bit RGB, row 0 at the top, encoded for display already) drawn to fill the viewport
// (picture_pass.h), sampled bilinearly: a composite shown in the window at the window's size.
uniform sampler2D uPicture;
uniform ivec2 uOriginPx;  // the viewport's lower-left corner in the framebuffer, pixels
uniform ivec2 uSizePx;    // the viewport's size, pixels
out vec4 fragColor;

void main() {
  vec2 uv = (gl_FragCoord.xy - vec2(uOriginPx)) / vec2(uSizePx);
  fragColor = vec4(texture(uPicture, vec2(uv.x, 1.0 - uv.y)).rgb, 1.0);
}
