#version 300 es
// Lit tree parts: half-Lambert sun plus a sky/ground hemisphere ambient.
// uDoubleSided = 1 for leaves and petals: the back face is lit with the flipped normal.
// uUseTexture = 1 (the grove renderer's card atlas of a tree in simulated bark, the garden's far
// trees): the base colour is uBaseMap at vUv instead of uColor, as shaders/garden/garden.frag
// takes its bark map; 0 everywhere else (the plain colours).
precision highp float;

in vec3 vNormal;
in vec3 vWorld;
in float vSelected;  // 1 on the selected branch, 0.5 above it (drawn highlighted)
in vec2 vUv;

uniform sampler2D uBaseMap;  // RGBA8, row 0 = v 0 (with uUseTexture = 1)
uniform float uUseTexture;
uniform float uAlphaCutoff;  // with uUseTexture: texels below it are cut out (0: none)

uniform vec3 uColor;
uniform vec3 uColorVariation;  // added with a per-position hash (leaf-to-leaf variation)
uniform vec3 uLightDirection;  // unit, towards the sun
uniform vec3 uCameraPosition;
uniform float uDoubleSided;
uniform float uSpecular;
uniform float uXray;  // 1 in the see-through pass that shows a selection hidden behind leaves

out vec4 outColor;

float hash(vec3 p) {
  p = fract(p * vec3(12.9898, 78.233, 37.719));
  p += dot(p, p.yzx + 19.19);
  return fract((p.x + p.y) * p.z);
}

void main() {
  if (uXray > 0.5 && vSelected <= 0.0) discard;
  vec3 n = normalize(vNormal);
  if (uDoubleSided > 0.5 && !gl_FrontFacing) n = -n;
  vec3 base = uColor + uColorVariation * (hash(floor(vWorld * 40.0)) - 0.5);
  if (uUseTexture > 0.5) {
    vec4 texel = texture(uBaseMap, vUv);
    if (texel.a < uAlphaCutoff) discard;
    base = texel.rgb;
  }
  float diffuse = max(dot(n, uLightDirection), 0.0);
  if (uDoubleSided > 0.5) diffuse = 0.25 + 0.75 * diffuse;  // thin parts let light through
  vec3 sky = vec3(0.62, 0.72, 0.85);
  vec3 ground = vec3(0.32, 0.30, 0.24);
  vec3 ambient = mix(ground, sky, 0.5 + 0.5 * n.y) * 0.45;
  vec3 view = normalize(uCameraPosition - vWorld);
  vec3 halfway = normalize(view + uLightDirection);
  float spec = uSpecular * pow(max(dot(n, halfway), 0.0), 24.0);
  vec3 color = base * (ambient + vec3(1.0, 0.97, 0.9) * diffuse * 0.85) + vec3(spec);
  vec3 mark = vSelected > 0.75 ? vec3(1.0, 0.55, 0.1) : vec3(1.0, 0.85, 0.25);
  color = mix(color, mark * (0.45 + 0.75 * diffuse), vSelected > 0.0 ? 0.85 : 0.0);
  outColor = vec4(pow(color, vec3(1.0 / 1.1)), uXray > 0.5 ? 0.65 : 1.0);
}
