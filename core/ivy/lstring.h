// The L-string of a grown ivy (Table 1): printed from the bud tree (a view, never the store), and
// re-interpreted by a turtle (A/D/Z move to the bud's coordinate, I draws from the previous bud to
// the next, [ ] push and pop, R() rotates the following symbol) to check it against the stored
// internodes. Does not: rewrite anything (growth.h does) or parse symbols other than Table 1's.
#pragma once

#include <glm/vec3.hpp>
#include <string>
#include <utility>
#include <vector>

#include "base/status.h"
#include "ivy/ivy.h"

namespace niwa::ivy {

// One line per plant: e.g. "A(0,10,10;0.2)" at step 0, "Z(..;0)[R(0,0,45)IA(..;0.005)]ID(..)IA(..)"
// later. Coordinates and nutrients are printed with 17 significant digits (exact round trip).
std::string PrintLString(const IvyModel& model);

// The internodes a turtle draws from an L-string, as (from, to) positions in drawing order.
Result<std::vector<std::pair<glm::dvec3, glm::dvec3>>> InterpretLString(const std::string& text);

// Symbol counts of an L-string.
struct LStringCounts {
  int A = 0, D = 0, Z = 0, I = 0, open = 0, close = 0, R = 0;
};
LStringCounts CountSymbols(const std::string& text);

// True when the turtle's internodes equal the model's (as sets of exact position pairs).
bool LStringMatchesModel(const IvyModel& model);

}  // namespace niwa::ivy
