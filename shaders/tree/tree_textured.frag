#version 300 es
// Textured tree parts, as the exported .glb's materials (core/tree/tree_gltf.cpp): base colour from
// the part's procedural texture (sRGB), leaves and flowers alpha-tested at 0.5 (glTF MASK), bark
// lit through its tangent-space normal map (tangent frame from screen-space derivatives, as three.js
// does for a glTF without tangents); half-Lambert sun, shadowed by the sun's shadow map
// (../common/shadow.glsl), plus a sky/ground hemisphere ambient darkened by the crown's ambient
// occlusion (vOcclusion, core/tree/crown_occlusion.h); leaves get back part of what the crown
// takes, in their colour (see main).
// uDoubleSided = 1 for leaves and petals: the back face is lit with the flipped normal.
precision highp float;

in vec3 vNormal;
in vec3 vWorld;
in float vSelected;  // 1 on the selected branch, 0.5 above it (drawn highlighted)
in vec2 vUv;
in float vOcclusion;  // 0 open sky .. 1 none
in vec4 vShadow;      // the fragment in the sun's clip space

uniform sampler2D uBaseMap;     // RGBA8, row 0 = v 0 (glTF's origin)
uniform sampler2D uNormalMap;   // bark only (uUseNormalMap = 1)
uniform float uUseTexture;      // 0: plain uColor (no textures sent)
uniform float uUseNormalMap;
uniform float uAlphaCutoff;     // 0.5 for leaves and flowers, 0 for bark
uniform vec3 uColor;
uniform vec3 uColorVariation;   // plain mode: added with a per-position hash
uniform vec3 uLightDirection;   // unit, towards the sun
uniform vec3 uCameraPosition;
uniform float uDoubleSided;
uniform float uSpecular;
uniform float uXray;  // 1 in the see-through pass that shows a selection hidden behind leaves
uniform float uCrownLight;  // 1 for leaves: the light the crown takes comes partly back (main)

out vec4 outColor;

#include "../common/shadow.glsl"

float hash(vec3 p) {
  p = fract(p * vec3(12.9898, 78.233, 37.719));
  p += dot(p, p.yzx + 19.19);
  return fract((p.x + p.y) * p.z);
}

// The normal map's (x, y, z) around the surface normal n; the map's +y is up in the image, i.e.
// towards decreasing v (three.js negates normalScale.y for glTF for the same reason).
vec3 perturbNormal(vec3 n, vec3 mapN) {
  vec3 q0 = dFdx(vWorld), q1 = dFdy(vWorld);
  vec2 st0 = dFdx(vUv), st1 = dFdy(vUv);
  vec3 q1perp = cross(q1, n), q0perp = cross(n, q0);
  vec3 t = q1perp * st0.x + q0perp * st1.x;
  vec3 b = q1perp * st0.y + q0perp * st1.y;
  float det = max(dot(t, t), dot(b, b));
  float scale = det == 0.0 ? 0.0 : inversesqrt(det);
  return normalize(t * (mapN.x * scale) - b * (mapN.y * scale) + n * mapN.z);
}

// Mip level the sampler reads at vUv (from the texel footprint on screen).
float mipLevel(vec2 size) {
  vec2 dx = dFdx(vUv * size), dy = dFdy(vUv * size);
  return max(0.0, 0.5 * log2(max(dot(dx, dx), dot(dy, dy))));
}

void main() {
  if (uXray > 0.5 && vSelected <= 0.0) discard;
  vec3 n = normalize(vNormal);
  if (uDoubleSided > 0.5 && !gl_FrontFacing) n = -n;
  vec3 base;
  if (uUseTexture > 0.5) {
    vec4 texel = texture(uBaseMap, vUv);
    // Averaged mip levels thin a cut-out (needles vanish at a distance): alpha is scaled up with
    // the level so the coverage stays about that of the full-size texture.
    if (uAlphaCutoff > 0.0) texel.a *= 1.0 + 0.4 * mipLevel(vec2(textureSize(uBaseMap, 0)));
    if (texel.a < uAlphaCutoff) discard;
    base = pow(texel.rgb, vec3(2.2));  // sRGB to linear
    if (uUseNormalMap > 0.5) n = perturbNormal(n, texture(uNormalMap, vUv).xyz * 2.0 - 1.0);
  } else {
    base = pow(uColor + uColorVariation * (hash(floor(vWorld * 40.0)) - 0.5), vec3(2.2));
  }
  float diffuse = max(dot(n, uLightDirection), 0.0);
  if (uDoubleSided > 0.5) diffuse = 0.25 + 0.75 * diffuse;  // thin parts let light through
  float unshadowed = diffuse;  // the selection's mark stays bright in the shadow (it must show)
  float visible = sunVisibility(vShadow);
  // Light the crown takes from a leaf is not all lost (uCrownLight = 1, the leaves): in the shadow
  // of the leaves between it and the sun it gets the sunlight they let through (a leaf's
  // transmittance taken equal to its reflectance, the base colour, as for a thin leaf; its own
  // colour stands in for theirs), and the sky the crown hides (occlusion) is replaced by those
  // leaves, half of them sunlit. So a summer crown's shade is green and an autumn one's warm, not
  // grey. Bark and blossom (whose colour is not the leaves') get neither.
  vec3 through = uCrownLight > 0.5 ? base : vec3(0.0);
  vec3 sunColour = vec3(1.0, 0.97, 0.9) * 1.1;
  vec3 sun = sunColour * diffuse * (visible + (1.0 - visible) * through);
  vec3 sky = vec3(0.62, 0.72, 0.85);
  vec3 ground = vec3(0.32, 0.30, 0.24);
  vec3 ambient = mix(ground, sky, 0.5 + 0.5 * n.y) * 0.55 * (1.0 - 0.8 * vOcclusion)
      + 0.8 * vOcclusion * through * sunColour * 0.5;
  vec3 view = normalize(uCameraPosition - vWorld);
  vec3 halfway = normalize(view + uLightDirection);
  float spec = uSpecular * pow(max(dot(n, halfway), 0.0), 24.0);
  vec3 color = base * (ambient + sun) + vec3(spec);
  color = pow(color, vec3(1.0 / 2.2));  // linear to sRGB
  vec3 mark = vSelected > 0.75 ? vec3(1.0, 0.55, 0.1) : vec3(1.0, 0.85, 0.25);
  color = mix(color, mark * (0.45 + 0.75 * unshadowed), vSelected > 0.0 ? 0.85 : 0.0);
  outColor = vec4(color, uXray > 0.5 ? 0.65 : 1.0);
}
