// The built-in ivy scenes (spec §3 and §6; the cube layout is not printed in the paper, §4 item
// 14).
#include "ivy/scenes.h"

#include <glm/geometric.hpp>

#include "geom/primitives.h"

namespace niwa::ivy {
namespace {

// Appends a mesh's triangles to `to` (vertices not shared between parts).
void Append(geom::TriMesh* to, const geom::TriMesh& part) {
  const uint32_t base = static_cast<uint32_t>(to->positions.size());
  to->positions.insert(to->positions.end(), part.positions.begin(), part.positions.end());
  for (std::size_t i = 0; i < part.positions.size(); ++i) {
    to->normals.push_back(i < part.normals.size() ? part.normals[i] : glm::vec3(0, 1, 0));
  }
  for (uint32_t idx : part.indices) to->indices.push_back(base + idx);
}

// An axis-aligned rectangle: `axis` 0/1/2 is its normal axis at coordinate c, spanning [a0, a1] x
// [b0, b1] in the two other axes (in x, y, z order); `sign` is the outward direction.
void AddQuad(geom::TriMesh* m, int axis, float c, float a0, float a1, float b0, float b1,
             int sign) {
  const int ua = axis == 0 ? 1 : 0, ub = axis == 2 ? 1 : 2;
  auto vert = [&](float a, float b) {
    glm::vec3 p(0.0f);
    p[axis] = c;
    p[ua] = a;
    p[ub] = b;
    return p;
  };
  glm::vec3 n(0.0f);
  n[axis] = static_cast<float>(sign);
  const uint32_t base = static_cast<uint32_t>(m->positions.size());
  glm::vec3 v[4] = {vert(a0, b0), vert(a1, b0), vert(a1, b1), vert(a0, b1)};
  for (const glm::vec3& p : v) {
    m->positions.push_back(p);
    m->normals.push_back(n);
  }
  // Wind counter-clockwise seen from the outward side.
  const glm::vec3 geo = glm::cross(v[1] - v[0], v[2] - v[0]);
  const bool ccw = glm::dot(geo, n) > 0;
  const uint32_t tri[6] = {0, 1, 2, 0, 2, 3};
  const uint32_t rev[6] = {0, 2, 1, 0, 3, 2};
  for (uint32_t k : ccw ? tri : rev) m->indices.push_back(base + k);
}

// Box faces [lo, hi] (all six).
void AddBox(geom::TriMesh* m, glm::vec3 lo, glm::vec3 hi) {
  Append(m, geom::MakeBox(hi - lo, (lo + hi) * 0.5f));
}

IvyScene Cubes4() {
  // L-tetracube, union surface only: a column of 3 cubes x [0, 400], y [0, 1200] and a side cube
  // x [400, 800], y [0, 400]; z [0, 400].
  IvyScene s{"cubes4",
             "the paper's 4 cubes of 400 px (L-tetracube, union surface, 20 tris)",
             false,
             {},
             {{"side", {600, 10, 410}}, {"column", {300, 10, 410}}}};
  geom::TriMesh& m = s.mesh;
  AddQuad(&m, 0, 0, 0, 1200, 0, 400, -1);      // column left x = 0
  AddQuad(&m, 0, 400, 400, 1200, 0, 400, +1);  // column right above the side cube
  AddQuad(&m, 0, 800, 0, 400, 0, 400, +1);     // side cube right
  AddQuad(&m, 2, 0, 0, 400, 0, 1200, -1);      // column back
  AddQuad(&m, 2, 400, 0, 400, 0, 1200, +1);    // column front
  AddQuad(&m, 2, 0, 400, 800, 0, 400, -1);     // side back
  AddQuad(&m, 2, 400, 400, 800, 0, 400, +1);   // side front
  AddQuad(&m, 1, 1200, 0, 400, 0, 400, +1);    // column top
  AddQuad(&m, 1, 400, 400, 800, 0, 400, +1);   // side top
  AddQuad(&m, 1, 0, 0, 800, 0, 400, -1);       // bottom
  return s;
}

IvyScene Wall() {
  IvyScene s{"wall",
             "a 1600 x 1200 px wall on a 1600 x 800 px ground (4 tris, free top edge)",
             false,
             {},
             {{"base", {0, 10, 10}}, {"left", {-400, 10, 10}}, {"right", {400, 10, 10}}}};
  AddQuad(&s.mesh, 2, 0, -800, 800, 0, 1200, +1);
  AddQuad(&s.mesh, 1, 0, -800, 800, 0, 800, +1);
  return s;
}

IvyScene Overhang() {
  IvyScene s = Wall();
  s.name = "overhang";
  s.description = "the wall with a 400 px box cantilevered at 600 px (underside, concave corners)";
  s.seeds = {{"base", {0, 10, 10}}, {"beside", {300, 10, 10}}};
  AddBox(&s.mesh, {-200, 600, 0}, {200, 1000, 400});
  return s;
}

IvyScene Stairs() {
  IvyScene s{"stairs",
             "5 steps of 200 px rising toward -z, on a ground",
             false,
             {},
             {{"foot", {0, 10, 10}}}};
  AddQuad(&s.mesh, 1, 0, -600, 600, 0, 800, +1);
  for (int i = 0; i < 5; ++i) {
    const float z1 = -200.0f * static_cast<float>(i), z0 = z1 - 200.0f;
    AddBox(&s.mesh, {-600, 0, z0}, {600, 200.0f * static_cast<float>(i + 1), z1});
  }
  return s;
}

IvyScene Pillar() {
  IvyScene s{"pillar",
             "a cylinder of radius 200 px, 1600 px high, 48 sides, on a ground",
             false,
             {},
             {{"foot", {0, 10, 210}}}};
  AddQuad(&s.mesh, 1, 0, -800, 800, -800, 800, +1);
  Append(&s.mesh, geom::MakeCylinder(200, 1600, 48, true));
  return s;
}

IvyScene Sphere() {
  IvyScene s{"sphere",
             "an icosphere of radius 400 px (1280 tris) centred 400 px up",
             false,
             {},
             {{"equator", {0, 400, 410}}}};
  geom::TriMesh ball = geom::MakeIcosphere(400, 3);
  for (glm::vec3& p : ball.positions) p.y += 400.0f;
  Append(&s.mesh, ball);
  return s;
}

IvyScene Free() {
  return {"free",
          "no support: every search accepts p + L v0 (the RNG-free nutrient replay)",
          true,
          {},
          {{"origin", {0, 0, 0}}}};
}

}  // namespace

geom::TriMesh IvyAttachTriangles(const geom::TriMesh& mesh,
                                 const std::vector<io::MeshMaterial>& materials,
                                 std::size_t* obstacles) {
  *obstacles = 0;
  const geom::VertexAttribute* mat = mesh.FindAttribute(io::kMaterialAttribute);
  geom::TriMesh out;
  out.positions = mesh.positions;
  out.normals = mesh.normals;
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    bool attach = true;
    if (mat != nullptr) {
      const float index = mat->values[mesh.indices[3 * t]];
      if (index >= 0 && static_cast<std::size_t>(index) < materials.size()) {
        const io::MeshMaterial& m = materials[static_cast<std::size_t>(index)];
        attach = m.ivy_support && m.name.rfind("noivy", 0) != 0;
      }
    }
    if (!attach) {
      ++*obstacles;
      continue;
    }
    out.indices.insert(out.indices.end(), mesh.indices.begin() + static_cast<std::ptrdiff_t>(3 * t),
                       mesh.indices.begin() + static_cast<std::ptrdiff_t>(3 * t + 3));
  }
  return out;
}

namespace {

Result<IvyScene> BuiltInScene(std::string_view name) {
  if (name == "cubes4") return Cubes4();
  if (name == "wall") return Wall();
  if (name == "overhang") return Overhang();
  if (name == "stairs") return Stairs();
  if (name == "pillar") return Pillar();
  if (name == "sphere") return Sphere();
  if (name == "free") return Free();
  return Status::Error("scene", "'" + std::string(name) +
                                    "' is unknown; must be one of cubes4, wall, overhang, "
                                    "stairs, pillar, sphere, free");
}

}  // namespace

const std::vector<std::string>& IvySceneNames() {
  static const std::vector<std::string> names = {"cubes4", "wall",   "overhang", "stairs",
                                                 "pillar", "sphere", "free"};
  return names;
}

Result<IvyScene> MakeIvyScene(std::string_view name) {
  Result<IvyScene> scene = BuiltInScene(name);
  if (scene.ok()) scene->px_per_unit = 1;  // every built-in scene is in px
  return scene;
}

}  // namespace niwa::ivy
