// `niwa mesh stats|closest|ray`: load a .glb/.gltf/.obj (or a built-in scene), build the BVH and
// answer one query, as one JSON object on stdout (metres, world space).
#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "base/echo.h"
#include "cli_common.h"
#include "geom/bvh.h"
#include "geom/closest_point.h"
#include "geom/mesh_metrics.h"
#include "geom/primitives.h"
#include "geom/ray_cast.h"
#include "io/mesh_reader.h"
#include "params/param_text.h"

namespace niwa::cli {
namespace {

constexpr int kMaxSubdivide = 8;
constexpr double kMaxCoordinate = 1e30;

// Flags every mesh command shares.
struct MeshSource {
  std::string mesh, scene;
  int subdivide = 0;
};

void AddMeshSource(CLI::App* cmd, MeshSource* s) {
  CLI::Option* mesh = AddInputFlag(cmd, "--mesh", &s->mesh,
                                   "Mesh file: .glb, .gltf (glTF 2.0, Draco natively) or .obj");
  CLI::Option* scene =
      cmd->add_option("--scene", s->scene,
                      "Built-in mesh instead of --mesh: box (1 m cube), plane (2 m, 4 x 4 quads), "
                      "cylinder (r 0.5 m, h 1 m, 32 sides), icosphere (r 1 m, level 3)");
  Excludes(mesh, scene);
  AddNumberFlag(cmd, "--subdivide", &s->subdivide, {0, kMaxSubdivide, true},
                "Split every triangle into 4^K coplanar ones, K in [0, 8] (default 0)");
}

glm::vec3 ParseVec3(const std::string& flag, const std::string& text) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    std::size_t comma = text.find(',', start);
    parts.push_back(
        text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  const std::string range = "must be three numbers X,Y,Z, each in [-1e30, 1e30]";
  if (text.empty()) Fail(Status::Error(flag, "required; " + range));
  if (parts.size() != 3)
    Fail(Status::Error(flag, "'" + Echo(text) + "' is not three numbers; " + range));
  glm::vec3 v;
  for (int i = 0; i < 3; ++i) {
    std::optional<double> x = ParseNumber(parts[static_cast<std::size_t>(i)]);
    if (!x || std::fabs(*x) > kMaxCoordinate) {
      Fail(Status::Error(flag, "'" + Echo(text) + "' is out of range; " + range));
    }
    v[i] = static_cast<float>(*x);
  }
  return v;
}

float ParseMaxDistance(const std::string& text) {
  if (text.empty() || text == "inf") return std::numeric_limits<float>::infinity();
  std::optional<double> r = ParseNumber(text);
  if (!r || *r < 0 || *r > kMaxCoordinate) {
    Fail(Status::Error("--max-distance", "'" + text +
                                             "' is out of range; must be a number in [0, 1e30] "
                                             "or inf (the default)"));
  }
  return static_cast<float>(*r);
}

nlohmann::json Vec(const glm::vec3& v) {
  return nlohmann::json::array(
      {static_cast<double>(v.x), static_cast<double>(v.y), static_cast<double>(v.z)});
}

// The mesh and its BVH, with what loading them took.
struct LoadedMesh {
  geom::TriMesh mesh;
  io::MeshReadStats read;
  geom::Bvh bvh;
  double ms_load = 0, ms_bvh = 0;
};

LoadedMesh Load(const MeshSource& s) {
  if (!s.mesh.empty() && !s.scene.empty()) {
    Fail(Status::Error("--mesh", "give either --mesh FILE or --scene NAME, not both"));
  }
  if (s.mesh.empty() && s.scene.empty()) {
    Fail(Status::Error("--mesh",
                       "required: a .glb, .gltf or .obj file (or --scene "
                       "box|plane|cylinder|icosphere)"));
  }
  const int levels = s.subdivide;  // parsed strictly by its flag
  LoadedMesh out;
  auto t0 = std::chrono::steady_clock::now();
  if (!s.mesh.empty()) {
    Result<geom::TriMesh> mesh = io::ReadMeshFile(s.mesh, &out.read);
    if (!mesh.ok()) Fail(mesh.status().Within("--mesh"));
    out.mesh = std::move(mesh).value();
  } else if (s.scene == "box") {
    out.mesh = geom::MakeBox(glm::vec3(1.0f));
  } else if (s.scene == "plane") {
    out.mesh = geom::MakePlane(2.0f, 2.0f, 4, 4);
  } else if (s.scene == "cylinder") {
    out.mesh = geom::MakeCylinder(0.5f, 1.0f, 32);
  } else if (s.scene == "icosphere") {
    out.mesh = geom::MakeIcosphere(1.0f, 3);
  } else {
    Fail(Status::Error("--scene", "'" + s.scene +
                                      "' is unknown; must be one of box, plane, "
                                      "cylinder, icosphere"));
  }
  if (levels > 0) {
    double after = static_cast<double>(out.mesh.triangle_count()) * std::pow(4.0, levels);
    if (after > static_cast<double>(io::kMaxMeshTriangles)) {
      Fail(Status::Error("--subdivide", std::to_string(levels) + " would make " +
                                            FormatNumber(after) + " triangles; the limit is " +
                                            std::to_string(io::kMaxMeshTriangles) + " (4 M)"));
    }
    out.mesh = geom::Subdivide(out.mesh, levels);
  }
  Check(geom::ValidateMesh(out.mesh, s.mesh.empty() ? "--scene" : "--mesh"));
  auto t1 = std::chrono::steady_clock::now();
  out.bvh = geom::Bvh::Build(out.mesh);
  auto t2 = std::chrono::steady_clock::now();
  out.ms_load = Ms(t0, t1);
  out.ms_bvh = Ms(t1, t2);
  return out;
}

int RunStats(const MeshSource& s, std::ostream& out) {
  LoadedMesh m = Load(s);
  geom::Bounds3 b = geom::MeshBounds(m.mesh);
  nlohmann::json j;
  j["triangles"] = m.mesh.triangle_count();
  j["vertices"] = m.mesh.vertex_count();
  j["degenerate"] = m.read.degenerate;
  j["bounds"] = {{"min", Vec(b.min)}, {"max", Vec(b.max)}};
  j["area"] = geom::SurfaceArea(m.mesh);
  j["meshes"] = m.read.meshes;
  j["skipped_points_lines"] = m.read.skipped_points_lines;
  j["draco_primitives"] = m.read.draco_primitives;
  j["bvh_nodes"] = m.bvh.node_count();
  j["bvh_depth"] = m.bvh.depth();
  j["ms_load"] = m.ms_load;
  j["ms_bvh"] = m.ms_bvh;
  out << j.dump() << "\n";
  return 0;
}

int RunClosest(const MeshSource& s, const std::string& point, const std::string& max_distance,
               std::ostream& out) {
  const glm::vec3 p = ParseVec3("--point", point);
  const float r = ParseMaxDistance(max_distance);
  LoadedMesh m = Load(s);
  geom::ClosestHit hit = geom::ClosestPoint(m.mesh, m.bvh, p, r);
  nlohmann::json j;
  j["found"] = hit.found;
  if (hit.found) {
    j["distance"] = static_cast<double>(hit.distance);
    j["point"] = Vec(hit.point);
    j["triangle"] = hit.triangle;
  }
  out << j.dump() << "\n";
  return 0;
}

int RunRay(const MeshSource& s, const std::string& origin, const std::string& dir,
           const std::string& max_distance, std::ostream& out) {
  const glm::vec3 o = ParseVec3("--origin", origin);
  const glm::vec3 d = ParseVec3("--dir", dir);
  if (d.x == 0.0f && d.y == 0.0f && d.z == 0.0f) {
    Fail(Status::Error("--dir", "'" + Echo(dir) + "' is zero; must be a non-zero direction X,Y,Z"));
  }
  const float r = ParseMaxDistance(max_distance);
  LoadedMesh m = Load(s);
  geom::RayHit hit = geom::FirstHit(m.mesh, m.bvh, o, d, r);
  nlohmann::json j;
  j["hit"] = hit.hit;
  if (hit.hit) {
    j["distance"] = static_cast<double>(hit.distance);
    j["point"] = Vec(hit.point);
    j["triangle"] = hit.triangle;
  }
  out << j.dump() << "\n";
  return 0;
}

}  // namespace

void AddMeshCommands(CLI::App& app, CommandList& commands) {
  CLI::App* mesh = app.add_subcommand(
      "mesh", "Read a mesh (.glb/.gltf/.obj) and query it: statistics, closest point, ray hit");
  mesh->require_subcommand(1);

  struct Options {
    MeshSource stats, closest, ray;
    std::string point, closest_max, origin, dir, ray_max;
  };
  auto o = std::make_shared<Options>();

  CLI::App* stats = mesh->add_subcommand(
      "stats", "Triangles, vertices, degenerate triangles, bounds, area and BVH size, as JSON");
  AddMeshSource(stats, &o->stats);
  commands.push_back(
      {stats, [o](std::ostream& out) { return RunStats(o->stats, out); }, {"--scene", "box"}});

  CLI::App* closest = mesh->add_subcommand(
      "closest", "Nearest surface point to --point (distance, point, triangle)");
  AddMeshSource(closest, &o->closest);
  closest->add_option("--point", o->point, "Query point X,Y,Z in metres");
  closest->add_option("--max-distance", o->closest_max,
                      "Search radius in metres, in [0, 1e30] or inf (default inf)");
  commands.push_back(
      {closest,
       [o](std::ostream& out) { return RunClosest(o->closest, o->point, o->closest_max, out); },
       {"--scene", "box", "--point", "0,2,0"}});

  CLI::App* ray = mesh->add_subcommand("ray", "First hit of the ray --origin + t --dir, t >= 0");
  AddMeshSource(ray, &o->ray);
  ray->add_option("--origin", o->origin, "Ray origin X,Y,Z in metres");
  ray->add_option("--dir", o->dir, "Ray direction X,Y,Z (any non-zero length)");
  ray->add_option("--max-distance", o->ray_max,
                  "Longest t in metres, in [0, 1e30] or inf (default inf)");
  commands.push_back(
      {ray,
       [o](std::ostream& out) { return RunRay(o->ray, o->origin, o->dir, o->ray_max, out); },
       {"--scene", "box", "--origin", "0,2,0", "--dir", "0,-1,0"}});
}

}  // namespace niwa::cli
