// The moss study's built-in scenes: boxes and a ground tessellated on a 5 cm grid, and icosphere
// rocks (scenes.h).
#include "moss/scenes.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <glm/geometric.hpp>
#include <map>
#include <utility>

#include "base/echo.h"
#include "math/det_math.h"

namespace niwa::moss {
namespace {

struct SceneSquare {
  glm::dvec3 centre;
  glm::dvec3 normal;
};
using SceneSquareRule = std::function<bool(const SceneSquare&)>;
using SceneLabel = std::function<std::pair<Geology, uint8_t>(const SceneSquare&)>;

// One face of a box (or a ground) as a grid of squares over origin + a·u + b·v, a, b in [0, 1];
// the outward normal is unit(u × v). A square whose centre `skip` names is left out (it lies
// under another solid); its two triangles otherwise take label(centre).
void AddSceneGrid(MossScene* scene, glm::dvec3 origin, glm::dvec3 u, glm::dvec3 v,
                  const SceneLabel& label, const SceneSquareRule& skip = nullptr) {
  const int nu = std::max(1, static_cast<int>(std::lround(glm::length(u) / kSceneGrid)));
  const int nv = std::max(1, static_cast<int>(std::lround(glm::length(v) / kSceneGrid)));
  const glm::dvec3 normal = glm::normalize(glm::cross(u, v));
  geom::TriMesh& mesh = scene->mesh;
  const uint32_t base = static_cast<uint32_t>(mesh.positions.size());
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) {
      const glm::dvec3 p =
          origin + u * (static_cast<double>(i) / nu) + v * (static_cast<double>(j) / nv);
      mesh.positions.push_back(glm::vec3(p));
      mesh.normals.push_back(glm::vec3(normal));
    }
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      SceneSquare square{origin + u * ((i + 0.5) / nu) + v * ((j + 0.5) / nv), normal};
      if (skip && skip(square)) continue;
      const auto [geology, region] = label(square);
      const uint32_t p00 = base + static_cast<uint32_t>(j * (nu + 1) + i);
      const uint32_t p10 = p00 + 1, p01 = p00 + static_cast<uint32_t>(nu + 1), p11 = p01 + 1;
      mesh.indices.insert(mesh.indices.end(), {p00, p10, p11, p00, p11, p01});
      for (int t = 0; t < 2; ++t) {
        scene->geology.push_back(geology);
        scene->region.push_back(region);
      }
    }
}

enum SceneBoxFace {
  kBoxTop = 1,
  kBoxBottom = 2,
  kBoxPlusX = 4,
  kBoxMinusX = 8,
  kBoxPlusZ = 16,
  kBoxMinusZ = 32,
  kBoxAll = 63
};

// The faces `faces` of the box lo..hi, outward.
void AddSceneBox(MossScene* scene, glm::dvec3 lo, glm::dvec3 hi, int faces, const SceneLabel& label,
                 const SceneSquareRule& skip = nullptr) {
  const glm::dvec3 d = hi - lo;
  const glm::dvec3 X(d.x, 0, 0), Y(0, d.y, 0), Z(0, 0, d.z);
  if (faces & kBoxTop) AddSceneGrid(scene, {lo.x, hi.y, lo.z}, Z, X, label, skip);
  if (faces & kBoxBottom) AddSceneGrid(scene, lo, X, Z, label, skip);
  if (faces & kBoxPlusX) AddSceneGrid(scene, {hi.x, lo.y, lo.z}, Y, Z, label, skip);
  if (faces & kBoxMinusX) AddSceneGrid(scene, lo, Z, Y, label, skip);
  if (faces & kBoxPlusZ) AddSceneGrid(scene, {lo.x, lo.y, hi.z}, X, Y, label, skip);
  if (faces & kBoxMinusZ) AddSceneGrid(scene, lo, Y, X, label, skip);
}

bool InsideFootprint(const glm::dvec3& p, double x0, double x1, double z0, double z1) {
  return p.x > x0 && p.x < x1 && p.z > z0 && p.z < z1;
}

MossScene PlaneScene() {
  MossScene scene;
  scene.name = "plane";
  scene.region_names = {"ground"};
  scene.description = "a flat 2 m x 2 m humus square at y = 0 (energy and soil checks)";
  AddSceneGrid(&scene, {-1, 0, -1}, {0, 0, 2}, {2, 0, 0},
               [](const SceneSquare&) { return std::make_pair(Geology::kHumus, uint8_t{0}); });
  return scene;
}

// Spec §3: soil slab x, z in [-1, 1], y in [-0.3, 0] (humus x < -1/3, sandy x < 1/3, else asphalt);
// back wall x [-1, 1], y [0, 1.5], z [-1, -0.9] (asphalt); roof x [-1, 1], y [1.0, 1.05],
// z [-0.9, -0.2] (asphalt); stone blocks x [0.3, 0.7] y [0, 0.4] z [0.1, 0.5] and x [-0.7, -0.3]
// y [0, 0.25] z [0.2, 0.6] (sandy). The solids are one union: faces inside another solid (the
// wall's, the stones' bottoms, the slab top under them, the roof's back, the wall front behind the
// roof) are left out.
MossScene ThesisScene() {
  enum : uint8_t {
    kOpen,
    kFloorSheltered,
    kRoofUnder,
    kWallSheltered,
    kTops,
    kOtherVertical,
    kOther
  };
  MossScene scene;
  scene.name = "thesis";
  scene.region_names = {"floor_open", "floor_sheltered", "roof_under", "wall_sheltered",
                        "tops",       "other_vertical",  "other"};
  scene.description =
      "fig 3.1 stand-in: 2 m soil slab (humus, sandy, asphalt by x), back wall 1.5 m, roof at "
      "1.0 m over the back, two sandy stone blocks";
  auto vertical_or = [](const SceneSquare& q, uint8_t otherwise) {
    return std::abs(q.normal.y) < 0.5 ? uint8_t{kOtherVertical} : otherwise;
  };
  // The slab.
  auto slab_geology = [](const SceneSquare& q) {
    return q.centre.x < -1.0 / 3 ? Geology::kHumus
                                 : (q.centre.x < 1.0 / 3 ? Geology::kSandy : Geology::kAsphalt);
  };
  AddSceneBox(
      &scene, {-1, -0.3, -1}, {1, 0, 1}, kBoxTop,
      [&](const SceneSquare& q) {
        return std::make_pair(slab_geology(q),
                              uint8_t(q.centre.z < -0.2 ? kFloorSheltered : kOpen));
      },
      [](const SceneSquare& q) {
        return InsideFootprint(q.centre, -1, 1, -1, -0.9) ||
               InsideFootprint(q.centre, 0.3, 0.7, 0.1, 0.5) ||
               InsideFootprint(q.centre, -0.7, -0.3, 0.2, 0.6);
      });
  AddSceneBox(&scene, {-1, -0.3, -1}, {1, 0, 1}, kBoxAll & ~kBoxTop, [&](const SceneSquare& q) {
    return std::make_pair(slab_geology(q), vertical_or(q, kOther));
  });
  // The back wall: its front (+z) is sheltered below the roof; the strip behind the roof is left
  // out.
  AddSceneBox(
      &scene, {-1, 0, -1}, {1, 1.5, -0.9}, kBoxAll & ~kBoxBottom,
      [&](const SceneSquare& q) {
        const bool front = q.normal.z > 0.5 && q.centre.y < 1.0;
        return std::make_pair(Geology::kAsphalt,
                              front ? uint8_t{kWallSheltered} : vertical_or(q, kTops));
      },
      [](const SceneSquare& q) {
        return q.normal.z > 0.5 && q.centre.y > 1.0 && q.centre.y < 1.05;
      });
  // The roof, its back against the wall.
  AddSceneBox(
      &scene, {-1, 1.0, -0.9}, {1, 1.05, -0.2}, kBoxAll & ~kBoxMinusZ, [&](const SceneSquare& q) {
        return std::make_pair(Geology::kAsphalt,
                              q.normal.y < -0.5 ? uint8_t{kRoofUnder} : vertical_or(q, kTops));
      });
  // The stone blocks.
  auto stone = [&](const SceneSquare& q) {
    return std::make_pair(Geology::kSandy, vertical_or(q, kTops));
  };
  AddSceneBox(&scene, {0.3, 0, 0.1}, {0.7, 0.4, 0.5}, kBoxAll & ~kBoxBottom, stone);
  AddSceneBox(&scene, {-0.7, 0, 0.2}, {-0.3, 0.25, 0.6}, kBoxAll & ~kBoxBottom, stone);
  return scene;
}

// Figs 2.5/2.6: a humus ground (2 m square, y = 0) and two facing asphalt-grey walls 1.6 m long and
// 1 m tall, 1 m apart: with the sun in the south (sun_azimuth 90, e.g. sun_altitude 45) the north
// wall's south face is sunlit and the south wall's north face sees only bounced light.
MossScene WallsScene() {
  enum : uint8_t { kGround, kSunlitFace, kShadedFace, kOther };
  MossScene scene;
  scene.name = "walls";
  scene.region_names = {"ground", "sunlit_face", "shaded_face", "other"};
  scene.description =
      "figs 2.5/2.6: two facing walls 1 m apart on humus; with sun_altitude 45 one face is "
      "sunlit, the other lit only by bounces";
  AddSceneGrid(
      &scene, {-1, 0, -1}, {0, 0, 2}, {2, 0, 0},
      [](const SceneSquare&) { return std::make_pair(Geology::kHumus, uint8_t{kGround}); },
      [](const SceneSquare& q) {
        return InsideFootprint(q.centre, -0.8, 0.8, -0.6, -0.5) ||
               InsideFootprint(q.centre, -0.8, 0.8, 0.5, 0.6);
      });
  AddSceneBox(&scene, {-0.8, 0, -0.6}, {0.8, 1.0, -0.5}, kBoxAll & ~kBoxBottom,
              [](const SceneSquare& q) {
                return std::make_pair(Geology::kAsphalt,
                                      q.normal.z > 0.5 ? uint8_t{kSunlitFace} : uint8_t{kOther});
              });
  AddSceneBox(&scene, {-0.8, 0, 0.5}, {0.8, 1.0, 0.6}, kBoxAll & ~kBoxBottom,
              [](const SceneSquare& q) {
                return std::make_pair(Geology::kAsphalt,
                                      q.normal.z < -0.5 ? uint8_t{kShadedFace} : uint8_t{kOther});
              });
  return scene;
}

// An icosphere of `level` subdivisions (20·4^level triangles, counter-clockwise outward) on the
// unit sphere.
void UnitIcosphere(int level, std::vector<glm::dvec3>* points, std::vector<uint32_t>* tris) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  *points = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
             {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  for (glm::dvec3& p : *points) p = glm::normalize(p);
  *tris = {0, 11, 5,  0, 5,  1, 0, 1, 7, 0, 7,  10, 0, 10, 11, 1, 5, 9, 5, 11,
           4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3,  9,  4, 3,  4,  2, 3, 2, 6, 3,
           6, 8,  3,  8, 9,  4, 9, 5, 2, 4, 11, 6,  2, 10, 8,  6, 7, 9, 8, 1};
  for (int l = 0; l < level; ++l) {
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> middle;
    auto mid = [&](uint32_t a, uint32_t b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = middle.find(key);
      if (it != middle.end()) return it->second;
      points->push_back(glm::normalize((*points)[a] + (*points)[b]));
      const uint32_t index = static_cast<uint32_t>(points->size() - 1);
      middle.emplace(key, index);
      return index;
    };
    std::vector<uint32_t> next;
    next.reserve(tris->size() * 4);
    for (std::size_t i = 0; i < tris->size(); i += 3) {
      const uint32_t a = (*tris)[i], b = (*tris)[i + 1], c = (*tris)[i + 2];
      const uint32_t ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
      next.insert(next.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
    }
    tris->swap(next);
  }
}

// Smooth relief in [-1, 1] for the rocks (det_math only, so every build gets the same bits).
double RockRelief(const glm::dvec3& p) {
  return det::Sin(5.0 * p.x + 1.7) * det::Sin(4.0 * p.y + 0.3) * det::Sin(6.0 * p.z + 2.1);
}

constexpr double kRockRelief = 0.12;  // displacement amplitude, in rock radii

// A humus ground (2 m square, y = 0) and five sandy rocks: icospheres displaced by RockRelief,
// sunk to half their radius. Ground squares whose centre lies within 0.76 r of a rock's axis are
// left out (the undisplaced sphere meets the ground at 0.866 r; the relief moves it by ±12 %).
MossScene RocksScene(int rock_triangles) {
  enum : uint8_t { kGround, kRockUp, kRockSide, kRockDown };
  MossScene scene;
  scene.name = "rocks";
  scene.region_names = {"ground", "rock_up", "rock_side", "rock_down"};
  scene.description =
      "five noise-displaced sandy rocks on a 2 m humus ground (rock_triangles sets their "
      "triangles)";
  struct Rock {
    double x, z, r;
  };
  const Rock rocks[5] = {{-0.5, -0.4, 0.25},
                         {0.45, -0.3, 0.3},
                         {0.0, 0.45, 0.22},
                         {-0.55, 0.5, 0.15},
                         {0.6, 0.55, 0.18}};
  AddSceneGrid(
      &scene, {-1, 0, -1}, {0, 0, 2}, {2, 0, 0},
      [](const SceneSquare&) { return std::make_pair(Geology::kHumus, uint8_t{kGround}); },
      [&](const SceneSquare& q) {
        for (const Rock& rock : rocks) {
          const double dx = q.centre.x - rock.x, dz = q.centre.z - rock.z;
          if (dx * dx + dz * dz < (0.76 * rock.r) * (0.76 * rock.r)) return true;
        }
        return false;
      });
  int level = 0;
  while (5 * 20 * (1 << (2 * level)) < rock_triangles) ++level;
  std::vector<glm::dvec3> unit;
  std::vector<uint32_t> tris;
  UnitIcosphere(level, &unit, &tris);
  geom::TriMesh& mesh = scene.mesh;
  for (const Rock& rock : rocks) {
    const uint32_t base = static_cast<uint32_t>(mesh.positions.size());
    const glm::dvec3 centre(rock.x, 0.5 * rock.r, rock.z);
    for (const glm::dvec3& n : unit) {
      const glm::dvec3 p = centre + n * (rock.r * (1.0 + kRockRelief * RockRelief(n)));
      mesh.positions.push_back(glm::vec3(p));
      mesh.normals.push_back(glm::vec3(n));
    }
    for (std::size_t i = 0; i < tris.size(); i += 3) {
      const uint32_t a = base + tris[i], b = base + tris[i + 1], c = base + tris[i + 2];
      mesh.indices.insert(mesh.indices.end(), {a, b, c});
      const glm::dvec3 pa(mesh.positions[a]), pb(mesh.positions[b]), pc(mesh.positions[c]);
      const glm::dvec3 cr = glm::cross(pb - pa, pc - pa);
      const double len = glm::length(cr);
      const double ny = len > 0 ? cr.y / len : 0;
      scene.geology.push_back(Geology::kSandy);
      scene.region.push_back(ny > 0.5 ? kRockUp : (ny < -0.5 ? kRockDown : kRockSide));
    }
  }
  return scene;
}

}  // namespace

const std::vector<std::string>& SceneNames() {
  static const std::vector<std::string> names = {"plane", "thesis", "walls", "rocks"};
  return names;
}

std::size_t RockTrianglesBuilt(int rock_triangles) {
  std::size_t triangles = 5 * 20;
  while (triangles < static_cast<std::size_t>(std::max(rock_triangles, 0))) triangles *= 4;
  return triangles;
}

Result<MossScene> BuildScene(std::string_view name, int rock_triangles) {
  if (name == "plane") return PlaneScene();
  if (name == "thesis") return ThesisScene();
  if (name == "walls") return WallsScene();
  if (name == "rocks") {
    if (rock_triangles < kRockTrianglesMin || rock_triangles > kRockTrianglesMax)
      return Status::Error("rock_triangles", "must be in " + std::to_string(kRockTrianglesMin) +
                                                 ".." + std::to_string(kRockTrianglesMax));
    return RocksScene(rock_triangles);
  }
  return Status::Error("scene", "'" + Echo(std::string(name)) +
                                    "' is unknown; must be plane, thesis, walls or rocks");
}

}  // namespace niwa::moss
