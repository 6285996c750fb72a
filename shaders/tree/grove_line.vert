#version 300 es
// Grove, hybrid mode: the line segments of one (unique tree, distance band) draw list as screen-space
// quads (like line.vert), for every instance of the band at once: the segments are read from a
// float texture (4 RGBA texels each: p0 + width px, p1, eq. 4.2 colour, the sway skin of both ends
// (joint0, joint1, weight0, weight1); rows of 1024 texels), both ends skinned to the instance's
// pose block aBlock (skin.glsl),
// 4 indexed vertices per segment (uThin false), or 2 per segment drawn as gl.LINES for segments at
// most a pixel wide (uThin true, from segment uFirst on); one GL instance per tree instance. Shaded
// by grove_line.frag.
layout(location = 0) in vec4 aInstance;   // xyz: position of the tree's base, w: scale
layout(location = 1) in float aWidthScale;  // band representative's depth / this instance's depth
layout(location = 2) in float aBlock;       // the instance's pose block (index among the tree's instances)
layout(location = 3) in float aTurn;        // radians about y (0 in the grove; the garden's copies')

uniform highp sampler2D uSegments;
uniform mat4 uViewProjection;
uniform vec2 uViewport;  // pixels
uniform bool uThin;      // gl.LINES: vertex 2 s is p0 of segment uFirst + s, 2 s + 1 its p1
uniform int uFirst;
uniform int uNodes;  // node points per pose block

out vec3 vColor;
out float vCoverage;  // a line thinner than a pixel is drawn 1 px wide and this opaque

vec4 texel(int i) { return texelFetch(uSegments, ivec2(i % 1024, i / 1024), 0); }

#include "../common/skin.glsl"
#include "../common/turn.glsl"

// End `end` (0: p0, 1: p1) of a segment at p, swayed with this instance's poses, in the world.
vec3 world(vec3 p, vec4 skin, int end) {
  uint joint = uint(aBlock) * uint(uNodes) + uint(end == 0 ? skin.x : skin.y);
  return aInstance.xyz + aInstance.w * turn(skinPosition(joint, end == 0 ? skin.z : skin.w, p), aTurn);
}

void main() {
  if (uThin) {
    int segment = uFirst + gl_VertexID / 2;
    vec4 a = texel(segment * 4);
    int end = gl_VertexID & 1;
    vec3 p = end == 0 ? a.xyz : texel(segment * 4 + 1).xyz;
    vCoverage = clamp(a.w * aWidthScale, 0.0, 1.0);
    vColor = texel(segment * 4 + 2).rgb;
    gl_Position = uViewProjection * vec4(world(p, texel(segment * 4 + 3), end), 1.0);
    return;
  }
  int segment = gl_VertexID / 4;  // indexed: 4 vertices per segment (triangles 0 1 2, 2 1 3)
  int k = gl_VertexID % 4;
  vec4 a = texel(segment * 4), b = texel(segment * 4 + 1), c = texel(segment * 4 + 2);
  vec4 skin = texel(segment * 4 + 3);
  vec4 c0 = uViewProjection * vec4(world(a.xyz, skin, 0), 1.0);
  vec4 c1 = uViewProjection * vec4(world(b.xyz, skin, 1), 1.0);
  bool far = k >= 2;
  float side = (k & 1) == 0 ? -1.0 : 1.0;
  vec2 s0 = c0.xy / max(c0.w, 1e-6) * uViewport * 0.5;
  vec2 s1 = c1.xy / max(c1.w, 1e-6) * uViewport * 0.5;
  vec2 along = s1 - s0;
  vec2 normal = length(along) > 1e-6 ? normalize(vec2(-along.y, along.x)) : vec2(1.0, 0.0);
  float d = a.w * aWidthScale;  // eq. 4.1 D_i at this instance's distance and scale, pixels
  float width = max(d, 1.0);
  vCoverage = clamp(d, 0.0, 1.0);
  vec4 clip = far ? c1 : c0;
  clip.xy += normal * side * 0.5 * width / (uViewport * 0.5) * clip.w;
  vColor = c.rgb;
  gl_Position = clip;
}
