#version 300 es
// Picking pass: bark only, each vertex carries its branch id, skinned like tree.vert so a swaying
// branch is picked where it is drawn; drawn into an offscreen framebuffer.
layout(location = 0) in vec3 aPosition;
layout(location = 2) in uint aBranch;
layout(location = 4) in uint aJoint;
layout(location = 5) in float aWeight;

uniform mat4 uViewProjection;

flat out uint vBranch;

#include "../common/skin.glsl"

void main() {
  vBranch = aBranch;
  gl_Position = uViewProjection * vec4(skinPosition(aJoint, aWeight, aPosition), 1.0);
}
