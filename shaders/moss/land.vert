#version 300 es
// The moss study's land (Nomura 2010 §3.2): three vertices per soil cell in metres, y up, with the
// cell's flat normal, its geology and its overlay values of the last day (coverage in [0, 1],
// irradiance S in W/m²), drawn through uModel (an offset and a uniform scale that fit the land in the view).
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in float aCoverage;
layout(location = 3) in float aIrradiance;
layout(location = 4) in float aGeology;  // 0 humus, 1 sandy, 2 asphalt

uniform mat4 uViewProjection;
uniform vec4 uModel;  // xyz: offset subtracted, w: scale (world = (p - offset) * scale)

out vec3 vNormal;
out float vCoverage;
out float vIrradiance;
out float vGeology;

void main() {
  vNormal = aNormal;
  vCoverage = aCoverage;
  vIrradiance = aIrradiance;
  vGeology = aGeology;
  gl_Position = uViewProjection * vec4((aPosition - uModel.xyz) * uModel.w, 1.0);
}
