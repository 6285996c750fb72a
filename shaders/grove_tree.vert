#version 300 es
// Grove, full mode: one unique tree's bark, leaves or flowers drawn once per instance (instanced);
// each instance moves and scales the tree (no rotation), shaded by tree.frag.
layout(location = 0) in vec3 aPosition;  // metres, the tree's own frame (base at the origin)
layout(location = 1) in vec3 aNormal;
layout(location = 7) in vec4 aInstance;  // xyz: position of the tree's base, w: scale

uniform mat4 uViewProjection;

out vec3 vNormal;
out vec3 vWorld;
out float vSelected;

void main() {
  vec3 world = aInstance.xyz + aInstance.w * aPosition;
  vNormal = aNormal;  // uniform scale, no rotation: normals unchanged
  vWorld = world;
  vSelected = 0.0;
  gl_Position = uViewProjection * vec4(world, 1.0);
}
