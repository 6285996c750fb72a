// The tree's skinned and fluttering vertex (thesis eq. 3.15 as core/sway/skin.h writes it, leaf
// flutter beyond the thesis), shared by tree.vert and shadow.vert so the shadow moves with the tree.
// Needs ../common/skin.glsl included before it.
uniform float uTime;        // simulated time, s
uniform float uFlutter;     // leaf flutter amplitude as a fraction of the leaf length
uniform float uLeafLength;  // metres

float hash1(float x) { return fract(sin(x * 12.9898) * 43758.5453); }

// The world position (metres) of a rest-pose vertex; `rotation` its node point's rotation.
vec3 swayedWorld(vec3 position, uint joint, float weight, vec2 uv, out mat3 rotation) {
  vec3 translation, tipOffset;
  rotation = poseRotation(joint, translation, tipOffset);
  vec3 world = rotation * position + translation + weight * tipOffset;
  // Leaf flutter: each leaf (8 vertices, both faces) flaps about its petiole with its own phase and
  // rate; the tip moves most, both faces alike so the leaf stays closed.
  if (uFlutter > 0.0) {
    float leaf = float(gl_VertexID / 8);
    float phase = 6.2831853 * hash1(leaf + float(joint) * 0.618);
    float rate = 7.0 + 5.0 * hash1(leaf * 1.7 + 3.1);
    world.y += uFlutter * uLeafLength * uv.y * sin(rate * uTime + phase);
  }
  return world;
}
