// Test helper: grow one of the embedded presets for a number of years (one call instead of a
// GrowRequest built by hand in every test file).
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <string>

#include "tree/growth.h"
#include "tree/presets.h"
#include "tree/tree_state.h"

namespace niwa::testing {

// The preset's parameters; its own seed unless `seed` is given.
inline Tree GrowPreset(const std::string& preset, int years,
                       std::optional<uint64_t> seed = std::nullopt) {
  GrowRequest r;
  r.preset = preset;
  r.params = FindPreset(preset)->params;
  r.years = years;
  r.seed = seed ? *seed : FindPreset(preset)->seed;
  return GrowTree(r);
}

// A tree state of `preset` at `years` (its defaults otherwise), for tests that set limits on it.
inline TreeState PresetState(const std::string& preset, int years) {
  TreeState state;
  EXPECT_TRUE(SetStatePreset(preset, &state).ok());
  EXPECT_TRUE(SetStateYears(years, &state).ok());
  return state;
}

}  // namespace niwa::testing
