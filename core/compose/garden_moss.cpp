// Moss over the garden (garden_moss.h).
#include "compose/garden_moss.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <nlohmann/json.hpp>

#include "light/sun.h"
#include "math/det_math.h"
#include "tree/tree_params.h"

namespace niwa::compose {

GardenGround MossGround(const GardenGround& ground) {
  if (ground.n <= kMossGroundCells) return ground;
  GardenGround coarse;
  coarse.n = kMossGroundCells;
  coarse.size = ground.size;
  coarse.cell = ground.size / kMossGroundCells;
  coarse.relief = ground.relief;
  coarse.source = ground.source;
  const int m = coarse.n + 1;
  coarse.h.resize(static_cast<std::size_t>(m) * m);
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i)
      coarse.h[static_cast<std::size_t>(j) * m + i] =
          ground.HeightAt(-ground.size / 2 + i * coarse.cell, -ground.size / 2 + j * coarse.cell);
  return coarse;
}

moss::MossScene GardenMossLand(const GardenScene& scene) {
  moss::MossScene land;
  land.name = "garden";
  land.description = "the garden's ground and objects (metres)";
  land.region_names = {"ground", "wall", "rock", "lantern"};
  auto append = [&](const geom::TriMesh& part, moss::Geology geology, uint8_t region) {
    const uint32_t base = static_cast<uint32_t>(land.mesh.positions.size());
    land.mesh.positions.insert(land.mesh.positions.end(), part.positions.begin(),
                               part.positions.end());
    for (uint32_t i : part.indices) land.mesh.indices.push_back(base + i);
    const std::size_t triangles = part.indices.size() / 3;
    land.geology.insert(land.geology.end(), triangles, geology);
    land.region.insert(land.region.end(), triangles, region);
  };
  geom::TriMesh ground = MossGround(scene.ground).Mesh();
  ground.normals.clear();
  ground.uvs.clear();
  append(ground, moss::Geology::kHumus, 0);
  // A dropped mesh object is a fifth region, "mesh", named only when the garden has one (a garden
  // of built-in objects keeps the four regions of its stats).
  for (const PlacedObject& o : scene.objects)
    if (o.kind == "mesh") {
      land.region_names.push_back("mesh");
      break;
    }
  for (const PlacedObject& o : scene.objects) {
    const uint8_t region = o.kind == "wall"      ? 1
                           : o.kind == "rock"    ? 2
                           : o.kind == "lantern" ? 3
                                                 : 4;
    append(o.mesh, moss::Geology::kAsphalt, region);
  }
  return land;
}

moss::MossCosts GardenMossCosts() {
  // CPU time, native, 2026-12-07, at loads 6-8 (docs/garden-model.md "The moss's estimate"): the
  // scale garden (66,804 cells, 20.7 within 1 m) and the default (35,132 cells, 64 within 1 m).
  moss::MossCosts c;
  c.cell_build = 16e-6;   // the land, its cells and their indexes: 21 and 31 µs a cell
  c.cell_list = 0.25e-6;  // ... of which the spread lists, by the cells within 1 m (fitted)
  c.photon = 1.1e-6;      // a path, the canopy's spheres crossed: 1.07-1.24 µs measured
  c.photon_cell = 10e-9;  // the spread: 0.44 stored photons a path, about 22 ns a stored pair
  c.cell_day = 70e-9;     // the soil (45-66 ns) and the cell's share of the gather
  c.moss_day = 0.1e-6;    // a moss or seed at the caps: 0.16 µs all told on the default garden
  c.moss_photon = 10e-9;  // its gather, by the photons within 1 m
  return c;
}

std::vector<moss::CanopySphere> GardenCanopy(const std::vector<TreeAt>& trees, double scale) {
  std::vector<moss::CanopySphere> spheres;
  for (const TreeAt& t : trees) {
    const double opacity = t.run->state().params.Get(ParamId::kSphereOpacity);
    const double diameter_depth = -det::Log(1.0 - std::min(opacity, 0.999999));
    const double a = t.rot * det::kPi / 180.0;
    const double c = det::Cos(a), s = det::Sin(a);
    for (const LeafSphere& leaf : t.run->leaf_spheres()) {
      const glm::dvec3 p = glm::dvec3(leaf.center) / 100.0;  // cm to m
      const double r = static_cast<double>(leaf.radius) / 100.0;
      if (!(r > 0)) continue;
      spheres.push_back({{t.x + c * p.x + s * p.z, t.y + p.y, t.z - s * p.x + c * p.z},
                         r,
                         scale * diameter_depth / (2 * r)});
    }
  }
  return spheres;
}

std::vector<float> GardenMossGroundLight(const moss::MossRun& run, const GardenGround& ground) {
  const moss::SoilCells& cells = run.cells();
  const std::vector<double>& S = run.world().S;
  const int n = std::min(ground.n, kMossGroundCells);  // MossGround's cells a side
  const double cell = ground.size / n;
  const int side = n + 1;
  auto nearest = [&](double x, double step, int cells_a_side) {
    return std::clamp(static_cast<int>(std::floor((x + ground.size / 2) / step + 0.5)), 0,
                      cells_a_side);
  };
  std::vector<double> sum(static_cast<std::size_t>(side) * side, 0.0), area(sum.size(), 0.0);
  for (std::size_t i = 0; i < cells.size() && i < S.size(); ++i) {
    if (cells.region[i] != 0) continue;
    const glm::dvec3& c = cells.centroid[i];
    const std::size_t k =
        static_cast<std::size_t>(nearest(c.z, cell, n)) * side + nearest(c.x, cell, n);
    sum[k] += S[i] * cells.area[i];
    area[k] += cells.area[i];
  }
  // A vertex no centroid is nearest (the grid's (0, 0) and (n, n) corners: each cell's two
  // triangles bin to its other two corners) takes the cells of its eight neighbours.
  const std::vector<double> own_sum = sum, own_area = area;
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i) {
      const std::size_t k = static_cast<std::size_t>(j) * side + i;
      if (own_area[k] > 0) continue;
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
          const int ii = i + di, jj = j + dj;
          if (ii < 0 || jj < 0 || ii >= side || jj >= side) continue;
          sum[k] += own_sum[static_cast<std::size_t>(jj) * side + ii];
          area[k] += own_area[static_cast<std::size_t>(jj) * side + ii];
        }
    }
  const int fine = ground.n + 1;
  std::vector<float> out(static_cast<std::size_t>(fine) * fine, -1.0f);
  for (int j = 0; j < fine; ++j)
    for (int i = 0; i < fine; ++i) {
      const std::size_t k =
          static_cast<std::size_t>(nearest(-ground.size / 2 + j * ground.cell, cell, n)) * side +
          nearest(-ground.size / 2 + i * ground.cell, cell, n);
      if (area[k] > 0)
        out[static_cast<std::size_t>(j) * fine + i] = static_cast<float>(sum[k] / area[k]);
    }
  return out;
}

nlohmann::ordered_json GardenMossStats(const moss::MossRun& run, const moss::CanopyShade* canopy) {
  const moss::SoilCells& cells = run.cells();
  const moss::MossWorld& w = run.world();
  const std::size_t n = cells.size();
  std::vector<int> on_cell(n, 0);
  std::vector<long> by_region(cells.region_names.size(), 0);
  std::array<long, moss::kSpeciesCount> by_species{};
  for (const moss::MossPlant& m : w.mosses) {
    ++on_cell[m.cell];
    ++by_region[cells.region[m.cell]];
    ++by_species[static_cast<int>(m.species)];
  }
  // The ground's cells (region 0) in the crowns' shade (the path to the sun meets leaves) and in
  // the open.
  const moss::MossParams& params = run.state().params;
  const glm::dvec3 sun = glm::normalize(glm::dvec3(
      light::SunDirection(static_cast<float>(params.Get(moss::MossParam::kSunAltitude)),
                          static_cast<float>(params.Get(moss::MossParam::kSunAzimuth)))));
  struct Side {
    double area = 0, mosses = 0, S_area = 0;
    long cells = 0;
  };
  Side shade, open;
  for (std::size_t i = 0; i < n; ++i) {
    if (cells.region[i] != 0) continue;
    const bool under =
        canopy != nullptr && !canopy->empty() &&
        canopy->OpticalDepth(cells.centroid[i], sun, std::numeric_limits<double>::infinity()) > 0.0;
    Side& side = under ? shade : open;
    side.area += cells.area[i];
    side.mosses += on_cell[i];
    side.S_area += (i < w.S.size() ? w.S[i] : 0.0) * cells.area[i];
    ++side.cells;
  }
  auto side_json = [](const Side& s) {
    nlohmann::ordered_json j;
    j["cells"] = s.cells;
    j["area_m2"] = s.area;
    j["mosses"] = s.mosses;
    j["mosses_per_m2"] = s.area > 0 ? s.mosses / s.area : 0.0;
    j["mean_S"] = s.area > 0 ? s.S_area / s.area : 0.0;
    return j;
  };
  // The objects' faces by the way they face (up, down, or north, east, south, west: the
  // horizontal part of the normal; x east, z south), their area and the mosses on them.
  static const char* kFacings[] = {"up", "down", "north", "east", "south", "west"};
  auto facing_of = [](const glm::dvec3& normal) {
    if (normal.y > 0.7) return 0;
    if (normal.y < -0.7) return 1;
    if (std::abs(normal.z) >= std::abs(normal.x)) return normal.z < 0 ? 2 : 4;
    return normal.x > 0 ? 3 : 5;
  };
  std::array<double, 6> face_area{}, face_mosses{};
  for (std::size_t i = 0; i < n; ++i)
    if (cells.region[i] != 0) face_area[facing_of(cells.normal[i])] += cells.area[i];
  for (const moss::MossPlant& m : w.mosses)
    if (cells.region[m.cell] != 0 && !m.on_moss) face_mosses[facing_of(m.normal)] += 1;
  nlohmann::ordered_json faces;
  for (int f = 0; f < 6; ++f)
    faces[kFacings[f]] = {{"area_m2", face_area[f]},
                          {"mosses", face_mosses[f]},
                          {"mosses_per_m2", face_area[f] > 0 ? face_mosses[f] / face_area[f] : 0}};
  nlohmann::ordered_json j;
  j["days"] = w.day;
  j["cells"] = n;
  j["mosses"] = w.mosses.size();
  nlohmann::ordered_json species;
  for (int s = 0; s < moss::kSpeciesCount; ++s)
    species[moss::SpeciesName(static_cast<moss::Species>(s))] = by_species[s];
  j["by_species"] = species;
  nlohmann::ordered_json regions;
  for (std::size_t r = 0; r < by_region.size(); ++r) regions[cells.region_names[r]] = by_region[r];
  j["by_region"] = regions;
  j["ground_in_crown_shade"] = side_json(shade);
  j["ground_open"] = side_json(open);
  j["object_faces"] = faces;  // mosses resting on other mosses are left out
  j["canopy"] = {{"spheres", canopy != nullptr ? canopy->size() : 0},
                 {"photons_intercepted", w.canopy_intercepted},
                 {"photons_absorbed", w.canopy_absorbed}};
  return j;
}

}  // namespace niwa::compose
