#version 300 es
// The garden page's colours: uMode 0 the ground, moss green in the hollows to dry grass and earth
// on the heights (by height over uRelief), or its overlay uOverlay: 1 the moss's light of its last
// day (vTint, W/m²: dark blue 0, teal 50 (the thesis's mosses grow below it), yellow 300 and over;
// grey where the moss has no cell), 2 the slope (green 0°, yellow 20°, red 45° and over), 3
// altitude bands uBand metres high with a dark line at each band's foot; 1 the objects (plaster walls, grey rocks and stone
// lanterns, the .glb's materials) and the ivy on them (brown stems, dark green leaves); 2 the
// trees (bark brown, leaves green, flowers pale pink); a distinct tree with simulated bark (uBarkSim
// 1: the garden's bark 1) wears its bark maps instead of the brown: base colour uBarkMap and the
// tangent-space normal map uBarkNormal (tangent frame from screen-space derivatives, as the tree
// page's tree_textured.frag). Ivy born after the year shown (vBirth over
// uYear: the year scrubber) is not drawn. The ground drawn through its level of detail (uGround.w
// 1: web/garden/ground_lod.js, fewer of the grid's vertices far away) reads its normal and moss light
// per fragment from uGroundMap (the grid's own per-vertex values, one texel a vertex, filtered as the
// full grid's triangles would interpolate them), so its light and overlays keep the grid's detail.
// Lambert from the frame's sun, shadowed by its shadow map, over a sky/ground ambient; both faces
// lit (leaves are cards).
precision highp float;

#include "../common/shadow.glsl"

in vec3 vNormal;
in float vTint;
in float vHeight;
in vec4 vShadow;
in float vBirth;
in vec2 vUv;
in vec3 vWorld;

uniform vec3 uLightDirection;  // unit, towards the sun
uniform int uMode;
uniform float uRelief;
uniform int uOverlay;  // the ground's: 0 none, 1 moss light, 2 slope, 3 altitude bands
uniform float uBand;   // m, an altitude band's height
uniform float uYear;   // the garden year shown
uniform int uBarkSim;  // 1: the trees drawn wear uBarkMap and uBarkNormal on their bark
uniform sampler2D uBarkMap;     // RGBA8 base colour, row 0 = v 0
uniform sampler2D uBarkNormal;  // RGBA8 OpenGL normal map
uniform vec4 uGround;           // the ground's grid: half its size (m), its cell (m), vertices a side, 1 on
uniform sampler2D uGroundMap;   // RGBA16F per grid vertex: normal xyz, the moss light (vTint's)

out vec4 outColor;

// The normal map's (x, y, z) around the surface normal n; the map's +y is up in the image, i.e.
// towards decreasing v (as tree_textured.frag). The derivatives are taken by the caller in uniform
// control flow.
vec3 perturbNormal(vec3 n, vec3 mapN, vec3 q0, vec3 q1, vec2 st0, vec2 st1) {
  vec3 q1perp = cross(q1, n), q0perp = cross(n, q0);
  vec3 t = q1perp * st0.x + q0perp * st1.x;
  vec3 b = q1perp * st0.y + q0perp * st1.y;
  float det = max(dot(t, t), dot(b, b));
  float scale = det == 0.0 ? 0.0 : inversesqrt(det);
  return normalize(t * (mapN.x * scale) - b * (mapN.y * scale) + n * mapN.z);
}

void main() {
  if (vBirth > uYear + 0.5) discard;
  vec3 n = normalize(vNormal);
  if (!gl_FrontFacing) n = -n;
  // The bark maps and the tangent frame's derivatives, read before any branch on a varying.
  vec3 barkColour = vec3(0.0), barkN = vec3(0.0, 0.0, 1.0);
  vec3 q0 = dFdx(vWorld), q1 = dFdy(vWorld);
  vec2 st0 = dFdx(vUv), st1 = dFdy(vUv);
  if (uBarkSim == 1) {
    barkColour = texture(uBarkMap, vUv).rgb;
    barkN = texture(uBarkNormal, vUv).xyz * 2.0 - 1.0;
  }
  float tint = vTint;
  if (uMode == 0 && uGround.w > 0.5) {
    vec4 g = texture(uGroundMap, ((vWorld.xz + uGround.x) / uGround.y + 0.5) / uGround.z);
    n = normalize(g.xyz);
    if (!gl_FrontFacing) n = -n;
    tint = g.w;
  }
  vec3 base;
  if (uMode == 0 && uOverlay == 1) {
    float s = tint;
    vec3 dark = vec3(0.12, 0.10, 0.38), teal = vec3(0.10, 0.58, 0.52), yellow = vec3(0.96, 0.88, 0.22);
    base = s < 0.0 ? vec3(0.5) : s < 50.0 ? mix(dark, teal, s / 50.0) : mix(teal, yellow, clamp((s - 50.0) / 250.0, 0.0, 1.0));
  } else if (uMode == 0 && uOverlay == 2) {
    float deg = degrees(acos(clamp(abs(n.y), 0.0, 1.0)));
    vec3 green = vec3(0.20, 0.55, 0.20), yellow = vec3(0.90, 0.80, 0.20), red = vec3(0.80, 0.15, 0.10);
    base = deg < 20.0 ? mix(green, yellow, deg / 20.0) : mix(yellow, red, clamp((deg - 20.0) / 25.0, 0.0, 1.0));
  } else if (uMode == 0 && uOverlay == 3) {
    float b = vHeight / max(uBand, 1e-3);
    float k = mod(floor(b), 2.0);
    base = k < 0.5 ? vec3(0.78, 0.70, 0.52) : vec3(0.55, 0.66, 0.45);
    if (fract(b) < 0.06 && vHeight > 0.02) base *= 0.45;  // not on the flat at the lowest point
  } else if (uMode == 0) {
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
    if (k == 0 && uBarkSim == 1) {
      base = barkColour;
      n = perturbNormal(n, barkN, q0, q1, st0, st1);
    }
  }
  float lit = sunVisibility(vShadow);
  float diffuse = max(dot(n, uLightDirection), 0.0) * lit;
  float ambient = 0.38 + 0.12 * n.y;
  outColor = vec4(base * (ambient + 0.75 * diffuse), 1.0);
}
