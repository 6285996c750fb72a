// What a page draws of a garden run: each distinct tree's mesh (see garden_view.h).
#include "compose/garden_view.h"

namespace niwa::compose {

TreeMesh GardenGroupMesh(const GardenRun& run, int group) {
  MeshOptions options;
  options.max_sides = kGardenViewMaxSides;
  return BuildTreeMesh(run.groups()[group].tree(), options);
}

}  // namespace niwa::compose
