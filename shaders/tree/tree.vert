#version 300 es
// Tree parts (bark tubes, leaf quads, flowers): rest positions in metres, y up, skinned to the sway
// node points (thesis eq. 3.15 as core/sway/skin.h writes it), leaves flutter in the wind.
// aHighlight: 1 on the selected branch, 0.5 on the branches a cut there would take with it, else 0
// (a per-vertex buffer for the bark; the constant 0 for leaves and flowers).
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 3) in float aHighlight;
layout(location = 4) in uint aJoint;   // node point of the vertex
layout(location = 5) in float aWeight; // (l_jn / l_j)^alpha of its node (eq. 3.15)
layout(location = 6) in vec2 aUv;      // texture coordinates (leaves: v = 0 at the petiole, 1 at the tip)

uniform mat4 uViewProjection;
uniform float uTime;        // simulated time, s
uniform float uFlutter;     // leaf flutter amplitude as a fraction of the leaf length
uniform float uLeafLength;  // metres

out vec3 vNormal;
out vec3 vWorld;
out float vSelected;
out vec2 vUv;  // for tree_textured.frag (tree.frag ignores it)

#include "../common/skin.glsl"

float hash1(float x) { return fract(sin(x * 12.9898) * 43758.5453); }

void main() {
  vec3 translation, tipOffset;
  mat3 rotation = poseRotation(aJoint, translation, tipOffset);
  vec3 world = rotation * aPosition + translation + aWeight * tipOffset;
  // Leaf flutter (beyond the thesis): each leaf (8 vertices, both faces) flaps about its petiole
  // with its own phase and rate; the tip moves most, both faces alike so the leaf stays closed.
  if (uFlutter > 0.0) {
    float leaf = float(gl_VertexID / 8);
    float phase = 6.2831853 * hash1(leaf + float(aJoint) * 0.618);
    float rate = 7.0 + 5.0 * hash1(leaf * 1.7 + 3.1);
    world.y += uFlutter * uLeafLength * aUv.y * sin(rate * uTime + phase);
  }
  vNormal = rotation * aNormal;
  vWorld = world;
  vSelected = aHighlight;
  vUv = aUv;
  gl_Position = uViewProjection * vec4(world, 1.0);
}
