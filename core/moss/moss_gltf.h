// The moss study's glTF output (Nomura 2010 §3.8, fig 3.7; spec §6 "glTF export"): the land with a
// per-vertex map (COLOR_0 on a colour ramp, the raw value as an application attribute) and the moss
// tufts (fig 3.7's sugigoke-like tuft, 21 triangles, coloured by species), merged into one
// primitive or drawn with EXT_mesh_gpu_instancing, per-moss species and birth day as node extras.
// Does not: run the model (the run gives each cell's value and each tuft's place), jitter tufts by
// 1/f noise (thesis §3.8's display noise is not built: a tuft stands at its moss's centre), write
// bytes (io/gltf_writer) or read files.
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "base/budget.h"
#include "base/status.h"
#include "geom/tri_mesh.h"
#include "io/gltf_writer.h"
#include "moss/moss.h"
#include "moss/soil_cells.h"

namespace niwa::moss {

// What the land's vertex colours show (--map): the coverage of each cell by mosses growing on it
// (min(1, n·s²/A), as the stats' coverage), the last day's S, T_s, rh_s, θ, or the best of the
// three species' fitness G (eq 3.17) at the cell.
enum class MossMap : int { kCoverage = 0, kS, kT_s, kRh_s, kTheta, kFitness };
constexpr int kMossMapCount = 6;
const char* MossMapName(MossMap map);  // "coverage", "S", "T_s", "rh_s", "theta", "fitness"
// The map named `name`; the error names "map" and the allowed names.
Status MossMapFromName(std::string_view name, MossMap* map);

// Where a map's colour ramp starts and ends (a value outside is clamped): coverage and fitness
// [0, 1], S [0, 120] W/m² (the stats' top irradiance band), T_s [263.15, 303.15] K, rh_s [0, 1],
// theta [0, 1] as θ / θ_SAT of the cell's geology.
struct MapRamp {
  double lo, hi;
  const char* of;  // what is ramped: "value" or "theta/theta_SAT"
};
MapRamp MossMapRamp(MossMap map);

// The linear RGB of the ramp (viridis, five stops) at t, clamped to [0, 1].
std::array<float, 3> RampColour(double t);
// The linear RGB of a species' tufts: gingoke silver-green, haigoke yellow-green, sugigoke dark
// green.
std::array<float, 3> SpeciesColour(Species species);

// Fig 3.7's tuft at unit height, base at the origin, growing along +y: a three-sided stem, a crown
// and two whorls of three leaves; positions, normals and indices only.
geom::TriMesh TuftMesh();
constexpr int kTuftTriangles = 21;
constexpr int kTuftVertices = 31;

// One tuft: base at `pos`, up along `normal` (unit), turned `angle` radians about it, `size` m
// tall (the moss's s scaled by its growth, moss_run.h).
struct TuftPlace {
  glm::dvec3 pos{0}, normal{0, 1, 0};
  double size = 0.01;
  double angle = 0;
  Species species = Species::kGingoke;
  int birth_day = 0;
};

// The land of `cells` with per-vertex normals, COLOR_0 (RampColour of ramp[i]) and the raw value of
// the map as the attribute named after it ("coverage" -> _COVERAGE); cell i is vertices 3i..3i+2.
geom::TriMesh LandMapMesh(const SoilCells& cells, MossMap map, const std::vector<double>& value,
                          const std::vector<double>& ramp);
// Every tuft in one mesh: positions, normals, COLOR_0 by species.
geom::TriMesh MergedTufts(const std::vector<TuftPlace>& tufts);

// The document: node "land" (the land, extras: map, attribute, ramp, day), node "tufts" (merged:
// one primitive, extras {species_names, species: [index per moss], birth_day: [...]}; instancing:
// no mesh, a child node per species present, "tufts_<species>", drawing the species' tuft mesh
// once per moss through EXT_mesh_gpu_instancing, extras {species, birth_day}); no tufts node
// without mosses.
gltf::Document MossDocument(geom::TriMesh land, MossMap map, int day,
                            const std::vector<TuftPlace>& tufts, bool instancing);

// What writing the .glb of `cells` cells and `mosses` tufts needs (upper bounds).
Estimate MossGlbEstimate(std::size_t cells, std::size_t mosses);

}  // namespace niwa::moss
