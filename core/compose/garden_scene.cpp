// The garden's ground and objects (see garden_scene.h).
#include "compose/garden_scene.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

#include "geom/bvh.h"
#include "geom/mesh_metrics.h"
#include "geom/primitives.h"
#include "geom/ray_cast.h"
#include "math/det_math.h"
#include "random/pcg32.h"
#include "terrain/terrain_params.h"
#include "terrain/terrain_run.h"

namespace niwa::compose {
namespace {

// A ground mesh: bytes a triangle holds in its BVH while the grid's rays are cast, seconds a
// triangle's build takes and seconds a ray takes (generous: docs/budgets.md).
constexpr double kGroundMeshBytesPerTriangle = 256;
constexpr double kGroundMeshSecondsPerTriangle = 1e-6;
constexpr double kGroundMeshSecondsPerRay = 5e-6;

// Bytes a ground vertex holds while built (a height, then position, normal, uv and its share of
// the indices) and seconds a vertex takes: counts times generous constants (docs/budgets.md).
constexpr double kGroundBytesPerVertex = 8 + 12 + 12 + 8 + 24;
constexpr double kGroundSecondsPerVertex = 2e-7;

// Bilinear sample of a row-major grid of w × h values at (fx, fy) in cell units, clamped.
double SampleGrid(const std::vector<double>& v, int w, int h, double fx, double fy) {
  fx = std::clamp(fx, 0.0, static_cast<double>(w - 1));
  fy = std::clamp(fy, 0.0, static_cast<double>(h - 1));
  const int i = std::min(static_cast<int>(fx), w - 2 < 0 ? 0 : w - 2);
  const int j = std::min(static_cast<int>(fy), h - 2 < 0 ? 0 : h - 2);
  const double u = w > 1 ? fx - i : 0, t = h > 1 ? fy - j : 0;
  auto at = [&](int a, int b) {
    return v[static_cast<std::size_t>(std::min(b, h - 1)) * w + std::min(a, w - 1)];
  };
  return (1 - t) * ((1 - u) * at(i, j) + u * at(i + 1, j)) +
         t * ((1 - u) * at(i, j + 1) + u * at(i + 1, j + 1));
}

// Scales heights to [0, relief] (all 0 when flat or relief 0).
void NormaliseHeights(std::vector<double>* h, double relief) {
  if (h->empty()) return;
  const auto [lo, hi] = std::minmax_element(h->begin(), h->end());
  const double low = *lo, span = *hi - *lo;
  for (double& v : *h) v = span > 0 && relief > 0 ? (v - low) / span * relief : 0.0;
}

// Fills the vertices of an m × m grid whose `known` is false, ring by ring outwards from the
// known ones: each takes the mean of its eight neighbours known or filled in an earlier ring (the
// rings in grid order, so the fill is the same bits everywhere). Needs one known vertex.
void FillFromNeighbours(std::vector<double>* h, std::vector<bool> known, int m) {
  std::vector<std::size_t> ring;
  for (;;) {
    ring.clear();
    std::vector<double> value;
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) {
        const std::size_t k = static_cast<std::size_t>(j) * m + i;
        if (known[k]) continue;
        double sum = 0;
        int count = 0;
        for (int dj = -1; dj <= 1; ++dj)
          for (int di = -1; di <= 1; ++di) {
            const int ii = i + di, jj = j + dj;
            if (ii < 0 || jj < 0 || ii >= m || jj >= m) continue;
            const std::size_t q = static_cast<std::size_t>(jj) * m + ii;
            if (known[q]) sum += (*h)[q], ++count;
          }
        if (count > 0) ring.push_back(k), value.push_back(sum / count);
      }
    if (ring.empty()) return;
    for (std::size_t r = 0; r < ring.size(); ++r) (*h)[ring[r]] = value[r], known[ring[r]] = true;
  }
}

void AppendMesh(geom::TriMesh* into, const geom::TriMesh& part) {
  const uint32_t base = static_cast<uint32_t>(into->positions.size());
  into->positions.insert(into->positions.end(), part.positions.begin(), part.positions.end());
  into->normals.insert(into->normals.end(), part.normals.begin(), part.normals.end());
  if (part.uvs.size() == part.positions.size()) {
    into->uvs.insert(into->uvs.end(), part.uvs.begin(), part.uvs.end());
  } else {
    into->uvs.insert(into->uvs.end(), part.positions.size(), glm::vec2(0.0f));
  }
  for (uint32_t i : part.indices) into->indices.push_back(base + i);
}

geom::TriMesh Moved(geom::TriMesh mesh, const glm::vec3& by) {
  for (glm::vec3& p : mesh.positions) p += by;
  return mesh;
}

}  // namespace

glm::dvec2 TurnPlan(double x, double z, double rot_deg) {
  const double a = rot_deg * det::kPi / 180.0;
  const double c = det::Cos(a), s = det::Sin(a);
  return {c * x + s * z, -s * x + c * z};
}

GardenGround::Plane GardenGround::PlaneAt(double x, double z) const {
  if (n <= 0) return {};
  const double fx = std::clamp((x + size / 2) / cell, 0.0, static_cast<double>(n));
  const double fz = std::clamp((z + size / 2) / cell, 0.0, static_cast<double>(n));
  const int i = std::min(static_cast<int>(fx), n - 1), j = std::min(static_cast<int>(fz), n - 1);
  const double u = fx - i, v = fz - j;
  const double h00 = At(i, j), h10 = At(i + 1, j), h01 = At(i, j + 1), h11 = At(i + 1, j + 1);
  // Triangles (00, 11, 10) where u >= v and (00, 01, 11) where u < v: Mesh()'s split.
  Plane p;
  p.dx = u >= v ? h10 - h00 : h11 - h01;
  p.dz = u >= v ? h11 - h10 : h01 - h00;
  p.h = h00 + u * p.dx + v * p.dz;
  return p;
}

double GardenGround::HeightAt(double x, double z) const { return PlaneAt(x, z).h; }

double GardenGround::SlopeAt(double x, double z) const {
  const Plane p = PlaneAt(x, z);
  const double g = std::sqrt(p.dx * p.dx + p.dz * p.dz) / cell;
  return det::Atan2(g, 1.0) * 180.0 / det::kPi;
}

geom::TriMesh GardenGround::Mesh() const {
  geom::TriMesh mesh;
  const int m = n + 1;
  mesh.positions.reserve(static_cast<std::size_t>(m) * m);
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      mesh.positions.emplace_back(-size / 2 + i * cell, At(i, j), -size / 2 + j * cell);
      const double dx = (At(std::min(i + 1, n), j) - At(std::max(i - 1, 0), j)) /
                        ((std::min(i + 1, n) - std::max(i - 1, 0)) * cell);
      const double dz = (At(i, std::min(j + 1, n)) - At(i, std::max(j - 1, 0))) /
                        ((std::min(j + 1, n) - std::max(j - 1, 0)) * cell);
      mesh.normals.push_back(glm::normalize(glm::vec3(-dx, 1.0, -dz)));
      mesh.uvs.emplace_back(static_cast<float>(static_cast<double>(i) / n),
                            static_cast<float>(static_cast<double>(j) / n));
    }
  mesh.indices.reserve(static_cast<std::size_t>(n) * n * 6);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const uint32_t v00 = j * m + i, v10 = v00 + 1, v01 = v00 + m, v11 = v01 + 1;
      mesh.indices.insert(mesh.indices.end(), {v00, v11, v10, v00, v01, v11});
    }
  return mesh;
}

bool PlacedObject::Covers(double px, double pz, double margin) const {
  const glm::dvec2 local = TurnPlan(px - x, pz - z, -rot);
  return std::abs(local.x) <= hx + margin && std::abs(local.y) <= hz + margin;
}

Result<GardenGround> BuildGardenGround(const GardenState& state, const Budget& budget,
                                       std::string* truncated_by) {
  GardenGround g;
  g.n = state.params.GetInt(GardenParam::kGroundRes);
  g.size = state.params.Get(GardenParam::kSize);
  g.cell = g.size / g.n;
  const double vertices = static_cast<double>(g.n + 1) * (g.n + 1);
  NIWA_RETURN_IF_ERROR(
      CheckEstimate({vertices * kGroundBytesPerVertex, vertices * kGroundSecondsPerVertex,
                     "the ground (" + FormatCount(vertices) + " vertices)"},
                    budget, "lower ground_res"));
  const int m = g.n + 1;
  g.h.assign(static_cast<std::size_t>(m) * m, 0.0);
  const double relief = state.params.Get(GardenParam::kRelief);
  if (state.ground == GroundKind::kFlat || relief == 0) {
    g.source = "flat";
  } else if (state.ground == GroundKind::kTerrain) {
    terrain::TerrainState ts = state.terrain;
    NIWA_RETURN_IF_ERROR(
        ts.params.Set(terrain::TerrainParam::kRes, std::min(g.n, 256)).Within("ground.terrain"));
    terrain::TerrainRunPlan plan;
    Result<terrain::TerrainRun> run = terrain::TerrainRun::Start(ts, budget, std::move(plan));
    if (!run.ok()) return run.status().Within("ground.terrain");
    NIWA_RETURN_IF_ERROR(run->Advance(nullptr).Within("ground.terrain"));
    if (truncated_by != nullptr) *truncated_by = run->truncated_by();
    const terrain::Heightfield& hf = run->heightfield();
    if (hf.width < 2 || hf.height < 2) return Status::Error("ground.terrain", "grew no surface");
    // The square of the heightfield's longer side, centred on its box: garden x east = plan x,
    // garden z south = −plan y.
    const double w = hf.width * hf.cell, hh = hf.height * hf.cell;
    const double side = std::max(w, hh);
    const double cx = hf.x0 + w / 2, cy = hf.y1 - hh / 2;
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) {
        const double px = cx + (static_cast<double>(i) / g.n - 0.5) * side;
        const double py = cy - (static_cast<double>(j) / g.n - 0.5) * side;
        g.h[static_cast<std::size_t>(j) * m + i] = SampleGrid(
            hf.h, hf.width, hf.height, (px - hf.x0) / hf.cell - 0.5, (hf.y1 - py) / hf.cell - 0.5);
      }
    g.source = "terrain " + (ts.preset.empty() ? std::string("default") : ts.preset) + " (seed " +
               std::to_string(ts.seed) + ")";
  } else if (state.ground == GroundKind::kMesh) {
    // Any mesh as the ground, as a heightmap is: its plan's bounding square (the longer side,
    // centred) stretched over the garden's square, x east and z south as the mesh's own x and z,
    // and the surface seen from above (a ray down at each vertex of the grid: the highest hit)
    // scaled to `relief`. Overhangs and caves are lost; a vertex whose ray meets nothing (a hole,
    // or beyond a round mesh's rim) takes the mean of its hit or already filled neighbours, ring
    // by ring outwards from the hits, so the surface runs on level past the rim (before
    // 2026-12-07 it took the lowest height hit: a cliff at the rim of a round mesh).
    const geom::TriMesh& mesh = state.ground_mesh;
    const std::string name = "'" + state.heightmap_name + "'";
    if (mesh.triangle_count() == 0)
      return Status::Error("ground.file", name + " has no triangles; must be a mesh to stand on");
    const double triangles = static_cast<double>(mesh.triangle_count());
    NIWA_RETURN_IF_ERROR(CheckEstimate(
        {triangles * kGroundMeshBytesPerTriangle,
         triangles * kGroundMeshSecondsPerTriangle + vertices * kGroundMeshSecondsPerRay,
         "the ground mesh (" + FormatCount(triangles) + " triangles, " + FormatCount(vertices) +
             " rays)"},
        budget, "lower ground_res or use a smaller mesh"));
    const geom::Bounds3 bounds = geom::MeshBounds(mesh);
    const glm::dvec3 lo(bounds.min), hi(bounds.max);
    const double side = std::max(hi.x - lo.x, hi.z - lo.z);
    if (!(side > 0) || !std::isfinite(side))
      return Status::Error("ground.file", name + " has no extent in plan (x, z); must be a ground");
    const double cx = (lo.x + hi.x) / 2, cz = (lo.z + hi.z) / 2;
    const geom::Bvh bvh = geom::Bvh::Build(mesh);
    const float top = static_cast<float>(hi.y + 1.0 + 0.01 * (hi.y - lo.y));
    std::vector<bool> hit(g.h.size(), false);
    double lowest = std::numeric_limits<double>::infinity();
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) {
        const double px = cx + (static_cast<double>(i) / g.n - 0.5) * side;
        const double pz = cz + (static_cast<double>(j) / g.n - 0.5) * side;
        const geom::RayHit r = geom::FirstHitWithoutNormal(
            mesh, bvh, glm::vec3(static_cast<float>(px), top, static_cast<float>(pz)),
            glm::vec3(0, -1, 0), std::numeric_limits<float>::infinity());
        if (!r.hit) continue;
        const std::size_t k = static_cast<std::size_t>(j) * m + i;
        g.h[k] = static_cast<double>(r.point.y);
        hit[k] = true;
        lowest = std::min(lowest, g.h[k]);
      }
    if (!std::isfinite(lowest))
      return Status::Error("ground.file", name + ": no ray from above meets it; must be a ground");
    FillFromNeighbours(&g.h, hit, m);
    g.source = "mesh " + state.heightmap_name + " (" + FormatCount(triangles) + " triangles)";
  } else {
    Result<image::Gray16Image> img =
        DecodeGardenHeightmap(state.heightmap_name, state.heightmap_png);
    if (!img.ok()) return img.status();
    std::vector<double> v(img->pixels.begin(), img->pixels.end());
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i)
        g.h[static_cast<std::size_t>(j) * m + i] =
            SampleGrid(v, img->width, img->height, static_cast<double>(i) / g.n * (img->width - 1),
                       static_cast<double>(j) / g.n * (img->height - 1)) /
            65535.0;
    g.source = "heightmap " + state.heightmap_name + " (" + std::to_string(img->width) + " x " +
               std::to_string(img->height) + ")";
  }
  if (g.source != "flat") NormaliseHeights(&g.h, relief);
  g.relief = *std::max_element(g.h.begin(), g.h.end());
  return g;
}

geom::TriMesh GardenObjectMesh(const std::string& kind, uint64_t variant) {
  geom::TriMesh mesh;
  if (kind == "wall") {
    // A garden wall (tsuiji-bei): 6 m long, 1.8 m high, 0.45 m thick, with a coping on top.
    AppendMesh(&mesh, geom::MakeBox({6.0f, 1.6f, 0.45f}, {0.0f, 0.8f, 0.0f}));
    AppendMesh(&mesh, geom::MakeBox({6.3f, 0.2f, 0.7f}, {0.0f, 1.7f, 0.0f}));
  } else if (kind == "lantern") {
    // A stone lantern (tōrō): base, post, platform, fire box, roof and finial, 1.6 m high.
    AppendMesh(&mesh, geom::MakeCylinder(0.32f, 0.15f, 12));
    AppendMesh(&mesh, Moved(geom::MakeCylinder(0.12f, 0.6f, 10), {0.0f, 0.15f, 0.0f}));
    AppendMesh(&mesh, geom::MakeBox({0.5f, 0.12f, 0.5f}, {0.0f, 0.81f, 0.0f}));
    AppendMesh(&mesh, geom::MakeBox({0.34f, 0.3f, 0.34f}, {0.0f, 1.02f, 0.0f}));
    AppendMesh(&mesh, geom::MakeBox({0.7f, 0.1f, 0.7f}, {0.0f, 1.22f, 0.0f}));
    AppendMesh(&mesh, geom::MakeBox({0.45f, 0.12f, 0.45f}, {0.0f, 1.33f, 0.0f}));
    AppendMesh(&mesh, Moved(geom::MakeCylinder(0.07f, 0.2f, 8), {0.0f, 1.39f, 0.0f}));
  } else {
    // A rock: an icosphere 1.4 m across, flattened, its radius varied by a seeded low-frequency
    // bump, sunk so its widest ring sits at the ground (base centre at y = 0).
    geom::TriMesh rock = geom::MakeIcosphere(0.7f, 2);
    Pcg32 rng(0x526f636bULL + variant);
    glm::vec3 bumps[4];
    for (glm::vec3& b : bumps) {
      // Drawn one at a time: the order of a constructor's arguments is unspecified.
      const float bx = static_cast<float>(rng.Uniform() * 2 - 1);
      const float by = static_cast<float>(rng.Uniform() * 2 - 1);
      const float bz = static_cast<float>(rng.Uniform() * 2 - 1);
      b = glm::vec3(bx, by, bz);
      if (glm::length(b) < 1e-3f) b = glm::vec3(0, 1, 0);
      b = glm::normalize(b);
    }
    for (glm::vec3& p : rock.positions) {
      const glm::vec3 d = glm::normalize(p);
      float r = 1.0f;
      for (const glm::vec3& b : bumps) r += 0.12f * glm::dot(d, b) * glm::dot(d, b);
      p = d * (0.7f * r);
      p.y = p.y * 0.6f + 0.1f;
    }
    rock.normals.clear();
    // Flat-ish normals from the faces around each vertex.
    rock.normals.assign(rock.positions.size(), glm::vec3(0.0f));
    for (std::size_t t = 0; t < rock.triangle_count(); ++t) {
      const uint32_t a = rock.indices[3 * t], b = rock.indices[3 * t + 1],
                     c = rock.indices[3 * t + 2];
      const glm::vec3 fn =
          glm::cross(rock.positions[b] - rock.positions[a], rock.positions[c] - rock.positions[a]);
      rock.normals[a] += fn, rock.normals[b] += fn, rock.normals[c] += fn;
    }
    for (glm::vec3& nrm : rock.normals) nrm = glm::normalize(nrm);
    AppendMesh(&mesh, rock);
  }
  return mesh;
}

// A dropped mesh as an object: its bounds' base centre moved to the origin (so it stands where it
// is placed, on the ground), its uvs and other attributes dropped (objects are drawn in one plain
// material), and a normal per vertex (geom::FaceNormals: its triangles', area-weighted) when it has
// none.
geom::TriMesh StandingMesh(const geom::TriMesh& in) {
  geom::TriMesh mesh;
  mesh.positions = in.positions;
  mesh.indices = in.indices;
  if (mesh.positions.empty()) return mesh;
  const geom::Bounds3 box = geom::MeshBounds(mesh);
  const glm::vec3 base((box.min.x + box.max.x) / 2, box.min.y, (box.min.z + box.max.z) / 2);
  for (glm::vec3& p : mesh.positions) p -= base;
  mesh.normals = in.normals.size() == in.positions.size() ? in.normals : geom::FaceNormals(mesh);
  return mesh;
}

Result<GardenScene> BuildGardenScene(const GardenState& state, const Budget& budget) {
  GardenScene scene;
  Result<GardenGround> ground = BuildGardenGround(state, budget, &scene.truncated_by);
  if (!ground.ok()) return ground.status();
  scene.ground = std::move(*ground);
  for (std::size_t k = 0; k < state.objects.size(); ++k) {
    const GardenObject& o = state.objects[k];
    PlacedObject placed;
    placed.kind = o.kind;
    placed.x = o.x, placed.z = o.z, placed.rot = o.rot;
    placed.base_y = scene.ground.HeightAt(o.x, o.z);
    geom::TriMesh mesh = o.kind == "mesh" ? StandingMesh(o.mesh) : GardenObjectMesh(o.kind, k);
    if (mesh.triangle_count() == 0)
      return Status::Error("objects[" + std::to_string(k) + "].file",
                           "'" + o.file + "' has no triangles; must be a mesh");
    const geom::Bounds3 box = geom::MeshBounds(mesh);
    placed.hx = std::max(std::abs(box.min.x), std::abs(box.max.x)) * o.scale;
    placed.hz = std::max(std::abs(box.min.z), std::abs(box.max.z)) * o.scale;
    const double a = o.rot * det::kPi / 180.0;
    const float c = static_cast<float>(det::Cos(a)), s = static_cast<float>(det::Sin(a));
    const float sc = static_cast<float>(o.scale);
    for (glm::vec3& p : mesh.positions) {
      const glm::vec3 q = p * sc;
      p = glm::vec3(c * q.x + s * q.z, q.y + static_cast<float>(placed.base_y),
                    -s * q.x + c * q.z) +
          glm::vec3(static_cast<float>(o.x), 0.0f, static_cast<float>(o.z));
    }
    for (glm::vec3& nrm : mesh.normals)
      nrm = glm::vec3(c * nrm.x + s * nrm.z, nrm.y, -s * nrm.x + c * nrm.z);
    placed.mesh = std::move(mesh);
    scene.objects.push_back(std::move(placed));
  }
  return scene;
}

}  // namespace niwa::compose
