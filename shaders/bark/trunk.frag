#version 300 es
// The trunk segment: the base-colour map lit by the page's sun through the normal map (tangent
// space, OpenGL: green up the image = up the trunk), Lambert over a sky/ground ambient, with a
// faint broad highlight (bark is rough: the ORM map's roughness is near 1).
precision highp float;

in vec2 vUv;
in vec3 vNormal;
in vec3 vTangent;
in vec3 vPosition;

uniform sampler2D uBaseColour;
uniform sampler2D uNormalMap;
uniform vec3 uLightDirection;  // unit, towards the sun
uniform vec3 uEye;

out vec4 outColor;

void main() {
  vec3 N = normalize(vNormal), T = normalize(vTangent), B = cross(N, T);
  vec3 t = texture(uNormalMap, vUv).xyz * 2.0 - 1.0;
  vec3 n = normalize(T * t.x + B * t.y + N * t.z);
  vec3 base = texture(uBaseColour, vUv).rgb;
  float diffuse = max(dot(n, uLightDirection), 0.0);
  float ambient = 0.28 + 0.10 * n.y;
  vec3 h = normalize(uLightDirection + normalize(uEye - vPosition));
  float spec = 0.04 * pow(max(dot(n, h), 0.0), 8.0);
  outColor = vec4(base * (ambient + 0.85 * diffuse) + spec, 1.0);
}
