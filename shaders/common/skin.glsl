// Sway skinning shared by the vertex shaders (web/gl/program.js inserts it where a shader says
// #include "../common/skin.glsl", relative to that shader):
// node-point poses from core/sway/skin.h in a float texture, 4 RGBA32F texels per node point
// (R columns with M in w, then T), rows of 1024 texels. p' = R p + T + w M, n' = R n.
uniform highp sampler2D uPoses;

mat3 poseRotation(uint joint, out vec3 translation, out vec3 tipOffset) {
  int texel = int(joint) * 4;
  ivec2 at = ivec2(texel % 1024, texel / 1024);
  vec4 c0 = texelFetch(uPoses, at, 0);
  vec4 c1 = texelFetch(uPoses, at + ivec2(1, 0), 0);
  vec4 c2 = texelFetch(uPoses, at + ivec2(2, 0), 0);
  translation = texelFetch(uPoses, at + ivec2(3, 0), 0).xyz;
  tipOffset = vec3(c0.w, c1.w, c2.w);
  return mat3(c0.xyz, c1.xyz, c2.xyz);
}

vec3 skinPosition(uint joint, float weight, vec3 p) {
  vec3 t, m;
  mat3 r = poseRotation(joint, t, m);
  return r * p + t + weight * m;
}
