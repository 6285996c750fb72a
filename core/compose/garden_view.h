// What a page draws of a garden run (issue 33 item 6; web/bindings/garden_bindings.cpp), from
// GardenRun's public API: each distinct tree's full mesh (the tree study's BuildTreeMesh) at the
// page's detail, in metres at the origin, for the page to place at every copy; the same of any
// year the run recorded (GardenRun::Start's record_years), for the year scrubber. Does not: place
// trees (the page does, from the planting), build the .glb's LOD (garden_run.cpp Document), or
// draw anything.
#pragma once

#include "compose/garden_run.h"
#include "tree/mesh.h"

namespace niwa::compose {

// Sides of the thickest bark tube in a page's garden: coarser than the tree page's 12 (many trees).
constexpr int kGardenViewMaxSides = 6;

// The full mesh of group `group` of `run` (bark tubes of 3 to kGardenViewMaxSides sides, leaves,
// flowers; the tree's own look), its trunk's foot at the origin.
TreeMesh GardenGroupMesh(const GardenRun& run, int group);

// The same mesh of group `group` as it stood after garden year `year` (GardenRun::TreeAtYear: a
// recorded year, or the last grown); an empty mesh when that year was not recorded.
TreeMesh GardenGroupMeshAt(const GardenRun& run, int group, int year);

// True when year `year`'s picture can be drawn without regrowing (recorded, or the last grown).
bool GardenYearShown(const GardenRun& run, int year);

}  // namespace niwa::compose
