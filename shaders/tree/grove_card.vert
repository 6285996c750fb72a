#version 300 es
// Grove, hybrid mode: the texture cards of one (unique tree, distance band) draw list, drawn once per
// instance of that band (instanced; moved, scaled and turned about y by aTurn: 0 in the grove, the
// garden's copies' turn in the garden, garden_hybrid.js), skinned to that instance's
// sway poses (pose block aBlock: the band's members are ordered by distance, not by instance),
// shaded by card.frag.
layout(location = 0) in vec3 aPosition;  // metres, the tree's own frame
layout(location = 1) in vec2 aUv;        // atlas
layout(location = 4) in uint aJoint;     // node point of the card corner
layout(location = 5) in float aWeight;   // its eq. 3.15 weight
layout(location = 7) in vec4 aInstance;  // xyz: position of the tree's base, w: scale
layout(location = 9) in float aBlock;    // the instance's pose block (its index among the tree's instances)
layout(location = 10) in float aTurn;    // radians about y (shaders/common/turn.glsl)

uniform mat4 uViewProjection;
uniform int uNodes;  // node points per pose block

out vec2 vUv;

#include "../common/skin.glsl"
#include "../common/turn.glsl"

void main() {
  vUv = aUv;
  vec3 swayed = skinPosition(uint(aBlock) * uint(uNodes) + aJoint, aWeight, aPosition);
  gl_Position = uViewProjection * vec4(aInstance.xyz + aInstance.w * turn(swayed, aTurn), 1.0);
}
