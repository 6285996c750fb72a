#version 300 es
// Grove, hybrid mode: the texture cards of one (unique tree, distance band) draw list, drawn once per
// instance of that band (instanced; moved and scaled, never rotated), shaded by card.frag.
layout(location = 0) in vec3 aPosition;  // metres, the tree's own frame
layout(location = 1) in vec2 aUv;        // atlas
layout(location = 7) in vec4 aInstance;  // xyz: position of the tree's base, w: scale

uniform mat4 uViewProjection;

out vec2 vUv;

void main() {
  vUv = aUv;
  gl_Position = uViewProjection * vec4(aInstance.xyz + aInstance.w * aPosition, 1.0);
}
