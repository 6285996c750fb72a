// The page's budget (docs/budgets.md), the same for every study's binding: what a laptop tab's
// WASM heap holds, by estimate (1 GB), and 60 estimated seconds for one job.
// Does not: measure anything (the studies' estimates are checked against it).
#pragma once

#include <cstdint>

#include "base/budget.h"

namespace niwa {

inline Budget PageBudget() {
  Budget budget;
  budget.memory_bytes = uint64_t{1} << 30;
  budget.seconds = 60;
  budget.memory_limit = "page memory budget";
  budget.seconds_limit = "page time budget";
  return budget;
}

}  // namespace niwa
