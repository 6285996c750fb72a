// Ivy tubes, leaves and suckers as TriMeshes (spec §1.5), and the .glb.
#include "ivy/ivy_mesh.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "geom/linear_queries.h"
#include "geom/ray_cast.h"
#include "io/gltf_writer.h"
#include "ivy/ivy_leaf_texture.h"
#include "math/det_math.h"

namespace niwa::ivy {
namespace {

constexpr int kSides = 6;

glm::dvec3 UnitOrUp(const glm::dvec3& v) {
  double l = std::sqrt(glm::dot(v, v));
  return l > 0 ? v / l : glm::dvec3(0, 1, 0);
}

// Any unit vector perpendicular to v.
glm::dvec3 Perpendicular(const glm::dvec3& v) {
  glm::dvec3 a = std::fabs(v.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  return UnitOrUp(glm::cross(v, a));
}

struct Builder {
  geom::TriMesh mesh;
  std::vector<float> birth;
  bool textured = false;  // every vertex gets the texture coordinate `uv` (leaves)
  glm::vec2 uv{0, 0};
  void Reserve(std::size_t parts, std::size_t vertices, std::size_t indices) {
    mesh.positions.reserve(parts * vertices);
    mesh.normals.reserve(parts * vertices);
    if (textured) mesh.uvs.reserve(parts * vertices);
    birth.reserve(parts * vertices);
    mesh.indices.reserve(parts * indices);
  }
  uint32_t Vertex(const glm::dvec3& p, const glm::dvec3& n, double step) {
    mesh.positions.push_back(glm::vec3(p));
    mesh.normals.push_back(glm::vec3(n));
    if (textured) mesh.uvs.push_back(uv);
    birth.push_back(static_cast<float>(step));
    return static_cast<uint32_t>(mesh.positions.size() - 1);
  }
  void Tri(uint32_t a, uint32_t b, uint32_t c) {
    mesh.indices.insert(mesh.indices.end(), {a, b, c});
  }
  // An open tube from a (radius ra) to b (radius rb).
  void Tube(const glm::dvec3& a, const glm::dvec3& b, double ra, double rb, double step) {
    const glm::dvec3 h = UnitOrUp(b - a), e1 = Perpendicular(h), e2 = glm::cross(h, e1);
    uint32_t first = static_cast<uint32_t>(mesh.positions.size());
    for (int k = 0; k < kSides; ++k) {
      double s, c;
      det::SinCos(2.0 * det::kPi * k / kSides, &s, &c);
      const glm::dvec3 n = c * e1 + s * e2;
      Vertex(a + ra * n, n, step);
      Vertex(b + rb * n, n, step);
    }
    for (uint32_t k = 0; k < kSides; ++k) {
      const uint32_t k2 = (k + 1) % kSides;
      const uint32_t a0 = first + 2 * k, b0 = a0 + 1, a1 = first + 2 * k2, b1 = a1 + 1;
      Tri(a0, a1, b1);
      Tri(a0, b1, b0);
    }
  }
  // A flat polygon fan around `centre` in the plane (u, v), outline radii per angle; with
  // `uvs` (one per outline point, textured builders) the centre takes `centre_uv`.
  void Fan(const glm::dvec3& centre, const glm::dvec3& u, const glm::dvec3& v,
           const std::vector<glm::dvec2>& outline, double step,
           const std::vector<glm::vec2>* uvs = nullptr, glm::vec2 centre_uv = {0, 0}) {
    const glm::dvec3 n = UnitOrUp(glm::cross(u, v));
    if (uvs) uv = centre_uv;
    uint32_t c = Vertex(centre, n, step);
    uint32_t first = static_cast<uint32_t>(mesh.positions.size());
    for (std::size_t k = 0; k < outline.size(); ++k) {
      if (uvs) uv = (*uvs)[k];
      Vertex(centre + outline[k].x * u + outline[k].y * v, n, step);
    }
    const uint32_t count = static_cast<uint32_t>(outline.size());
    for (uint32_t k = 0; k < count; ++k) Tri(c, first + k, first + (k + 1) % count);
  }
  geom::TriMesh Done() {
    mesh.AddAttribute("birth_step", 1).values = birth;
    return std::move(mesh);
  }
};

// The leaf outline (ivy_leaf_texture.h) at `width`.
std::vector<glm::dvec2> LeafOutline(double width) {
  std::vector<glm::dvec2> out;
  for (const auto& [x, y] : LeafOutlineUnit()) out.push_back({x * width, y * width});
  return out;
}

// The outline's texture coordinates (the same for every leaf).
std::vector<glm::vec2> LeafOutlineUvs() {
  std::vector<glm::vec2> uvs;
  for (const auto& [x, y] : LeafOutlineUnit()) {
    glm::vec2 uv;
    LeafUv(x, y, &uv.x, &uv.y);
    uvs.push_back(uv);
  }
  return uvs;
}

// Does the segment a→b touch the support (every triangle: obstacles too)?
bool Crosses(const Support& s, const glm::dvec3& a, const glm::dvec3& b) {
  if (s.accel == Accel::kLinear)
    return geom::SegmentHitsLinear(*s.mesh, glm::vec3(a), glm::vec3(b));
  return geom::SegmentHits(*s.mesh, *s.bvh, glm::vec3(a), glm::vec3(b));
}

// A uniform number in [0, 1) from a bud's id (SplitMix64; the leaves' thinning, no RNG stream);
// `k` > 0 gives the bud's k-th further number (its extra leaves', the row leaf_spacing).
double BudHash01(int id, int k = 0) {
  uint64_t x = (static_cast<uint64_t>(static_cast<uint32_t>(id)) |
                (static_cast<uint64_t>(static_cast<uint32_t>(k)) << 32)) *
                   0x2545f4914f6cdd1dULL +
               0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  x ^= x >> 31;
  return static_cast<double>(x >> 11) * (1.0 / 9007199254740992.0);
}

// The blade's turns about the face normal tried in order (issue 31 item 7), in degrees.
constexpr double kLeafTurns[] = {0, 45, -45, 90, -90, 135, -135, 180};

}  // namespace

double LeafLight(const glm::dvec3& face_normal, const glm::dvec3& up, bool shaded) {
  const double facing = (1.0 + glm::dot(face_normal, up)) / 2.0;
  return (0.6 + 0.4 * facing) * (shaded ? 0.35 : 1.0);
}

IvyMeshes BuildIvyMeshes(const IvyModel& m, const IvyParams& p, const Support* support,
                         LeafPlacement* placement) {
  const double r_tip = p.Get(IvyParam::kRTip), pipe = p.Get(IvyParam::kPipeExp);
  const double leaf = p.Get(IvyParam::kLeafSize), petiole = p.Get(IvyParam::kPetiole);
  const double tau = p.Get(IvyParam::kLeafAge), tilt = p.Get(IvyParam::kLeafTilt);
  const double L = p.Get(IvyParam::kL);
  const double light_w = p.Get(IvyParam::kLeafLight);
  const double density = IvyLeafDensity(p);  // leaves a bud (leaf_spacing)
  const int copies = IvyLeavesPerBud(p);
  const glm::dvec3 up =
      UnitOrUp(glm::dvec3(p.Get(IvyParam::kUpX), p.Get(IvyParam::kUpY), p.Get(IvyParam::kUpZ)));
  // Tips below each bud (pipe model r = r_tip · n_tips^(1/pipe_exp)), children before parents.
  std::vector<int> tips(m.buds.size(), 0);
  for (std::size_t i = m.buds.size(); i-- > 0;) {
    const Bud& b = m.buds[i];
    if (b.child[0] < 0 && b.child[1] < 0) tips[i] = 1;
    if (b.parent >= 0) tips[static_cast<std::size_t>(b.parent)] += tips[i];
  }
  auto radius = [&](int id) {
    const Bud& b = m.buds[static_cast<std::size_t>(id)];
    double r =
        r_tip * det::Exp(det::Log(static_cast<double>(tips[static_cast<std::size_t>(id)])) / pipe);
    // No tube crosses the support at a node.
    return std::min(r, std::max(r_tip, 0.9 * b.clearance));
  };
  int last_step = 0;
  for (const Bud& b : m.buds) last_step = std::max(last_step, b.born_step);
  Builder stems, leaves, suckers;
  leaves.textured = true;
  // Room for every vertex and index (a tube: 12 vertices, 36 indices; a leaf: its petiole tube
  // and an 11-vertex fan; a sucker: its tube and a 9-vertex disc).
  const std::size_t outline = LeafOutlineUnit().size();
  stems.Reserve(m.internodes.size(), 2 * kSides, 6 * kSides);
  leaves.Reserve(m.buds.size() * static_cast<std::size_t>(copies), 2 * kSides + 1 + outline,
                 6 * kSides + 3 * outline);
  suckers.Reserve(m.buds.size(), 2 * kSides + 9, 6 * kSides + 3 * 8);
  // The petiole on the midrib's texels; the fan's centre (the blade's base) at the petiole end.
  glm::vec2 petiole_uv, base_uv;
  LeafUv(0.0, 0.1, &petiole_uv.x, &petiole_uv.y);
  LeafUv(0.0, 0.0, &base_uv.x, &base_uv.y);
  const std::vector<glm::vec2> outline_uvs = LeafOutlineUvs();
  for (const Internode& in : m.internodes) {
    const Bud& a = m.buds[static_cast<std::size_t>(in.from_bud)];
    const Bud& b = m.buds[static_cast<std::size_t>(in.to_bud)];
    stems.Tube(a.pos, b.pos, radius(a.id), radius(b.id), in.step);
  }
  for (const Bud& b : m.buds) {
    // Sucker: pos -> anchor, a disc of radius 0.1 L at the anchor facing the surface; none on a
    // hanging tendril's buds (they hold on to nothing).
    const glm::dvec3 n = b.outward;
    if (b.hang == 0) {
      suckers.Tube(b.pos, b.anchor + 0.01 * L * n, 0.2 * r_tip, 0.2 * r_tip, b.born_step);
      const glm::dvec3 t1 = Perpendicular(n), t2 = glm::cross(n, t1);
      std::vector<glm::dvec2> disc;
      for (int k = 0; k < 8; ++k) {
        double s, c;
        det::SinCos(2.0 * det::kPi * k / 8, &s, &c);
        disc.push_back({0.1 * L * c, 0.1 * L * s});
      }
      suckers.Fan(b.anchor + 0.01 * L * n, t1, t2, disc, b.born_step);
    }
    if (b.parent < 0) continue;
    // The row leaf_spacing (docs/ivy-model.md "Leaves a real length apart"): below one leaf a bud
    // a bud keeps its leaf with probability n (its hash 7, apart from the light's); above,
    // `copies` leaves share the internode from its parent: the bud's own at the bud, the others
    // evenly back along the stem, each with the bud's face and age and its own hash.
    if (density < 1 && BudHash01(b.id, 7) >= density) continue;
    // Leaf opposite the sucker: petiole along n tilted toward up, blade normal ≈ n. With the
    // support: n is the anchor face's normal on the bud's side, and the leaf turns about it, then
    // shrinks, until its petiole, spokes and rim cross no face (LeafPlacement).
    glm::dvec3 leaf_n = n;
    const bool check = support != nullptr && support->mesh != nullptr && b.anchor_tri >= 0;
    if (check && b.hang == 0) {
      const geom::TriMesh& attach = support->attach_mesh ? *support->attach_mesh : *support->mesh;
      const glm::dvec3 face = TriangleNormal(attach, static_cast<uint32_t>(b.anchor_tri));
      leaf_n = glm::dot(face, b.pos - b.anchor) < 0 ? -face : face;
    }
    // Light (leaf_light): thinning, size and the blade's turn toward the sky.
    bool shaded = false;
    if (light_w > 0 && support != nullptr && support->mesh != nullptr) {
      const float reach = static_cast<float>(1e3 * L);
      shaded =
          support->accel == Accel::kLinear
              ? geom::FirstHitLinear(*support->mesh, glm::vec3(b.pos), glm::vec3(up), reach).hit
              : geom::FirstHit(*support->mesh, *support->bvh, glm::vec3(b.pos), glm::vec3(up),
                               reach)
                    .hit;
    }
    const glm::dvec3 stem_from = m.buds[static_cast<std::size_t>(b.parent)].pos;
    for (int copy = 0; copy < copies; ++copy) {
      const glm::dvec3 at =
          copy == 0 ? b.pos : b.pos + (stem_from - b.pos) * (static_cast<double>(copy) / copies);
      double size_factor = 1, blade_turn = 0;
      if (light_w > 0) {
        const double light = LeafLight(leaf_n, up, shaded);
        if (BudHash01(b.id, copy == 0 ? 0 : 7 + copy) >= 1.0 - 0.75 * light_w * (1.0 - light)) {
          if (placement) ++placement->thinned;
          continue;
        }
        size_factor = 1.0 + 0.6 * light_w * (1.0 - light);
        blade_turn = light_w * 0.5 * det::Acos(std::clamp(glm::dot(leaf_n, up), -1.0, 1.0));
      }
      if (placement) ++placement->drawn;
      // The blade's direction from its base: along the petiole's tangent direction (leaf_light 0),
      // else hanging from the petiole's end, leaning out from the face by the turn (never into it).
      double sb = 0, cb = 1;
      if (blade_turn != 0) det::SinCos(blade_turn, &sb, &cb);
      const double hang_b = light_w > 0 ? -1.0 : 1.0;
      double st, ct;
      det::SinCos(tilt * det::kPi / 180.0, &st, &ct);
      glm::dvec3 up_t = up - glm::dot(up, leaf_n) * leaf_n;
      up_t = glm::dot(up_t, up_t) > 1e-12 ? UnitOrUp(up_t) : Perpendicular(leaf_n);
      const double age = static_cast<double>(last_step - b.born_step);
      const double full_width = leaf * size_factor * std::min(1.0, (age + 1.0) / tau);
      glm::dvec3 dir_t = up_t, base = at;
      double width = full_width;
      std::vector<glm::dvec2> blade;
      bool placed = false;
      for (int halving = 0; halving < 3 && !placed; ++halving) {
        for (double turn : kLeafTurns) {
          double sa, ca;
          det::SinCos(turn * det::kPi / 180.0, &sa, &ca);
          dir_t = ca * up_t + sa * glm::cross(leaf_n, up_t);
          width = full_width / static_cast<double>(1 << halving);
          const double pet = petiole / static_cast<double>(1 << halving);
          base = at + pet * UnitOrUp(ct * leaf_n + st * dir_t);
          blade = LeafOutline(width);
          if (!check) {
            placed = true;
            break;
          }
          const glm::dvec3 across = UnitOrUp(glm::cross(dir_t, leaf_n));
          const glm::dvec3 along = hang_b * cb * dir_t + sb * leaf_n;
          bool crosses = Crosses(*support, at, base);
          glm::dvec3 prev = base + blade.back().x * across + blade.back().y * along;
          for (std::size_t k = 0; k < blade.size() && !crosses; ++k) {
            const glm::dvec3 q = base + blade[k].x * across + blade[k].y * along;
            crosses = Crosses(*support, base, q) || Crosses(*support, prev, q);
            prev = q;
          }
          if (!crosses) {
            placed = true;
            if (placement && (turn != 0 || halving > 0)) ++placement->turned;
            if (placement && halving > 0) ++placement->shrunk;
            break;
          }
        }
      }
      if (check && !placed && placement) {
        ++placement->turned;
        ++placement->shrunk;
        ++placement->crossing;
      }
      glm::dvec3 across = UnitOrUp(glm::cross(dir_t, leaf_n));
      // Turned by light: the blade's normal is the side of its plane that looks up (its outline
      // mirrored across the midrib, so the sun lights its face).
      if (light_w > 0 && glm::dot(-cb * leaf_n - sb * dir_t, up) < 0) across = -across;
      leaves.uv = petiole_uv;
      leaves.Tube(at, base, 0.3 * r_tip, 0.3 * r_tip, b.born_step);
      leaves.Fan(base, across, hang_b * cb * dir_t + sb * leaf_n, blade, b.born_step, &outline_uvs,
                 base_uv);
    }
  }
  return {stems.Done(), leaves.Done(), suckers.Done()};
}

Result<gltf::Document> BuildIvyDocument(const IvyModel& model, const IvyParams& params,
                                        uint64_t seed, int steps, const geom::TriMesh* support,
                                        const Support* leaves_outside) {
  IvyMeshes meshes = BuildIvyMeshes(model, params, leaves_outside);
  gltf::Document doc;
  doc.scene_name = "ivy";
  nlohmann::json extras;
  // The parameters by key (sorted, as nlohmann::json keeps objects), each value a double: the
  // same text ParamsToJson's round trip through parse gave, without the parse.
  nlohmann::json& by_key = extras["params"] = nlohmann::json::object();
  for (std::size_t i = 0; i < params.size(); ++i) by_key[params.table().row(i).key] = params.Get(i);
  extras["seed"] = seed;
  extras["steps"] = steps;
  doc.asset_extras_json = extras.dump();
  auto material = [&](const char* name, std::array<double, 4> colour) {
    gltf::Material mat;
    mat.name = name;
    mat.base_color_factor = colour;
    mat.metallic_factor = 0;
    mat.roughness_factor = 0.8;
    mat.double_sided = true;
    doc.materials.push_back(mat);
    return static_cast<int>(doc.materials.size() - 1);
  };
  auto add = [&](const char* name, geom::TriMesh mesh, int mat) {
    if (mesh.triangle_count() == 0) return;
    gltf::Primitive prim;
    prim.mesh = std::move(mesh);
    prim.material = mat;
    prim.index_type = gltf::IndexType::kUint32;
    gltf::Mesh out;  // moved in: a braced {prim} would copy every vertex
    out.name = name;
    out.primitives.push_back(std::move(prim));
    doc.meshes.push_back(std::move(out));
    gltf::Node node;
    node.name = name;
    node.mesh = static_cast<int>(doc.meshes.size() - 1);
    doc.nodes.push_back(node);
    doc.scene_nodes.push_back(static_cast<int>(doc.nodes.size() - 1));
  };
  add("ivy_stems", std::move(meshes.stems), material("stem", {0.35, 0.22, 0.12, 1}));
  // The leaf's texture (ivy_leaf_texture.h); its factor white so the texels give the colour.
  const Result<std::vector<unsigned char>>& leaf_png = LeafTexturePng();
  if (!leaf_png.ok()) return leaf_png.status().Within("leaf texture");
  gltf::Texture leaf_texture;
  leaf_texture.name = "ivy_leaf";
  leaf_texture.png = *leaf_png;
  leaf_texture.wrap_s = leaf_texture.wrap_t = gltf::Wrap::kClampToEdge;
  doc.textures.push_back(std::move(leaf_texture));
  const int leaf_material = material("leaf", {1, 1, 1, 1});
  doc.materials[static_cast<std::size_t>(leaf_material)].base_color_texture =
      static_cast<int>(doc.textures.size()) - 1;
  add("ivy_leaves", std::move(meshes.leaves), leaf_material);
  add("ivy_suckers", std::move(meshes.suckers), material("sucker", {0.55, 0.4, 0.25, 1}));
  if (support != nullptr) {
    geom::TriMesh s;
    s.positions = support->positions;
    s.indices = support->indices;
    if (support->normals.size() == support->positions.size()) s.normals = support->normals;
    add("support", std::move(s), material("support", {0.7, 0.7, 0.7, 1}));
  }
  return doc;
}

Result<std::vector<unsigned char>> WriteIvyGlb(const IvyModel& model, const IvyParams& params,
                                               uint64_t seed, int steps,
                                               const geom::TriMesh* support,
                                               const Support* leaves_outside) {
  Result<gltf::Document> doc =
      BuildIvyDocument(model, params, seed, steps, support, leaves_outside);
  if (!doc.ok()) return doc.status();
  return gltf::WriteGlb(*doc);
}

}  // namespace niwa::ivy
