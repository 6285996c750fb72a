// The moss study's state as far as the soil and fitness commands need it: a preset and the table's
// values over it, read from a share-link hash (keys with an optional prefix, "moss." on a composed
// page) and written back to one; the run's days, seed and built-in scene (the photon count and
// the indirect switch are table rows: `photons`, `indirect`), and the land when it is another
// study's (scene "tree": a tree preset and its years; scene "terrain": a terrain preset and its
// RNG seed; the composition tier grows it, core/compose/moss_land.h). Does not: read files, grow
// a land or check that a tree or terrain preset exists (the composition tier does), or know a
// front end (errors name state fields: "preset", "days", "seed", "scene", "tree", "tree_years",
// "terrain", "terrain_seed", "rock_triangles", a row key).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "base/status.h"
#include "moss/moss_params.h"
#include "moss/scenes.h"

namespace niwa::moss {

struct MossState {
  std::string preset = "nomura2010";
  MossParams params;
  int days = 300;                // the thesis's 300 days (§4.1)
  uint64_t seed = 1;             // the run's RNG streams (photons, growth, rain, placement)
  std::string scene = "thesis";  // a built-in scene (scenes.h), kTreeLand or kTerrainLand
  // With scene kTreeLand: the tree preset ("niwa presets tree") and its age in years.
  std::string tree = "sakura";
  int tree_years = 10;
  // With scene kTerrainLand: the terrain preset ("niwa presets terrain": a method or a figure
  // preset) and its RNG seed.
  std::string terrain = "improved";
  uint64_t terrain_seed = 1;
  // With scene "rocks": the rocks' triangles (scenes.h: the next icosphere level up).
  int rock_triangles = kRockTrianglesDefault;
};

// The scene names of a land grown by another study (through core/compose, never core/moss).
constexpr const char* kTreeLand = "tree";
constexpr const char* kTerrainLand = "terrain";
constexpr double kMaxMossTreeYears = 100;  // the tree study's kMaxYears

constexpr int kMaxMossDays = 3650;
constexpr uint64_t kMaxMossSeed = 4294967295u;

// Each checks its range; the error names the field ("days" 0..3650, "seed" 0..4294967295 whole,
// "scene" one of scenes.h's names, tree or terrain).
Status SetMossDays(double days, MossState* state);
Status SetMossSeed(double seed, MossState* state);
Status SetMossScene(std::string_view scene, MossState* state);
// The land's fields (read only on their scene): "tree" and "terrain" 1..40 of [a-z0-9_-] (the
// spelling only: the composition tier names an unknown preset), "tree_years" whole in 1..100,
// "terrain_seed" whole in 0..4294967295.
Status SetMossTree(std::string_view name, MossState* state);
Status SetMossTreeYears(double years, MossState* state);
Status SetMossTerrain(std::string_view name, MossState* state);
Status SetMossTerrainSeed(double seed, MossState* state);
// "rock_triangles" whole in [kRockTrianglesMin, kRockTrianglesMax] (read on scene rocks only).
Status SetMossRockTriangles(double triangles, MossState* state);

// Resets the values to the preset's (moss_params.h MossPreset); the error names "preset".
Status SetMossPreset(std::string_view name, MossState* state);

// Applies a share-link hash: the preset first, then every row key (clamped into its range, or
// dropped, with a notice); an unknown key, a repeated key or an over-long hash gives a notice
// (io/hash_codec.h: a repeated key or a hash over 16,384 characters is refused whole).
void ApplyMossHash(std::string_view hash, std::string_view prefix, MossState* state,
                   std::vector<std::string>* notices);

// A state file {preset, scene, days, seed, tree, tree_years, terrain, terrain_seed,
// rock_triangles, params: {key: value}} (any subset): the preset first,
// then the others; a key outside these, a repeated key or a wrong type is an error naming it
// (nothing applied). MossStateJson writes every field (the land's on its scene only;
// rock_triangles on rocks where it differs from 1,600) and every row, read back to the same state.
Status ApplyMossStateJson(const std::string& text, MossState* state);
std::string MossStateJson(const MossState& state);

// "preset=NAME", then scene, days and seed where they differ from the defaults (thesis, 300, 1),
// the land's fields on its scene (tree and tree_years; terrain and terrain_seed; rock_triangles on
// rocks where it differs from 1,600), then every row
// that differs from the preset, keys prefixed.
std::string EncodeMossHash(const MossState& state, std::string_view prefix = "");

}  // namespace niwa::moss
