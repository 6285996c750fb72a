#version 300 es
// Card atlas (thesis 4.2.1): group representatives and leaf clusters already projected by
// core/render/atlas_mesh into atlas clip space; shaded by tree_textured.frag (the page: each part's
// own texture through its uvs) or tree.frag (plain colours) with world normals and the sun.
layout(location = 0) in vec3 aPosition;  // atlas clip x, y and depth
layout(location = 1) in vec3 aNormal;    // world
layout(location = 2) in vec2 aUv;        // the part's texture coordinates (bark, leaf, flower)

out vec3 vNormal;
out vec3 vWorld;
out float vSelected;
out vec2 vUv;
out float vOcclusion;  // tree_textured.frag's: none here (no occlusion, no shadow map in the atlas)
out vec4 vShadow;

void main() {
  vNormal = aNormal;
  vUv = aUv;
  vWorld = vec3(aPosition.xy * 8.0, 0.0);  // only seeds tree.frag's colour variation
  vSelected = 0.0;
  vOcclusion = 0.0;
  vShadow = vec4(0.0);
  gl_Position = vec4(aPosition, 1.0);
}
