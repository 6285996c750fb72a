#version 300 es
// Picking pass: bark only, each vertex carries its branch id, drawn into an offscreen framebuffer.
layout(location = 0) in vec3 aPosition;
layout(location = 2) in uint aBranch;

uniform mat4 uViewProjection;

flat out uint vBranch;

void main() {
  vBranch = aBranch;
  gl_Position = uViewProjection * vec4(aPosition, 1.0);
}
