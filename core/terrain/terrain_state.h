// The one resolver of a terrain run's state (figure preset, seed contour, RNG seed, parameters)
// from a state JSON (the page, --params FILE) or a share-link hash (the page, --url), bare keys on
// the terrain page and the "terrain." prefix on a composed page. Does not: check the seed's
// geometry (generate.h CheckSeed), grow (generate.h) or parse parameter JSON itself
// (params/param_json).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "base/status.h"
#include "terrain/contour.h"
#include "terrain/terrain_params.h"

namespace niwa::terrain {

// Most seed points a hash or state JSON carries (a longer contour goes in a file: --contour).
constexpr std::size_t kMaxStatePoints = 2000;
// Longest text of a link's contour=... points: the link's limit (io/hash_codec.h kMaxHashLength,
// 16,384) less room for the preset and every changed row (contour_repair.h FitContourToLink).
constexpr std::size_t kMaxLinkContourChars = 15360;

struct TerrainState {
  std::string preset;            // "" (the table's defaults), a method or a figure preset name
  std::string builtin = "disk";  // a built-in seed, or "" when `points` is the seed
  Ring points;                   // the drawn or file contour (metres, as given) when builtin ""
  TerrainParams params;          // BaseParams(preset, builtin), then overrides
  // The RNG seed, a state field as the tree's and the ivy's: a preset or a new seed contour keeps
  // it. Links and state files written while it was a table row (params.seed) still read.
  uint64_t seed = kDefaultTerrainSeed;
};

// The values a state starts from: the table's defaults, the built-in seed's d, Δh and h0, then the
// preset's rows. Error names "preset" or "builtin" and the allowed names.
Result<TerrainParams> BaseParams(std::string_view preset, std::string_view builtin);

// Each setter checks its value and leaves the state unchanged on error (field "preset", "builtin",
// "contour", "seed"; the CLI renames it to its flag).
Status SetTerrainPreset(std::string_view name, TerrainState* state);   // resets params to the base
Status SetTerrainBuiltin(std::string_view name, TerrainState* state);  // params unchanged
Status SetTerrainSeed(double seed, TerrainState* state);  // whole number in [0, kMaxTerrainSeed]
// 3..kMaxStatePoints finite points; clears builtin. Orientation and simplicity are CheckSeed's.
Status SetTerrainPoints(const Ring& points, TerrainState* state);

// The seed ring of a state: the built-in's or the points.
Result<Ring> StateSeed(const TerrainState& state);

// Applies {preset, builtin, contour: [[x, y], ...], seed, params: {key: value}} (or the keys at
// the top level) onto state; a "preset" resets the parameters first, then the rest goes on top.
// A "seed" inside "params" (a file of before the seed was a state field) is the seed; given at
// both places it is refused. Strict: the first bad field is the error and the state is unchanged.
Status ApplyTerrainStateJson(const std::string& text, TerrainState* state);
// What ApplyTerrainStateJson reads back to the same state (every parameter).
std::string TerrainStateJson(const TerrainState& state);

// Applies "#preset=improved&builtin=lobes7&seed=3&d=25" or "#contour=x,y;x,y;...&..." (keys
// prefixed with `prefix`, e.g. "terrain."). Forgiving: bad values are clamped or dropped with one
// printable notice each; keys of other studies are skipped when `prefix` is non-empty.
void ApplyTerrainHash(std::string_view hash, std::string_view prefix, TerrainState* state,
                      std::vector<std::string>* notices);
// "x,y;x,y;..." of a contour's points, each coordinate as its shortest round-trip text (the
// contour= value EncodeTerrainHash writes).
std::string EncodeContourPoints(const Ring& points);
// preset, builtin or contour (each coordinate as its shortest round-trip text), the parameters
// that differ from BaseParams and the seed when it is not kDefaultTerrainSeed, at the place its row
// had (after clean_angle), so a link and a .glb's url are those of before: ApplyTerrainHash of it
// gives the same state, bit for bit.
std::string EncodeTerrainHash(const TerrainState& state, std::string_view prefix = "");

}  // namespace niwa::terrain
