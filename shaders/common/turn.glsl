// A turn about y by `a` radians, counter-clockwise seen from above (the garden's copies' turn, as
// the .glb's YawQuaternion), shared by the garden's meshes (shaders/garden/garden.vert) and the
// grove's cards and lines (shaders/tree/grove_card.vert, grove_line.vert).
vec3 turn(vec3 v, float a) {
  float c = cos(a), s = sin(a);
  return vec3(c * v.x + s * v.z, v.y, -s * v.x + c * v.z);
}
