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

// Grows tree preset `name` for `years` years (the errors name --tree-preset and --tree-years) and
// returns it as a scene whose one named seed, "trunk", is the +z side of the trunk foot.
inline Result<ivy::IvyScene> TreeSupportScene(const std::string& name, double years) {
  Result<BarkSupport> bark = GrowBarkSupport(name, years);
  if (!bark.ok()) {
    return Status::Error(bark.status().field() == "tree" ? "--tree-preset" : "--tree-years",
                         bark.status().message());
  }
  ivy::IvyScene scene;
  scene.name = "tree:" + name;
  scene.description = bark->description;
  scene.mesh = std::move(bark->mesh);
  scene.seeds.push_back({"trunk", bark->trunk_seed});
  return scene;
}

}  // namespace niwa::cli
