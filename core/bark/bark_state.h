// The bark study's state: the species preset, the model, the RNG seed and the table's values over
// the preset, from a state JSON (--params FILE, the page) or a share-link hash (keys with an
// optional prefix, "bark." on a composed page), and written back to both. Does not: run the model
// (bark_run.h), read files or know a front end (errors name state fields: "species", "model",
// "seed", a row key).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "bark/bark_params.h"
#include "base/status.h"

namespace niwa::bark {

constexpr double kMaxBarkSeed = 4294967295.0;

struct BarkState {
  std::string species = "camphor";
  std::string model = "2layer";  // or "4layer"
  uint64_t seed = 1;
  BarkParams params = *BarkPreset("camphor");
};

// Resets the values to the preset's (BarkPreset); the error names "species".
Status SetBarkSpecies(std::string_view name, BarkState* state);
// "2layer" or "4layer"; the error names "model".
Status SetBarkModel(std::string_view name, BarkState* state);
// A whole number in [0, 4294967295]; the error names "seed".
Status SetBarkSeed(double seed, BarkState* state);
// Sets N_R and N_H ("128x64"); errors name "N_R" or "N_H".
Status SetBarkSize(std::string_view text, BarkState* state);

// Cross-row checks of a whole state (CheckBarkParams); the error names the row.
Status CheckBarkState(const BarkState& state);

// Applies {species, model, seed, params: {key: value}} (or the rows at the top level) onto state;
// a "species" resets the rows first, then the rest goes on top. Strict: the first bad field is
// the error and the state is unchanged.
Status ApplyBarkStateJson(const std::string& text, BarkState* state);
// What ApplyBarkStateJson reads back to the same state (every row).
std::string BarkStateJson(const BarkState& state);

// Applies "species=pine&seed=3&N_R=64" (keys prefixed with `prefix`). Forgiving: bad values are
// clamped or dropped with one printable notice each; keys of other studies are skipped when
// `prefix` is non-empty.
void ApplyBarkHash(std::string_view hash, std::string_view prefix, BarkState* state,
                   std::vector<std::string>* notices);
// "species=NAME&model=2layer&seed=N" and every row that differs from the species' preset.
std::string EncodeBarkHash(const BarkState& state, std::string_view prefix = "");

}  // namespace niwa::bark
