// What a page draws of a garden run: each distinct tree's mesh (see garden_view.h).
#include "compose/garden_view.h"

#include "image/png.h"

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

const BarkFrame* GardenGroupBark(const GardenRun& run, int group) {
  const GardenBarks& barks = run.barks();
  if (!barks.on || group < 0 || static_cast<std::size_t>(group) >= barks.trees.size())
    return nullptr;
  return barks.trees[group].frame.get();
}

Result<image::Rgba8Image> GardenGroupBarkImage(const GardenRun& run, int group, bool normal) {
  const BarkFrame* frame = GardenGroupBark(run, group);
  if (frame == nullptr) return Status::Error("bark", "this tree wears the procedural bark");
  const std::string& png = normal ? frame->normal : frame->base_colour;
  Result<image::Rgba8Image> pixels =
      image::DecodeRgba8Png(reinterpret_cast<const unsigned char*>(png.data()), png.size());
  if (!pixels.ok()) return Status::Error("bark", pixels.status().Line());
  return pixels;
}

std::vector<float> GardenGroupBarkUvs(const GardenRun& run, int group, int year,
                                      const TreeMesh& mesh) {
  const BarkFrame* frame = GardenGroupBark(run, group);
  const Tree* tree = run.TreeAtYear(group, year);
  if (frame == nullptr || tree == nullptr) return {};
  return WrapBarkUvs(*tree, mesh, *frame);
}

bool GardenYearShown(const GardenRun& run, int year) {
  if (year == run.done()) return true;
  for (const GardenYearRecord& r : run.years())
    if (r.year == year) return true;
  return false;
}

}  // namespace niwa::compose
