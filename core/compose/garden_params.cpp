// The garden's parameter table (see garden_params.h).
#include "compose/garden_params.h"

namespace niwa::compose {
namespace {

using GP = GardenParam;
constexpr int GardenId(GP p) { return static_cast<int>(p); }
constexpr Stage kGardenGrow = Stage::kGrow;
constexpr Stage kGardenMesh = Stage::kMesh;

std::vector<ParamSpec> GardenRows() {
  return {
      // ------------------------------------------------ ground
      {GardenId(GP::kSize), "size", "L", "m", 40, 4, 1000, false, "ground", kGardenGrow,
       "Side of the square garden, centred on the origin (x east, z south, y up)."},
      {GardenId(GP::kRelief), "relief", "Δh", "m", 6, 0, 500, false, "ground", kGardenGrow,
       "Height from the ground's lowest to its highest point: a terrain's heights (or a "
       "heightmap's 0..65535) are scaled to it. 0 gives a flat ground."},
      {GardenId(GP::kGroundRes), "ground_res", "", "cells", 128, 8, 1024, true, "ground",
       kGardenGrow,
       "Cells of the ground's grid along a side; every placed thing stands on its triangles."},
      // ------------------------------------------------ clock
      {GardenId(GP::kYears), "years", "", "years", 10, 0, 60, true, "clock", kGardenGrow,
       "The garden's age: every plant grows this many years on top of the age it was planted "
       "at."},
      // ------------------------------------------------ planting rules
      {GardenId(GP::kDensity), "density", "ρ_p", "1/m²", 0.01, 0, 1, false, "planting", kGardenGrow,
       "Trees per square metre the planting rules aim for over the whole garden (0: only the "
       "hand-placed plants). The spacing, altitude, slope, mask and objects refuse some."},
      {GardenId(GP::kSpacing), "spacing", "d_min", "m", 5, 0.1, 100, false, "planting", kGardenGrow,
       "Poisson minimum spacing: no two trees' trunks closer than this (hand-placed ones "
       "included)."},
      {GardenId(GP::kAltMin), "alt_min", "", "m", 0, 0, 500, false, "planting", kGardenGrow,
       "Lowest altitude a rule plants at, metres above the ground's lowest point."},
      {GardenId(GP::kAltMax), "alt_max", "", "m", 500, 0, 500, false, "planting", kGardenGrow,
       "Highest altitude a rule plants at, metres above the ground's lowest point."},
      {GardenId(GP::kSlopeMax), "slope_max", "", "°", 30, 0, 90, false, "planting", kGardenGrow,
       "Steepest ground a rule plants on (the ground triangle's slope under the trunk)."},
      {GardenId(GP::kPlantSeed), "plant_seed", "", "", 1, 0, 4294967295.0, true, "planting",
       kGardenGrow, "Seed of the planting rules' candidates, species draws and variants."},
      {GardenId(GP::kVariants), "variants", "", "", 3, 1, 64, true, "planting", kGardenGrow,
       "Distinct trees per species among the rule-planted ones (tree seeds 1..variants): "
       "trees of one variant are one mesh, instanced, unless they shade a neighbour."},
      // ------------------------------------------------ interactions
      {GardenId(GP::kShade), "shade", "", "", 1, 0, 1, true, "interactions", kGardenGrow,
       "1: trees closer than shade_reach grow together year by year, each shaded by the others' "
       "leaves in the thesis's light model (2.3.2); 0: every tree grows alone."},
      {GardenId(GP::kShadeReach), "shade_reach", "", "m", 10, 0.5, 100, false, "interactions",
       kGardenGrow, "Trunks closer than this shade each other (when shade is 1)."},
      {GardenId(GP::kIvySteps), "ivy_steps", "", "steps/year", 60, 0, 160, true, "interactions",
       kGardenGrow,
       "Ivy steps (paper 004's unit) a garden year: the ivy of the state's seeds grows years × "
       "ivy_steps steps on the objects, the trunks near them and the ground (0: no ivy)."},
      {GardenId(GP::kMossDays), "moss_days", "", "days/year", 10, 0, 60, true, "interactions",
       kGardenGrow,
       "Moss days (paper 001's unit) a garden year: after each year of the trees, the moss grows "
       "moss_days days over the ground and the objects, under that year's leaves (0: no moss)."},
      {GardenId(GP::kMossShade), "moss_shade", "", "", 1, 0, 1, true, "interactions", kGardenGrow,
       "1: the moss's photons cross the trees' leaves (Beer–Lambert through the leaf spheres of "
       "the thesis's light model), so the moss grows in the canopies' shade; 0: no leaves in its "
       "light."},
      {GardenId(GP::kMossCanopy), "moss_canopy", "", "×", 1, 0.1, 20, false, "interactions",
       kGardenGrow,
       "Scales the leaves' extinction in the moss's light (1: the tree's own sphere_opacity, "
       "the thesis's light model, whose crowns let about 60 % of the sun through; real crowns of "
       "leaf area index 3 to 5 let 5 to 20 % through)."},
      // ------------------------------------------------ export
      {GardenId(GP::kMaxTriangles), "max_triangles", "", "", 8000, 100, 1000000, true, "export",
       kGardenMesh,
       "Triangles of each distinct tree in the .glb (render/tree_lod: tubes, branch cards, twig "
       "cones, leaf-cluster cards)."},
      {GardenId(GP::kLod), "lod", "", "", 0, 0, 1, true, "export", kGardenMesh,
       "1: each distinct tree also as _LOD1 and _LOD2 (25 % and 5 % of its triangles)."},
      {GardenId(GP::kInstancing), "instancing", "", "", 1, 0, 1, true, "export", kGardenMesh,
       "1: a distinct tree's copies as one node with EXT_mesh_gpu_instancing; 0: one plain node "
       "a copy, sharing the mesh (for loaders without the extension)."},
      {GardenId(GP::kShapes), "shapes", "", "meshes/variant", 8, 0, 64, true, "export", kGardenMesh,
       "Trees grown with their neighbours' shade differ a little, so each is its own mesh: with "
       "N, the .glb keeps at most N meshes a species variant and draws each such tree as the "
       "nearest of them (height, crown reach, lean), turned to lean its own way and scaled to "
       "its height (within 25 %); 0: every such tree its own mesh."},
      // ------------------------------------------------ bark
      {GardenId(GP::kBark), "bark", "", "", 0, 0, 1, true, "bark", kGardenGrow,
       "0: every tree wears the tree study's procedural bark texture; 1: each distinct tree's "
       "bark is the bark study (paper 003, 2-layer) run on its own trunk's radius history, the "
       "bark species from its tree species (pine: pine; cherries, keyaki, azalea: tallow; the "
       "rest: camphor)."},
      {GardenId(GP::kBarkMapSize), "bark_map_size", "", "px", 256, 256, 4096, true, "bark",
       kGardenGrow,
       "Longer side of each simulated bark's maps (a power of two; a thin trunk's tall tile "
       "gets a narrower map): small, since the garden is seen from afar."},
  };
}

}  // namespace

const ParamTable& GardenTable() {
  static const ParamTable table("garden", GardenRows(),
                                {{"ground", "Ground"},
                                 {"clock", "Clock"},
                                 {"planting", "Planting rules"},
                                 {"interactions", "Interactions"},
                                 {"export", "Export"},
                                 {"bark", "Bark"}});
  return table;
}

const ParamTable& TableOf(GardenParam) { return GardenTable(); }

}  // namespace niwa::compose
