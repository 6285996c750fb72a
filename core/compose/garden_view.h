// What a page draws of a garden run (issue 33 item 6; web/bindings/garden_bindings.cpp), from
// GardenRun's public API: each distinct tree's full mesh (the tree study's BuildTreeMesh) at the
// page's detail, in metres at the origin, for the page to place at every copy; the same of any
// year the run recorded (GardenRun::Start's record_years), for the year scrubber; with the garden's
// bark 1, each distinct tree's simulated bark (compose/garden_bark: the maps its .glb wears) and
// its page mesh's bark UVs wrapping that tile. Does not: place
// trees (the page does, from the planting), build the .glb's LOD (garden_run.cpp Document), or
// draw anything.
#pragma once

#include "base/status.h"
#include "compose/garden_run.h"
#include "image/image.h"
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

// The simulated bark group `group` wears (the old frame of GrowGardenBarks: the maps the .glb's
// tree carries), or null when it wears the procedural bark (bark 0, or a tree that kept it).
const BarkFrame* GardenGroupBark(const GardenRun& run, int group);

// The pixels of group `group`'s simulated bark map (`normal`: the normal map, else the base colour;
// row 0 = v 0), decoded from the PNG the .glb carries (the run keeps no pixels: GrowGardenBarks);
// an error naming "bark" when the group wears the procedural bark.
Result<image::Rgba8Image> GardenGroupBarkImage(const GardenRun& run, int group, bool normal);

// The bark UVs (u, v per bark vertex) of `mesh`, a GardenGroupMesh(At) of group `group` as it
// stood after garden year `year`, wrapping the group's simulated bark tile around every tube
// (WrapBarkUvs, as the .glb's levels: WrapGardenBarkUvs); empty when the group's bark is
// procedural or the year is not drawn. A recorded year wears the last year's maps (the bark is
// run once, after the clock).
std::vector<float> GardenGroupBarkUvs(const GardenRun& run, int group, int year,
                                      const TreeMesh& mesh);

// True when year `year`'s picture can be drawn without regrowing (recorded, or the last grown).
bool GardenYearShown(const GardenRun& run, int year);

}  // namespace niwa::compose
