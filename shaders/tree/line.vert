#version 300 es
// Hybrid mode lines (thesis 4.2): six vertices per segment, each a corner of a screen-space quad of
// the segment's width D_i in pixels (eq. 4.1); the segment's data are read from data textures
// (rows of 1024 texels) by gl_VertexID, and both ends are skinned to the sway.
uniform highp sampler2D uLinePositions;  // 2 texels per segment: p0, p1 (metres)
uniform highp sampler2D uLineColors;     // eq. 4.2
uniform highp sampler2D uLineWidths;     // D_i, pixels (may be below 1)
uniform highp usampler2D uLineJoints;    // node points of p0, p1
uniform highp sampler2D uLineWeights;    // their eq. 3.15 weights

uniform mat4 uViewProjection;
uniform vec2 uViewport;  // pixels

out vec3 vColor;
out float vCoverage;  // a line thinner than a pixel is drawn 1 px wide and this opaque

#include "../common/skin.glsl"

ivec2 texelOf(int i) { return ivec2(i % 1024, i / 1024); }

void main() {
  int segment = gl_VertexID / 6;
  // Two triangles (0, 1, 2) and (2, 1, 3) over the corners 0, 1 at p0 and 2, 3 at p1.
  int corner = gl_VertexID % 6;
  corner = corner < 3 ? corner : (corner == 3 ? 2 : (corner == 4 ? 1 : 3));
  vec3 p0 = texelFetch(uLinePositions, texelOf(2 * segment), 0).xyz;
  vec3 p1 = texelFetch(uLinePositions, texelOf(2 * segment + 1), 0).xyz;
  uvec2 joints = texelFetch(uLineJoints, texelOf(segment), 0).xy;
  vec2 weights = texelFetch(uLineWeights, texelOf(segment), 0).xy;
  float d = texelFetch(uLineWidths, texelOf(segment), 0).x;
  float width = max(d, 1.0);
  vCoverage = clamp(d, 0.0, 1.0);
  vec4 c0 = uViewProjection * vec4(skinPosition(joints.x, weights.x, p0), 1.0);
  vec4 c1 = uViewProjection * vec4(skinPosition(joints.y, weights.y, p1), 1.0);
  bool far = corner >= 2;
  float side = (corner & 1) == 0 ? -1.0 : 1.0;
  vec2 s0 = c0.xy / max(c0.w, 1e-6) * uViewport * 0.5;
  vec2 s1 = c1.xy / max(c1.w, 1e-6) * uViewport * 0.5;
  vec2 along = s1 - s0;
  vec2 normal = length(along) > 1e-6 ? normalize(vec2(-along.y, along.x)) : vec2(1.0, 0.0);
  vec4 clip = far ? c1 : c0;
  clip.xy += normal * side * 0.5 * width / (uViewport * 0.5) * clip.w;
  vColor = texelFetch(uLineColors, texelOf(segment), 0).rgb;
  gl_Position = clip;
}
