// The share-URL hash codec: preset, seed, years, changed parameters and prunes as "k=v&k=v".
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "params/param_table.h"
#include "tree/growth.h"

namespace niwa {

struct TreeState {
  std::string preset = "sakura";
  uint64_t seed = 1;
  int years = 15;
  ParamSet params;  // full values (preset values plus overrides)
  std::vector<Prune> prunes;
  std::string camera;  // opaque "yaw,pitch,distance,tx,ty,tz" kept for the page
};

constexpr int kMaxYears = 100;

// Encodes only the parameters that differ from the preset's values.
std::string EncodeStateHash(const TreeState& state);

// Decodes a hash (with or without the leading '#'). Unknown keys, bad or out-of-range values are
// dropped or clamped and described in notices (one line each); the result is always usable.
TreeState DecodeStateHash(const std::string& hash, std::vector<std::string>* notices);

// "12:b42" (branch 42 after year 12) or "10:since7" (all growth since year 7, after year 10).
bool ParsePrune(const std::string& text, Prune* prune, std::string* error);
std::string FormatPrune(const Prune& prune);

}  // namespace niwa
