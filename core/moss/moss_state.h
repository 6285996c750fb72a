// The moss study's state as far as the soil and fitness commands need it: a preset and the table's
// values over it, read from a share-link hash (keys with an optional prefix, "moss." on a composed
// page) and written back to one. Does not: hold a run's days, seed or scene yet (the moss run,
// issue 29's next slice, adds them here), read files or know a front end (errors name state
// fields: "preset", a row key).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "base/status.h"
#include "moss/moss_params.h"

namespace niwa::moss {

struct MossState {
  std::string preset = "nomura2010";
  MossParams params;
};

// Resets the values to the preset's (moss_params.h MossPreset); the error names "preset".
Status SetMossPreset(std::string_view name, MossState* state);

// Applies a share-link hash: the preset first, then every row key (clamped into its range, or
// dropped, with a notice); an unknown key, a repeated key or an over-long hash gives a notice
// (io/hash_codec.h: a repeated key or a hash over 16,384 characters is refused whole).
void ApplyMossHash(std::string_view hash, std::string_view prefix, MossState* state,
                   std::vector<std::string>* notices);

// "preset=NAME" and every row that differs from the preset, keys prefixed.
std::string EncodeMossHash(const MossState& state, std::string_view prefix = "");

}  // namespace niwa::moss
