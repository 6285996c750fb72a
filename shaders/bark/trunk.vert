#version 300 es
// A trunk segment wearing the bark maps (spec §6 "a lit trunk segment"): a cylinder of the
// patch's radius and height (cm) standing beside the tile, the tile wrapped once around it (u =
// angle / 2π from the front, increasing towards +x; v up the trunk), with its tangent frame for
// the normal map (T around, B up, N out: right-handed).
layout(location = 0) in vec2 aAround;  // angle (radians), height share 0..1

uniform mat4 uViewProjection;
uniform vec4 uModel;   // xyz: offset subtracted (cm), w: scale
uniform vec3 uCentre;  // the axis's foot (cm)
uniform vec2 uSize;    // radius, height (cm)

out vec2 vUv;
out vec3 vNormal;
out vec3 vTangent;
out vec3 vPosition;

void main() {
  float phi = aAround.x;
  vec3 n = vec3(sin(phi), 0.0, cos(phi));
  vNormal = n;
  vTangent = vec3(cos(phi), 0.0, -sin(phi));
  vUv = vec2(phi / 6.28318530718, 1.0 - aAround.y);
  vec3 p = uCentre + vec3(n.x * uSize.x, aAround.y * uSize.y, n.z * uSize.x);
  vPosition = (p - uModel.xyz) * uModel.w;
  gl_Position = uViewProjection * vec4(vPosition, 1.0);
}
