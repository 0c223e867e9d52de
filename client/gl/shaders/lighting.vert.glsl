// World-space meshes (no model matrix) through the orbit camera's clipFromView * viewFromWorld.
in vec3 aPosition;
in vec3 aNormal;
uniform mat4 uClipFromWorld;
out vec3 vPositionWorld;
out vec3 vNormalWorld;
void main() {
  vPositionWorld = aPosition;
  vNormalWorld = aNormal;
  gl_Position = uClipFromWorld * vec4(aPosition, 1.0);
}
