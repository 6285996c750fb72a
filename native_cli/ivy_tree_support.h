// `niwa ivy grow --tree-preset NAME --tree-years N`: a Niwa tree (core/tree) as an ivy support, so
// ivy climbs its trunk and branches. The CLI is where the two studies meet: core/ivy never includes
// core/tree; it gets the bark (core/tree/bark_support, which the ivy page's bindings also call) as
// a plain geom::TriMesh in metres. Header-only (used by ivy_commands.cpp alone). Does not: add
// leaves or flowers to the support (ivy climbs bark only).
#pragma once

#include <string>

#include "base/status.h"
#include "ivy/scenes.h"
#include "tree/bark_support.h"

namespace niwa::cli {

// Grows tree preset `name` for `years` years within `budget` (the limits of `niwa tree grow`,
// shared with the ivy's own; the errors name --tree-preset, --tree-years or the limit) and
// returns it as a scene whose one named seed, "trunk", is the +z side of the trunk foot;
// *estimate gets the tree's and its bark's, *truncated_by the tree's stop line ("" if none).
inline Result<ivy::IvyScene> TreeSupportScene(const std::string& name, double years,
                                              const Budget& budget, Estimate* estimate,
                                              std::string* truncated_by) {
  BarkBudget bark_budget;
  bark_budget.budget = budget;
  Result<BarkSupport> bark = GrowBarkSupport(name, years, &bark_budget);
  if (!bark.ok()) {
    const std::string& field = bark.status().field();
    if (field == budget.memory_limit || field == budget.seconds_limit) return bark.status();
    return Status::Error(field == "tree" ? "--tree-preset" : "--tree-years",
                         bark.status().message());
  }
  *estimate = bark->estimate;
  *truncated_by = bark->truncated_by;
  ivy::IvyScene scene;
  scene.name = "tree:" + name;
  scene.description = bark->description;
  scene.mesh = std::move(bark->mesh);
  scene.seeds.push_back({"trunk", bark->trunk_seed});
  return scene;
}

}  // namespace niwa::cli
