#version 300 es
// The garden page's meshes (web/garden/garden_renderer.js): the ground, the objects and every
// distinct tree's mesh, in metres, y up; a tree's mesh drawn once per planted tree (instanced:
// aInstance = its foot x, y, z and its turn about y in radians, counter-clockwise seen from above,
// as the .glb's YawQuaternion); the ground and the objects with aInstance (0, 0, 0, 0). aTint: the
// ground's height (m), an object's kind (0 wall, 1 rock, 2 lantern, 3 ivy stem, 4 ivy leaf), a
// tree vertex's part (0 bark, 1 leaves, 2 flowers): garden.frag's colour. aBirth: the garden year
// an ivy vertex grew in (0 for every other vertex): garden.frag hides what the year shown (the
// year scrubber) had not grown. Blow (uSway 1): a tree vertex is first skinned to its copy's sway
// poses (core/sway/skin.h, eq. 3.15: node point aJoint of the copy's block starting at aBlock, in
// the tree's own frame), then turned and placed; uSway 0 draws the grown shape (the rest). aUv: a
// tree's bark texture coordinates when its distinct tree wears simulated bark (the garden's bark 1:
// its tile wrapped around each tube, as the .glb's), 0 elsewhere; vWorld for the normal map's
// tangent frame (garden.frag).
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in float aTint;
layout(location = 3) in vec4 aInstance;
layout(location = 4) in float aBirth;
layout(location = 5) in uint aJoint;    // the vertex's node point in its tree's sway model
layout(location = 6) in float aWeight;  // (l_jn / l_j)^alpha of its node (eq. 3.15)
layout(location = 7) in float aBlock;   // per copy: its first pose block
layout(location = 8) in vec2 aUv;       // a tree vertex's bark uv (simulated bark), else 0

uniform mat4 uViewProjection;
uniform mat4 uSunViewProjection;    // the shadow map's (web/gl/shadow_map.js)
uniform float uShadowNormalOffset;  // metres along the normal before the lookup
uniform int uSway;                  // 1: skin the trees to the poses (Blow)

out vec3 vNormal;
out float vTint;
out float vHeight;
out vec4 vShadow;
out float vBirth;
out vec2 vUv;
out vec3 vWorld;

#include "../common/turn.glsl"
#include "../common/skin.glsl"

void main() {
  vec3 local = aPosition, normal = aNormal;
  if (uSway == 1) {
    vec3 translation, tipOffset;
    mat3 rotation = poseRotation(uint(aBlock) + aJoint, translation, tipOffset);
    local = rotation * aPosition + translation + aWeight * tipOffset;
    normal = rotation * aNormal;
  }
  vec3 world = aInstance.xyz + turn(local, aInstance.w);
  vNormal = turn(normal, aInstance.w);
  vTint = aTint;
  vBirth = aBirth;
  vUv = aUv;
  vWorld = world;
  vHeight = world.y;
  vShadow = uSunViewProjection * vec4(world + normalize(vNormal + vec3(0.0, 1e-6, 0.0)) * uShadowNormalOffset, 1.0);
  gl_Position = uViewProjection * vec4(world, 1.0);
}
