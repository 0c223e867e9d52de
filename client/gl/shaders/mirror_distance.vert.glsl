// A mesh seen from a mirror's centre through one face of its distance cube (mirror_occlusion.h).
in vec3 aPosition;
uniform mat4 uClipFromWorld;
out vec3 vPositionWorld;
void main() {
  vPositionWorld = aPosition;
  gl_Position = uClipFromWorld * vec4(aPosition, 1.0);
}
