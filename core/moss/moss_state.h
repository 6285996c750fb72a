// The moss study's state as far as the soil and fitness commands need it: a preset and the table's
// values over it, read from a share-link hash (keys with an optional prefix, "moss." on a composed
// page) and written back to one; the run's days, seed and built-in scene (the photon count and
// the indirect switch are table rows: `photons`, `indirect`). Does not: read files or know a front
// end (errors name state fields: "preset", "days", "seed", "scene", a row key).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "base/status.h"
#include "moss/moss_params.h"

namespace niwa::moss {

struct MossState {
  std::string preset = "nomura2010";
  MossParams params;
  int days = 300;                // the thesis's 300 days (§4.1)
  uint64_t seed = 1;             // the run's RNG streams (photons, growth, rain, placement)
  std::string scene = "thesis";  // a built-in scene (scenes.h)
};

constexpr int kMaxMossDays = 3650;
constexpr uint64_t kMaxMossSeed = 4294967295u;

// Each checks its range; the error names the field ("days" 0..3650, "seed" 0..4294967295 whole,
// "scene" one of scenes.h's names).
Status SetMossDays(double days, MossState* state);
Status SetMossSeed(double seed, MossState* state);
Status SetMossScene(std::string_view scene, MossState* state);

// Resets the values to the preset's (moss_params.h MossPreset); the error names "preset".
Status SetMossPreset(std::string_view name, MossState* state);

// Applies a share-link hash: the preset first, then every row key (clamped into its range, or
// dropped, with a notice); an unknown key, a repeated key or an over-long hash gives a notice
// (io/hash_codec.h: a repeated key or a hash over 16,384 characters is refused whole).
void ApplyMossHash(std::string_view hash, std::string_view prefix, MossState* state,
                   std::vector<std::string>* notices);

// A state file {preset, scene, days, seed, params: {key: value}} (any subset): the preset first,
// then the others; a key outside these, a repeated key or a wrong type is an error naming it
// (nothing applied). MossStateJson writes every field and every row, read back to the same state.
Status ApplyMossStateJson(const std::string& text, MossState* state);
std::string MossStateJson(const MossState& state);

// "preset=NAME", then scene, days and seed where they differ from the defaults (thesis, 300, 1),
// then every row that differs from the preset, keys prefixed.
std::string EncodeMossHash(const MossState& state, std::string_view prefix = "");

}  // namespace niwa::moss
