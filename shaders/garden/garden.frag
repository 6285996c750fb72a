#version 300 es
// The garden page's colours: uMode 0 the ground, moss green in the hollows to dry grass and earth
// on the heights (by height over uRelief); 1 the objects (plaster walls, grey rocks and stone
// lanterns, the .glb's materials) and the ivy on them (brown stems, dark green leaves); 2 the
// trees (bark brown, leaves green, flowers pale pink).
// Lambert from the frame's sun, shadowed by its shadow map, over a sky/ground ambient; both faces
// lit (leaves are cards).
precision highp float;

#include "../common/shadow.glsl"

in vec3 vNormal;
in float vTint;
in float vHeight;
in vec4 vShadow;

uniform vec3 uLightDirection;  // unit, towards the sun
uniform int uMode;
uniform float uRelief;

out vec4 outColor;

void main() {
  vec3 n = normalize(vNormal);
  if (!gl_FrontFacing) n = -n;
  vec3 base;
  if (uMode == 0) {
    float t = clamp(vHeight / max(uRelief, 1e-3), 0.0, 1.0);
    vec3 low = vec3(0.30, 0.42, 0.20), mid = vec3(0.45, 0.50, 0.28), high = vec3(0.58, 0.52, 0.38);
    base = t < 0.5 ? mix(low, mid, t * 2.0) : mix(mid, high, t * 2.0 - 1.0);
  } else if (uMode == 1) {
    int k = int(vTint + 0.5);
    base = k == 0 ? vec3(0.86, 0.82, 0.74) : k == 1 ? vec3(0.50, 0.50, 0.48) : k == 2 ? vec3(0.62, 0.61, 0.57)
         : k == 3 ? vec3(0.34, 0.27, 0.18) : vec3(0.15, 0.34, 0.11);
  } else {
    int k = int(vTint + 0.5);
    base = k == 0 ? vec3(0.36, 0.25, 0.16) : k == 1 ? vec3(0.22, 0.46, 0.16) : vec3(0.95, 0.80, 0.85);
  }
  float lit = sunVisibility(vShadow);
  float diffuse = max(dot(n, uLightDirection), 0.0) * lit;
  float ambient = 0.38 + 0.12 * n.y;
  outColor = vec4(base * (ambient + 0.75 * diffuse), 1.0);
}
