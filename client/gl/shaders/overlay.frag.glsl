// The overlay picture (overlay_text.h: premultiplied RGBA8, row 0 at the top) drawn in a viewport
// of its own size at uOriginPx; blended with ONE, ONE_MINUS_SRC_ALPHA over the display.
uniform sampler2D uOverlay;
uniform ivec2 uOriginPx;  // the viewport's lower-left corner in the framebuffer, pixels
out vec4 fragColor;

void main() {
  ivec2 sizePx = textureSize(uOverlay, 0);
  ivec2 p = ivec2(gl_FragCoord.xy) - uOriginPx;
  fragColor = texelFetch(uOverlay, ivec2(p.x, sizePx.y - 1 - p.y), 0);
}
