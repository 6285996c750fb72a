#version 300 es
// Tree parts (bark tubes, leaf quads, flowers): rest positions in metres, y up, skinned to the sway
// node points (thesis eq. 3.15 as core/sway/skin.h writes it), leaves flutter in the wind
// (tree_pose.glsl). aHighlight: 1 on the selected branch, 0.5 on the branches a cut there would
// take with it, else 0 (a per-vertex buffer for the bark; the constant 0 for leaves and flowers).
// aOcclusion: the crown's ambient occlusion (core/tree/crown_occlusion.h; constant 0 without).
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 3) in float aHighlight;
layout(location = 4) in uint aJoint;   // node point of the vertex
layout(location = 5) in float aWeight; // (l_jn / l_j)^alpha of its node (eq. 3.15)
layout(location = 6) in vec2 aUv;      // texture coordinates (leaves: v = 0 at the petiole, 1 at the tip)
layout(location = 7) in float aOcclusion;

uniform mat4 uViewProjection;
uniform mat4 uSunViewProjection;  // the shadow map's (web/gl/shadow_map.js)
uniform float uShadowNormalOffset;  // metres along the normal (towards the sun) before the lookup
uniform vec3 uLightDirection;       // unit, towards the sun
// The selection's x-ray pass only (else 0): how far each side of a selected branch is pushed out
// on screen, in clip-space x and y (tree_renderer.js XRAY_WIDEN_PX / the drawing buffer's size: the
// branch drawn that many pixels wider; a twig thinner than a pixel has no fragments, so a branch
// picked in a dense crown showed no highlight at all).
uniform vec2 uXrayWiden;

out vec3 vNormal;
out vec3 vWorld;
out float vSelected;
out vec2 vUv;  // for tree_textured.frag (tree.frag ignores it)
out float vOcclusion;
out vec4 vShadow;  // the vertex in the sun's clip space

#include "../common/skin.glsl"
#include "tree_pose.glsl"

void main() {
  mat3 rotation;
  vec3 world = swayedWorld(aPosition, aJoint, aWeight, aUv, rotation);
  vNormal = rotation * aNormal;
  vWorld = world;
  vSelected = aHighlight;
  vUv = aUv;
  vOcclusion = aOcclusion;
  // Normal offset against shadow acne: the lookup point moves off the surface towards the sun's
  // side (both faces of a leaf alike).
  vec3 n = normalize(vNormal);
  vec3 towards = dot(n, uLightDirection) >= 0.0 ? n : -n;
  vShadow = uSunViewProjection * vec4(world + towards * uShadowNormalOffset, 1.0);
  gl_Position = uViewProjection * vec4(world, 1.0);
  if (aHighlight > 0.0 && uXrayWiden.x > 0.0) {
    // The tube's vertices pushed apart on screen along their normals' projection, by uXrayWiden
    // (times clip w: the same pixels at any depth). A normal seen end-on is left where it is.
    vec2 side = (uViewProjection * vec4(rotation * aNormal, 0.0)).xy;
    float len = length(side);
    if (len > 1e-6) gl_Position.xy += side / len * uXrayWiden * gl_Position.w;
  }
}
