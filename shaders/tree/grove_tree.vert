#version 300 es
// Grove, full mode: one unique tree's bark, leaves or flowers drawn once per instance (instanced);
// each instance moves and scales the tree (no rotation), skinned to ITS OWN sway poses (thesis
// eq. 3.15, core/sway/skin.h): instance k's node point j is pose-texture block k · uNodes + j.
// Shaded by tree.frag.
layout(location = 0) in vec3 aPosition;  // metres, the tree's own frame (base at the origin)
layout(location = 1) in vec3 aNormal;
layout(location = 4) in uint aJoint;     // node point of the vertex
layout(location = 5) in float aWeight;   // (l_jn / l_j)^alpha of its node (eq. 3.15)
layout(location = 7) in vec4 aInstance;  // xyz: position of the tree's base, w: scale

uniform mat4 uViewProjection;
uniform int uNodes;  // node points of the unique tree: the size of one instance's pose block

out vec3 vNormal;
out vec3 vWorld;
out float vSelected;
out vec2 vUv;  // tree.frag's texture coordinates: none here (plain colours)

#include "../common/skin.glsl"

void main() {
  vec3 translation, tipOffset;
  mat3 rotation = poseRotation(uint(gl_InstanceID) * uint(uNodes) + aJoint, translation, tipOffset);
  vec3 swayed = rotation * aPosition + translation + aWeight * tipOffset;
  vec3 world = aInstance.xyz + aInstance.w * swayed;  // the swayed tree scaled with the instance
  vNormal = rotation * aNormal;  // uniform scale, no instance rotation: only the sway turns normals
  vWorld = world;
  vSelected = 0.0;
  vUv = vec2(0.0);
  gl_Position = uViewProjection * vec4(world, 1.0);
}
