#version 300 es
// Lit ivy parts and support: half-Lambert sun plus a sky/ground hemisphere ambient, both faces lit
// (leaves are thin and a dropped mesh may be wound either way); uVariation adds a per-position
// hash so flat parts differ from one another. The base colour is uColor (display values) times
// uFactor (linear RGBA, glTF's baseColorFactor) times the vertex colour vColor (linear, COLOR_0),
// both taken to display values; uUseTexture = 1 multiplies in the texture uMap at vUv (its texels
// as stored: sRGB-encoded, display values): the .glb's leaf texture (core/ivy/ivy_leaf_texture.h)
// on the leaves, or a dropped glTF's baseColorTexture on the support. uAlphaCut: texels with
// alpha under it are discarded (0.5 on the leaves: the blade's outline; 0 on a support, drawn
// opaque). Values over 0.75 roll off smoothly towards 1 (a shoulder with slope 1 where it starts),
// so a white support keeps its shading on the lit side instead of clipping to one flat white.
precision highp float;

in vec3 vNormal;
in vec3 vWorld;
in vec2 vUv;
in vec4 vColor;

uniform vec3 uColor;
uniform vec3 uVariation;
uniform vec4 uFactor;
uniform vec3 uLightDirection;  // unit, towards the sun
uniform vec3 uCameraPosition;
uniform sampler2D uMap;  // RGBA8, row 0 = v 0 (glTF's origin)
uniform float uUseTexture;
uniform float uAlphaCut;

out vec4 outColor;

vec3 shoulder(vec3 c) {
  vec3 over = max(c - 0.75, 0.0);
  return min(c, vec3(0.75)) + 0.25 * (1.0 - exp(-over / 0.25));
}

float hash(vec3 p) {
  p = fract(p * vec3(12.9898, 78.233, 37.719));
  p += dot(p, p.yzx + 19.19);
  return fract((p.x + p.y) * p.z);
}

void main() {
  vec3 n = normalize(vNormal);
  vec3 view = normalize(uCameraPosition - vWorld);
  if (dot(n, view) < 0.0) n = -n;
  vec3 linear = max(uFactor.rgb * vColor.rgb, vec3(0.0));
  vec3 base = uColor * pow(linear, vec3(1.0 / 2.2));
  if (uUseTexture > 0.5) {
    vec4 texel = texture(uMap, vUv);
    if (texel.a * uFactor.a < uAlphaCut) discard;
    base *= texel.rgb;  // the flat colours are given in the same (display) values
  } else {
    base += uVariation * (hash(floor(vWorld * 6.0)) - 0.5);
  }
  float diffuse = 0.2 + 0.8 * max(dot(n, uLightDirection), 0.0);
  vec3 sky = vec3(0.62, 0.72, 0.85);
  vec3 ground = vec3(0.32, 0.30, 0.24);
  vec3 ambient = mix(ground, sky, 0.5 + 0.5 * n.y) * 0.45;
  vec3 color = base * (ambient + vec3(1.0, 0.97, 0.9) * diffuse * 0.8);
  outColor = vec4(pow(shoulder(color), vec3(1.0 / 1.1)), 1.0);
}
