// The moss study's glTF output: the land's map and fig 3.7's tufts (moss_gltf.h).
#include "moss/moss_gltf.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <utility>

#include "math/det_math.h"

namespace niwa::moss {
namespace {

constexpr const char* kMapNames[kMossMapCount] = {"coverage", "S",     "T_s",
                                                  "rh_s",     "theta", "fitness"};

// Viridis at 0, 1/4, 1/2, 3/4, 1, sRGB turned linear (COLOR_0 is linear).
constexpr float kViridis[5][3] = {{0.05795f, 0.00039f, 0.08843f},
                                  {0.04287f, 0.08461f, 0.25912f},
                                  {0.01493f, 0.28138f, 0.26432f},
                                  {0.11217f, 0.58535f, 0.12126f},
                                  {0.98415f, 0.79934f, 0.01826f}};

// A rotation as a unit quaternion (x, y, z, w).
struct TuftTurn {
  double x, y, z, w;
};
TuftTurn TurnProduct(const TuftTurn& a, const TuftTurn& b) {
  return {a.w * b.x + b.w * a.x + (a.y * b.z - a.z * b.y),
          a.w * b.y + b.w * a.y + (a.z * b.x - a.x * b.z),
          a.w * b.z + b.w * a.z + (a.x * b.y - a.y * b.x),
          a.w * b.w - (a.x * b.x + a.y * b.y + a.z * b.z)};
}
// +y turned onto the unit normal n, after a turn of `angle` about +y.
TuftTurn TuftTurnOf(const glm::dvec3& n, double angle) {
  TuftTurn align{1, 0, 0, 0};  // n straight down: half a turn about x
  if (n.y > -0.999999) {
    const double len = std::sqrt(n.z * n.z + n.x * n.x + (1 + n.y) * (1 + n.y));
    align = {n.z / len, 0, -n.x / len, (1 + n.y) / len};
  }
  double s, c;
  det::SinCos(0.5 * angle, &s, &c);
  return TurnProduct(align, {0, s, 0, c});
}
glm::dvec3 Turned(const TuftTurn& q, const glm::dvec3& v) {
  const glm::dvec3 u(q.x, q.y, q.z);
  const glm::dvec3 t =
      2.0 * glm::dvec3(u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x);
  return v + q.w * t +
         glm::dvec3(u.y * t.z - u.z * t.y, u.z * t.x - u.x * t.z, u.x * t.y - u.y * t.x);
}

glm::dvec3 TuftCross(const glm::dvec3& a, const glm::dvec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

std::string SpeciesMaterialName(Species s) { return std::string("tuft_") + SpeciesName(s); }

}  // namespace

const char* MossMapName(MossMap map) { return kMapNames[static_cast<int>(map)]; }

Status MossMapFromName(std::string_view name, MossMap* map) {
  for (int k = 0; k < kMossMapCount; ++k)
    if (name == kMapNames[k]) {
      *map = static_cast<MossMap>(k);
      return Status::Ok();
    }
  return Status::Error("map", "'" + std::string(name.substr(0, 64)) +
                                  "' is unknown; must be coverage, S, T_s, rh_s, theta or fitness");
}

MapRamp MossMapRamp(MossMap map) {
  switch (map) {
    case MossMap::kS:
      return {0, 120, "value"};
    case MossMap::kT_s:
      return {263.15, 303.15, "value"};
    case MossMap::kTheta:
      return {0, 1, "theta/theta_SAT"};
    default:
      return {0, 1, "value"};
  }
}

std::array<float, 3> RampColour(double t) {
  if (!(t > 0)) t = 0;  // NaN too: the ramp's start
  if (t > 1) t = 1;
  const double x = 4.0 * t;
  const int k = std::min(3, static_cast<int>(x));
  const float f = static_cast<float>(x - k);
  std::array<float, 3> c{};
  for (int i = 0; i < 3; ++i) c[i] = kViridis[k][i] + f * (kViridis[k + 1][i] - kViridis[k][i]);
  return c;
}

std::array<float, 3> SpeciesColour(Species species) {
  switch (species) {
    case Species::kGingoke:
      return {0.34239f, 0.44799f, 0.23302f};  // sRGB #9EB385
    case Species::kHaigoke:
      return {0.31855f, 0.44799f, 0.03968f};  // sRGB #99B338
    default:
      return {0.03310f, 0.14732f, 0.01533f};  // sRGB #336B21
  }
}

geom::TriMesh TuftMesh() {
  // Stem: a three-sided prism of radius 0.05 to y 0.6 (vertices 0-2 at the base, 3-5 on top); the
  // crown's tip (6) at y 1; six leaves in two whorls (y 0.3 and 0.45), 4 vertices each.
  constexpr double kR = 0.05, kTop = 0.6, kS3 = 0.8660254037844386;
  const glm::dvec3 ring[3] = {{kR, 0, 0}, {-0.5 * kR, 0, kS3 * kR}, {-0.5 * kR, 0, -kS3 * kR}};
  std::vector<glm::dvec3> p;
  std::vector<uint32_t> idx;
  for (const glm::dvec3& r : ring) p.push_back(r);
  for (const glm::dvec3& r : ring) p.push_back(r + glm::dvec3(0, kTop, 0));
  p.push_back({0, 1, 0});
  for (uint32_t k = 0; k < 3; ++k) {
    const uint32_t k1 = (k + 1) % 3;
    for (uint32_t v : {k, 3 + k1, k1, k, 3 + k, 3 + k1}) idx.push_back(v);  // outward
  }
  for (uint32_t k = 0; k < 3; ++k)
    for (uint32_t v : {3 + k, 6u, 3 + (k + 1) % 3}) idx.push_back(v);
  // Leaf directions every 60° from 30°: (cos, sin).
  const double dirs[6][2] = {{kS3, 0.5}, {0, 1}, {-kS3, 0.5}, {-kS3, -0.5}, {0, -1}, {kS3, -0.5}};
  for (int j = 0; j < 6; ++j) {
    const glm::dvec3 d(dirs[j][0], 0, dirs[j][1]), e(-dirs[j][1], 0, dirs[j][0]);
    const glm::dvec3 base = glm::dvec3(0, j % 2 == 0 ? 0.3 : 0.45, 0) + 0.04 * d;
    const glm::dvec3 mid = base + 0.18 * d + glm::dvec3(0, 0.10, 0);
    const glm::dvec3 tip = base + 0.42 * d + glm::dvec3(0, 0.28, 0);
    const uint32_t b = static_cast<uint32_t>(p.size());
    p.push_back(base);
    p.push_back(mid - 0.07 * e);
    p.push_back(tip);
    p.push_back(mid + 0.07 * e);
    for (uint32_t side : {b + 1, b + 3}) {  // each half faces up (+y side)
      const bool up = TuftCross(p[side] - base, tip - base).y > 0;
      for (uint32_t v : {b, up ? side : b + 2, up ? b + 2 : side}) idx.push_back(v);
    }
  }
  std::vector<glm::dvec3> n(p.size(), glm::dvec3(0));
  for (std::size_t t = 0; t < idx.size(); t += 3) {
    const glm::dvec3 f = TuftCross(p[idx[t + 1]] - p[idx[t]], p[idx[t + 2]] - p[idx[t]]);
    for (int k = 0; k < 3; ++k) n[idx[t + k]] += f;
  }
  geom::TriMesh mesh;
  for (std::size_t v = 0; v < p.size(); ++v) {
    mesh.positions.push_back(glm::vec3(p[v]));
    const double len = std::sqrt(n[v].x * n[v].x + n[v].y * n[v].y + n[v].z * n[v].z);
    mesh.normals.push_back(glm::vec3(n[v] / len));
  }
  mesh.indices = std::move(idx);
  return mesh;
}

geom::TriMesh LandMapMesh(const SoilCells& cells, MossMap map, const std::vector<double>& value,
                          const std::vector<double>& ramp) {
  geom::TriMesh mesh;
  mesh.positions = cells.mesh.positions;
  mesh.indices = cells.mesh.indices;
  mesh.normals.resize(mesh.positions.size());
  mesh.AddAttribute("COLOR_0", 3);
  mesh.AddAttribute(MossMapName(map), 1);  // may move the first: both found after adding
  geom::VertexAttribute& colour = mesh.attributes[0];
  geom::VertexAttribute& raw = mesh.attributes[1];
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const std::array<float, 3> c = RampColour(ramp[i]);
    for (std::size_t v = 3 * i; v < 3 * i + 3; ++v) {
      mesh.normals[v] = glm::vec3(cells.normal[i]);
      for (int k = 0; k < 3; ++k) colour.values[3 * v + k] = c[k];
      raw.values[v] = static_cast<float>(value[i]);
    }
  }
  return mesh;
}

geom::TriMesh MergedTufts(const std::vector<TuftPlace>& tufts) {
  const geom::TriMesh tuft = TuftMesh();
  geom::TriMesh mesh;
  const std::size_t nv = tuft.vertex_count();
  mesh.positions.reserve(nv * tufts.size());
  mesh.normals.reserve(nv * tufts.size());
  mesh.indices.reserve(tuft.indices.size() * tufts.size());
  std::vector<float> colours;
  colours.reserve(3 * nv * tufts.size());
  for (const TuftPlace& t : tufts) {
    const TuftTurn q = TuftTurnOf(t.normal, t.angle);
    const uint32_t first = static_cast<uint32_t>(mesh.positions.size());
    const std::array<float, 3> c = SpeciesColour(t.species);
    for (std::size_t v = 0; v < nv; ++v) {
      mesh.positions.push_back(
          glm::vec3(t.pos + t.size * Turned(q, glm::dvec3(tuft.positions[v]))));
      mesh.normals.push_back(glm::vec3(Turned(q, glm::dvec3(tuft.normals[v]))));
      colours.insert(colours.end(), c.begin(), c.end());
    }
    for (uint32_t i : tuft.indices) mesh.indices.push_back(first + i);
  }
  mesh.attributes.push_back({"COLOR_0", 3, std::move(colours)});
  return mesh;
}

gltf::Document MossDocument(geom::TriMesh land, MossMap map, int day,
                            const std::vector<TuftPlace>& tufts, bool instancing) {
  gltf::Document doc;
  doc.generator = "niwa moss grow";
  gltf::Material land_material;
  land_material.name = "land";
  land_material.metallic_factor = 0;
  doc.materials.push_back(land_material);
  gltf::Mesh land_mesh;
  land_mesh.name = "land";
  gltf::Primitive land_primitive;
  land_primitive.mesh = std::move(land);
  land_primitive.material = 0;
  land_mesh.primitives.push_back(std::move(land_primitive));
  doc.meshes.push_back(std::move(land_mesh));
  gltf::Node land_node;
  land_node.name = "land";
  land_node.mesh = 0;
  const MapRamp ramp = MossMapRamp(map);
  nlohmann::ordered_json land_extras;
  land_extras["map"] = MossMapName(map);
  land_extras["attribute"] = gltf::AttributeSemantic(MossMapName(map));
  land_extras["ramp"] = {ramp.lo, ramp.hi};
  land_extras["ramp_of"] = ramp.of;
  land_extras["day"] = day;
  land_node.extras_json = land_extras.dump();
  doc.nodes.push_back(land_node);
  doc.scene_nodes = {0};
  if (tufts.empty()) return doc;

  gltf::Node tuft_node;
  tuft_node.name = "tufts";
  if (!instancing) {
    gltf::Material m;
    m.name = "tufts";
    m.metallic_factor = 0;
    m.double_sided = true;
    doc.materials.push_back(m);
    gltf::Mesh mesh;
    mesh.name = "tufts";
    gltf::Primitive primitive;
    primitive.mesh = MergedTufts(tufts);
    primitive.material = 1;
    mesh.primitives.push_back(std::move(primitive));
    doc.meshes.push_back(std::move(mesh));
    tuft_node.mesh = 1;
    nlohmann::ordered_json extras;
    extras["species_names"] = {SpeciesName(Species::kGingoke), SpeciesName(Species::kHaigoke),
                               SpeciesName(Species::kSugigoke)};
    nlohmann::ordered_json species = nlohmann::ordered_json::array(),
                           birth = nlohmann::ordered_json::array();
    for (const TuftPlace& t : tufts) {
      species.push_back(static_cast<int>(t.species));
      birth.push_back(t.birth_day);
    }
    extras["species"] = species;
    extras["birth_day"] = birth;
    extras["triangles_per_tuft"] = kTuftTriangles;
    tuft_node.extras_json = extras.dump();
    doc.nodes.push_back(tuft_node);
    doc.scene_nodes.push_back(1);
    return doc;
  }
  doc.nodes.push_back(tuft_node);
  doc.scene_nodes.push_back(1);
  const geom::TriMesh tuft = TuftMesh();
  for (int s = 0; s < kSpeciesCount; ++s) {
    const Species species = static_cast<Species>(s);
    gltf::Node node;
    nlohmann::ordered_json birth = nlohmann::ordered_json::array();
    for (const TuftPlace& t : tufts) {
      if (t.species != species) continue;
      const TuftTurn q = TuftTurnOf(t.normal, t.angle);
      for (double v : {t.pos.x, t.pos.y, t.pos.z})
        node.instance_translations.push_back(static_cast<float>(v));
      for (double v : {q.x, q.y, q.z, q.w})
        node.instance_rotations.push_back(static_cast<float>(v));
      for (int k = 0; k < 3; ++k) node.instance_scales.push_back(static_cast<float>(t.size));
      birth.push_back(t.birth_day);
    }
    if (birth.empty()) continue;
    gltf::Material m;
    m.name = SpeciesMaterialName(species);
    const std::array<float, 3> c = SpeciesColour(species);
    m.base_color_factor = {c[0], c[1], c[2], 1.0};
    m.metallic_factor = 0;
    m.double_sided = true;
    doc.materials.push_back(m);
    gltf::Mesh mesh;
    mesh.name = SpeciesMaterialName(species);
    gltf::Primitive primitive;
    primitive.mesh = tuft;
    primitive.material = static_cast<int>(doc.materials.size()) - 1;
    mesh.primitives.push_back(std::move(primitive));
    doc.meshes.push_back(std::move(mesh));
    node.name = std::string("tufts_") + SpeciesName(species);
    node.mesh = static_cast<int>(doc.meshes.size()) - 1;
    nlohmann::ordered_json extras;
    extras["species"] = SpeciesName(species);
    extras["birth_day"] = birth;
    node.extras_json = extras.dump();
    doc.nodes[1].children.push_back(static_cast<int>(doc.nodes.size()));
    doc.nodes.push_back(std::move(node));
  }
  return doc;
}

Estimate MossGlbEstimate(std::size_t cells, std::size_t mosses) {
  // Land: 3 vertices a cell (position, normal, colour 12 bytes each, the raw value 4) and 12 bytes
  // of indices; a merged tuft: kTuftVertices vertices of 36 bytes and its indices, its extras.
  const double bytes =
      132.0 * static_cast<double>(cells) +
      (36.0 * kTuftVertices + 12.0 * kTuftTriangles + 24.0) * static_cast<double>(mosses);
  Estimate e;
  e.memory_bytes = 3.0 * bytes;  // the document's meshes, the writer's buffer, the file's bytes
  e.seconds = 3e-8 * bytes;
  e.what = "writing the .glb (" + FormatCount(static_cast<double>(cells)) + " cells, " +
           FormatCount(static_cast<double>(mosses)) + " tufts)";
  return e;
}

}  // namespace niwa::moss
