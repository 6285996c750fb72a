#version 300 es
// The moss study's land (Nomura 2010 §3.2): three vertices per soil cell in metres, y up, with the
// cell's flat normal, its geology, the coverage of the day shown (in [0, 1]) and the value of the
// overlay's field (S in W/m², T_s in K, rh_s, theta or best-species G of the last day), drawn through uModel (an offset and a uniform scale that fit the land in the view).
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in float aCoverage;
layout(location = 3) in float aValue;
layout(location = 4) in float aGeology;  // 0 humus, 1 sandy, 2 asphalt

uniform mat4 uViewProjection;
uniform vec4 uModel;  // xyz: offset subtracted, w: scale (world = (p - offset) * scale)

out vec3 vNormal;
out float vCoverage;
out float vValue;
out float vGeology;

void main() {
  vNormal = aNormal;
  vCoverage = aCoverage;
  vValue = aValue;
  vGeology = aGeology;
  gl_Position = uViewProjection * vec4((aPosition - uModel.xyz) * uModel.w, 1.0);
}
