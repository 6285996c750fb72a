#version 300 es
// A moss tuft: its species colour, Lambert from the page's sun over an ambient.
precision highp float;

in vec3 vNormal;
in vec3 vColour;

uniform vec3 uLightDirection;

out vec4 outColor;

void main() {
  vec3 n = normalize(vNormal);
  if (!gl_FrontFacing) n = -n;
  float diffuse = max(dot(n, uLightDirection), 0.0);
  outColor = vec4(vColour * (0.45 + 0.65 * diffuse), 1.0);
}
