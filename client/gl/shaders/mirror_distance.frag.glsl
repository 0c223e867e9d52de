// The distance from the mirror's centre to the surface (the nearest wins by the depth test).
in vec3 vPositionWorld;
uniform vec3 uCentre;
out vec4 fragColor;
void main() { fragColor = vec4(length(vPositionWorld - uCentre), 0.0, 0.0, 1.0); }
