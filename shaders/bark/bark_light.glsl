// The bark views' one lighting (included by quad.frag and trunk.frag): the base colour lit
// through the normal map (tangent space, OpenGL: green up the image = up the trunk) by a key
// light, over an ambient darkened by the ORM map's occlusion (red), with a faint broad highlight
// (the ORM map's roughness, green, is near 1 for bark). T, B, N: the surface's tangent frame
// (around, up, out); eye: towards the viewer.
vec3 barkLit(vec3 base, vec3 normalSample, vec3 orm, vec3 T, vec3 B, vec3 N, vec3 light, vec3 eye) {
  vec3 t = normalSample * 2.0 - 1.0;
  vec3 n = normalize(T * t.x + B * t.y + N * t.z);
  float diffuse = max(dot(n, light), 0.0);
  float ambient = (0.30 + 0.08 * n.y) * orm.r;
  float shininess = mix(24.0, 4.0, orm.g);
  float spec = 0.05 * (1.0 - orm.g * 0.7) * pow(max(dot(n, normalize(light + eye)), 0.0), shininess);
  return base * (ambient + 0.85 * diffuse) + spec;
}
