// The bark study's glTF output: a trunk segment wearing the maps (bark_gltf.h).
#include "bark/bark_gltf.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "math/det_math.h"

namespace niwa::bark {
namespace {

constexpr double kPi = 3.14159265358979323846;

gltf::Texture PngTexture(const std::string& name, const std::string& png) {
  gltf::Texture t;
  t.name = name;
  t.png.assign(png.begin(), png.end());
  t.wrap_s = t.wrap_t = gltf::Wrap::kRepeat;
  return t;
}

}  // namespace

int TileWraps(double radius_m, double tile_width_m) {
  if (!(tile_width_m > 0) || !(radius_m > 0)) return 1;
  return std::max(1, static_cast<int>(std::lround(2 * kPi * radius_m / tile_width_m)));
}

geom::TriMesh TrunkSegmentMesh(double radius_m, double height_m, double tile_width_m) {
  geom::TriMesh m;
  const int wraps = TileWraps(radius_m, tile_width_m);
  const int ring = kTrunkSides + 1;
  std::vector<float> tangents;
  tangents.reserve(static_cast<std::size_t>(8 * ring));
  for (int r = 0; r < 2; ++r) {  // base, then top
    const float y = r == 0 ? 0.0f : static_cast<float>(height_m);
    const float v = r == 0 ? 1.0f : 0.0f;
    for (int k = 0; k <= kTrunkSides; ++k) {
      // The seam's last column sits exactly on the first (angle 0), with u a whole number.
      const int kk = k == kTrunkSides ? 0 : k;
      double s = 0, c = 1;
      det::SinCos(2 * kPi * kk / kTrunkSides, &s, &c);
      m.positions.emplace_back(static_cast<float>(radius_m * s), y,
                               static_cast<float>(radius_m * c));
      m.normals.emplace_back(static_cast<float>(s), 0.0f, static_cast<float>(c));
      m.uvs.emplace_back(static_cast<float>(static_cast<double>(wraps) * k / kTrunkSides), v);
      tangents.insert(tangents.end(), {static_cast<float>(c), 0.0f, static_cast<float>(-s), 1.0f});
    }
  }
  for (int k = 0; k < kTrunkSides; ++k) {
    const uint32_t a = static_cast<uint32_t>(k), b = a + 1;
    const uint32_t c = a + static_cast<uint32_t>(ring), d = c + 1;
    // Counter-clockwise from outside: base k, base k+1, top k+1; base k, top k+1, top k.
    m.indices.insert(m.indices.end(), {a, b, d, a, d, c});
  }
  geom::VertexAttribute& t = m.AddAttribute("TANGENT", 4);
  t.values = std::move(tangents);
  return m;
}

gltf::Document TrunkDocument(geom::TriMesh mesh, const TrunkMaps& maps,
                             const std::string& extras_json) {
  gltf::Document doc;
  doc.scene_name = "bark";
  doc.asset_extras_json = extras_json;
  doc.textures.push_back(PngTexture("bark", maps.base_colour));
  doc.textures.push_back(PngTexture("bark_normal", maps.normal));
  doc.textures.push_back(PngTexture("bark_orm", maps.orm));
  gltf::Material material;
  material.name = "bark";
  material.base_color_texture = 0;
  material.normal_texture = 1;
  material.occlusion_texture = 2;           // R: occlusion
  material.metallic_roughness_texture = 2;  // G: roughness, B: metallic (0)
  material.metallic_factor = 1.0;
  material.roughness_factor = 1.0;
  doc.materials.push_back(std::move(material));
  gltf::Primitive primitive;
  primitive.mesh = std::move(mesh);
  primitive.material = 0;
  gltf::Mesh trunk;
  trunk.name = "trunk";
  trunk.primitives.push_back(std::move(primitive));
  doc.meshes.push_back(std::move(trunk));
  gltf::Node node;
  node.name = "trunk";
  node.mesh = 0;
  doc.nodes.push_back(std::move(node));
  doc.scene_nodes = {0};
  return doc;
}

Estimate TrunkGlbEstimate() {
  // Two rings of kTrunkSides + 1 vertices (position, normal, uv, tangent: 48 bytes), the indices,
  // the JSON chunk and the writer's copies, with room.
  const double vertices = 2.0 * (kTrunkSides + 1);
  return Estimate{vertices * 48 * 4 + kTrunkSides * 6 * 4 * 4 + 64 * 1024, 0.001,
                  "the trunk segment .glb"};
}

}  // namespace niwa::bark
