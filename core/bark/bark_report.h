// The bark run's statistics as one JSON object (`niwa bark grow --stats`, the page's panel): nodes,
// springs per family, steps, dt, the growth, broken counts and fractions per family, the
// vertical-crack share, regions (count, strips, mean and max width and height, closed fraction),
// intercepts, seed and hash. Does not: time anything (the front end adds ms and
// ns_per_spring_step) or run the model.
#pragma once

#include <string>

namespace niwa::bark {

class BarkRun;

std::string BarkStatsJson(const BarkRun& run);

}  // namespace niwa::bark
