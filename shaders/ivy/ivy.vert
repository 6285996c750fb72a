#version 300 es
// Ivy parts and their support (paper 004): positions in the scene's units, drawn through uModel
// (a uniform scale and offset that fits the scene in the view). aBirth is the step at which the
// part was made (core/ivy/ivy_mesh.h birth_step, the .glb's _BIRTH_STEP): a part born after the
// scrubber's step uStep is moved outside the clip volume, so the page replays the growth without
// regrowing it. The support has no birth attribute (the constant 0: always drawn). aUv: the
// leaves' texture coordinates (the .glb's TEXCOORD_0), or a dropped glTF support's base colour
// uvs (its material's baseColorTexture set, KHR_texture_transform applied by io/gltf_reader);
// aColor: a dropped glTF's COLOR_0 (linear RGBA; the constant (1, 1, 1, 1) on every other part).
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in float aBirth;
layout(location = 3) in vec2 aUv;
layout(location = 4) in vec4 aColor;

uniform mat4 uViewProjection;
uniform vec4 uModel;  // xyz: offset subtracted, w: scale (world = (p - offset) * scale)
uniform float uStep;

out vec3 vNormal;
out vec3 vWorld;
out vec2 vUv;
out vec4 vColor;

void main() {
  vec3 world = (aPosition - uModel.xyz) * uModel.w;
  vNormal = aNormal;
  vWorld = world;
  vUv = aUv;
  vColor = aColor;
  gl_Position = aBirth > uStep + 0.5 ? vec4(2.0, 2.0, 2.0, 1.0) : uViewProjection * vec4(world, 1.0);
}
