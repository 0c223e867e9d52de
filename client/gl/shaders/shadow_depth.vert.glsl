// One caster's depth render into its atlas tile: the CPU's lightClipFromWorld (light_clip.h).
in vec3 aPosition;
uniform mat4 uLightClipFromWorld;
void main() { gl_Position = uLightClipFromWorld * vec4(aPosition, 1.0); }
