// Moss over the garden (issue 33 items 1-3; docs/garden-model.md "Moss"): the moss study's land
// made of the garden's ground and objects, the trees' leaves of the year as the canopy its photons
// cross (moss/canopy.h), the garden's defaults for the moss's state, and the stats that say where
// the moss grew (under the crowns or in the open, on which object). Part of the composition tier:
// the moss study knows nothing of trees or gardens, the tree study nothing of moss. Does not: grow
// the moss (moss/moss_run does, driven year by year by compose/garden_run), mesh it, or name a
// flag (errors name state fields).
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <vector>

#include "compose/garden_scene.h"
#include "compose/tree_neighbours.h"
#include "moss/canopy.h"
#include "moss/moss_run.h"
#include "moss/moss_state.h"
#include "moss/scenes.h"

namespace niwa::compose {

// The most cells a side of the moss's ground: a finer garden ground (ground_res 512 on a 100 m
// garden: 525 k triangles, about 176 s of moss for 15 years at the moss study's provisional costs)
// is resampled to this for the moss.
constexpr int kMossGroundCells = 128;

// What the garden's moss counts its work at (moss::MossRun::RunEstimate; docs/garden-model.md
// "The moss's estimate"): measured in CPU time on the default and the scale gardens, where the
// study's provisional figures counted a cell's day at 2 µs (about 70 ns measured) and the caps'
// mosses at 4 µs a day; with the gather's disc over the land (r_gather 1 m) counted per cell and
// per photon in it.
moss::MossCosts GardenMossCosts();

// The ground the moss grows on: `ground` itself at kMossGroundCells cells a side or fewer, else a
// grid of kMossGroundCells cells over the same square whose vertices take the ground's height
// there (GardenGround::HeightAt); its relief and source are the ground's.
GardenGround MossGround(const GardenGround& ground);

// The land: the moss's ground's triangles (MossGround; humus, region "ground") and every object's
// (stone and plaster are hard, impervious surfaces: geology asphalt, the thesis's; region its kind:
// "wall", "rock", "lantern"), in the garden's frame.
moss::MossScene GardenMossLand(const GardenScene& scene);

// The trees' leaves as the moss's canopy: every tree's leaf spheres of its last started year
// (TreeRun::leaf_spheres, cm in its frame) turned and moved into the garden's frame (m), with the
// extinction that keeps 1 − opacity through a sphere's diameter (the tree's sphere_opacity row,
// thesis 2.3.2), times `scale` (the garden's moss_canopy).
std::vector<moss::CanopySphere> GardenCanopy(const std::vector<TreeAt>& trees, double scale = 1);

// Where the moss grew: for the ground's cells in the crowns' shade (the path from the cell's
// centre towards the moss's sun meets leaves: optical depth > 0) and in the open, their area,
// the mosses on them, per m², and their mean light S of the last day; the mosses per region
// (ground, wall, rock, lantern) and per species; the objects' faces by facing (up, down, north,
// east, south, west: area, mosses on them, per m²); the canopy's photons. `canopy` is the shade
// the last days were grown under (none: every ground cell is open).
// The moss's light S of the last day (W/m², light_smoothing_days' mean) on the ground, per vertex
// of its grid in GardenGround's order (vertex (i, j) at x = −L/2 + i·cell, z = −L/2 + j·cell):
// the area-weighted mean over the moss's ground cells whose centroid lies nearest that vertex of
// the moss's ground (MossGround), or, where none is (the grid's two corners), over those nearest
// its eight neighbours; read at the moss's ground vertex nearest each vertex of `ground`; −1 only
// where no ground cell is near (a garden without a moss ground). For a page's overlay.
std::vector<float> GardenMossGroundLight(const moss::MossRun& run, const GardenGround& ground);

nlohmann::ordered_json GardenMossStats(const moss::MossRun& run, const moss::CanopyShade* canopy);

}  // namespace niwa::compose
