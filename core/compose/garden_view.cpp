// What a page draws of a garden run: each distinct tree's mesh (see garden_view.h).
#include "compose/garden_view.h"

namespace niwa::compose {

namespace {

TreeMesh PageMesh(const Tree& tree) {
  MeshOptions options;
  options.max_sides = kGardenViewMaxSides;
  return BuildTreeMesh(tree, options);
}

}  // namespace

TreeMesh GardenGroupMesh(const GardenRun& run, int group) {
  return PageMesh(run.groups()[group].tree());
}

TreeMesh GardenGroupMeshAt(const GardenRun& run, int group, int year) {
  const Tree* tree = run.TreeAtYear(group, year);
  return tree != nullptr ? PageMesh(*tree) : TreeMesh{};
}

bool GardenYearShown(const GardenRun& run, int year) {
  if (year == run.done()) return true;
  for (const GardenYearRecord& r : run.years())
    if (r.year == year) return true;
  return false;
}

}  // namespace niwa::compose
