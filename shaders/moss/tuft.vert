#version 300 es
// One moss as a small tuft (Nomura 2010 §3.3: a moss of size s): the tuft's few triangles
// (aCorner: x, z across in units of s, y up along the normal in units of s) set on the moss's
// centre and turned to its normal, one instance per moss ever alive; a moss not alive on the day
// shown (birth ≤ uDay < death, death −1 while alive) is moved outside the clip volume, so the day
// scrubber replays the run without a new grow. Colour by species.
layout(location = 0) in vec3 aCorner;
layout(location = 1) in vec3 aPosition;  // per instance, metres
layout(location = 2) in vec3 aNormal;    // per instance
layout(location = 3) in float aSpecies;  // 0 gingoke, 1 haigoke, 2 sugigoke
layout(location = 4) in vec2 aLife;      // birth day, death day (−1: alive)

uniform mat4 uViewProjection;
uniform vec4 uModel;
uniform float uSize;  // the tuft's unit (m)
uniform float uDay;

out vec3 vNormal;
out vec3 vColour;

void main() {
  bool alive = aLife.x <= uDay && (aLife.y < 0.0 || uDay < aLife.y);
  vec3 up = normalize(aNormal);
  vec3 side = abs(up.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
  vec3 t = normalize(cross(side, up));
  vec3 b = cross(up, t);
  vec3 p = aPosition + uSize * (aCorner.x * t + aCorner.y * up + aCorner.z * b);
  vNormal = normalize(up + 0.6 * (aCorner.x * t + aCorner.z * b));
  int s = int(aSpecies + 0.5);
  vColour = s == 0 ? vec3(0.62, 0.72, 0.52) : s == 1 ? vec3(0.55, 0.68, 0.14) : vec3(0.13, 0.40, 0.15);
  gl_Position = alive ? uViewProjection * vec4((p - uModel.xyz) * uModel.w, 1.0) : vec4(2.0, 2.0, 2.0, 1.0);
}
