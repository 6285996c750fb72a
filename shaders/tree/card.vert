#version 300 es
// Hybrid mode cards (thesis 4.2): textured quads of branches and leaf clusters, skinned to the sway;
// each vertex also in the sun's clip space for the shadow map (card_lit.frag).
layout(location = 0) in vec3 aPosition;  // metres
layout(location = 1) in vec2 aUv;        // atlas
layout(location = 4) in uint aJoint;
layout(location = 5) in float aWeight;

uniform mat4 uViewProjection;
uniform mat4 uSunViewProjection;    // the shadow map's (web/gl/shadow_map.js)
uniform float uShadowNormalOffset;  // metres towards the sun before the lookup
uniform vec3 uLightDirection;       // unit, towards the sun

out vec2 vUv;
out vec4 vShadow;  // the vertex in the sun's clip space

#include "../common/skin.glsl"

void main() {
  vUv = aUv;
  vec3 world = skinPosition(aJoint, aWeight, aPosition);
  // A card has no surface normal of its own (it stands for a branch and its leaves): the lookup
  // moves towards the sun, off the leaves the card stands for, against their own shadow's acne.
  vShadow = uSunViewProjection * vec4(world + uLightDirection * (2.0 * uShadowNormalOffset), 1.0);
  gl_Position = uViewProjection * vec4(world, 1.0);
}
