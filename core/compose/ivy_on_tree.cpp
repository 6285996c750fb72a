// Ivy on a grown Niwa tree (see ivy_on_tree.h).
#include "compose/ivy_on_tree.h"

#include <utility>

#include "compose/bark_support.h"

namespace niwa::compose {

Result<ivy::IvySupportInput> IvyTreeSupport(const std::string& preset, double years,
                                            const Budget& budget, const std::string& years_name,
                                            const BarkProgress& on_stage) {
  BarkBudget bark_budget;
  bark_budget.budget = budget;
  bark_budget.years_name = years_name;
  Result<BarkSupport> bark = GrowBarkSupport(preset, years, &bark_budget, on_stage);
  if (!bark.ok()) return bark.status();
  ivy::IvyScene scene;
  scene.name = "tree:" + preset;
  scene.description = bark->description;
  scene.mesh = std::move(bark->mesh);
  scene.seeds.push_back({"trunk", bark->trunk_seed});
  scene.px_per_unit = 1000;  // the tree is in metres (the ivy's px are mm)
  return ivy::IvySupportInput::Prepared(std::move(scene), std::move(bark->estimate),
                                        std::move(bark->truncated_by));
}

}  // namespace niwa::compose
