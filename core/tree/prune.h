// Prunes of the tree study: cut a branch (or a year's growth) after a year, as text "12:b42" or
// "10:since7", and why a prune cut nothing. Does not: apply prunes (tree/growth does).
#pragma once

#include <string>
#include <string_view>

#include "base/status.h"
#include "tree/tree.h"

namespace niwa {

// Remove a branch and everything above it after the growth of `year` (thesis figs. 2.15, 2.18).
struct Prune {
  int year = 0;
  int branch = -1;      // a branch id from the JSON output, or -1
  int since_year = -1;  // or: every shoot grown in this year or later, or -1
};

// "12:b42" (branch 42 after year 12; "12:42" too) or "10:since7" (all growth since year 7, after
// year 10), years in [1, kMaxYears]. The error is {"prune", "'x' must be YEAR:bID or ..."}.
Result<Prune> ParsePrune(std::string_view text);
std::string FormatPrune(const Prune& prune);

// Ok when `prune` cuts something from `grown`, the tree its request grew; else the Status
// {FormatPrune(prune), why}: its year is after the last year grown, its branch id is not among the
// branches the tree had by that year (shoots take ids in the order they grow), or its "since" year
// is after its own year. For the CLI's error and the page's notice.
Status IdlePruneReason(const Prune& prune, const Tree& grown);

}  // namespace niwa
