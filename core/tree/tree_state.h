// The one resolver of the tree study's state: preset, seed, years, parameters, prunes and camera,
// from a state JSON (the page), a share-link hash (the page and --url) or the CLI's flags, which
// all call these functions. Does not: grow the tree (tree/growth) or parse JSON of parameters
// alone (params/param_json).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "base/status.h"
#include "tree/growth.h"

namespace niwa {

// What a tree page or command grows: the GrowRequest (preset, params, seed, years, prunes) plus the
// page's camera. Default: the default preset's values.
struct TreeState : GrowRequest {
  std::string camera;  // "yaw,pitch,distance,tx,ty,tz" as given, kept for the page
  TreeState();
};

constexpr const char* kDefaultPreset = "sakura";
constexpr double kMaxSeed = 4294967295.0;
constexpr std::size_t kMaxPrunes = 256;

// Each setter checks its value and leaves the state unchanged on error. Errors name the state
// field ("preset", "years", "seed", "prune", "camera"); the CLI renames it to its flag.
// Resets params, seed and years to the preset's (prunes and camera stay).
Status SetStatePreset(std::string_view name, TreeState* state);
Status SetStateYears(double years, TreeState* state);            // whole number in [0, kMaxYears]
Status SetStateSeed(double seed, TreeState* state);              // whole number in [0, kMaxSeed]
Status AddStatePrune(std::string_view text, TreeState* state);   // ParsePrune, at most 256
Status SetStateCamera(std::string_view text, TreeState* state);  // numbers and commas only

// The cross-row check of the tree table's wind rows, made wherever a state is loaded: ok when
// gust_off > gust_on, else {"gust_off", "5 must be greater than gust_on (7)"}.
Status CheckGustOrder(const ParamSet& params);

// Applies {preset, seed, years, params: {key: value}, prunes: ["12:b42"], camera} onto state: a
// "preset" resets the state to that preset first; the other fields go on top. Values may be
// numbers or numeric strings (params also booleans). Strict: the first bad field is the error and
// the state is unchanged; any other top-level key is refused by name ("colour: unknown state key;
// the keys are preset, seed, years, params, prunes, camera").
Status ApplyStateJson(const std::string& text, TreeState* state);
// {preset, seed, years, params: {every key: value}, prunes: [...], camera}: what ApplyStateJson
// reads back to the same state.
std::string TreeStateJson(const TreeState& state);

// The state file (the page's Save, 'niwa tree state', read by 'niwa tree grow --state'):
// {preset, seed, years, params: {only the values that differ from the preset's}, prunes:
// ["YEAR:bID" | "YEAR:sinceY"], camera}, two-space indented. ApplyStateJson onto a default
// TreeState reads it back to the same state (and a file with only some keys takes the preset's
// values, or the default preset's, for the rest).
std::string TreeStateFileJson(const TreeState& state);

// A --url value: a whole share link ("http://host/#preset=...", "https://host/dir/index.html#...")
// or a bare hash (with or without '#'); returns the tree hash it holds. A link to another page
// than the tree's ("" or index.html) is refused: {"url", "'grove.html' is the grove page, not a
// tree link; ..."}.
Result<std::string> TreeHashOfLink(std::string_view url);

// Decodes a share-link hash (with or without '#'). Forgiving: unknown keys, bad or out-of-range
// values are dropped or clamped with one notice line each; the result is always usable. A hash
// over kMaxHashLength is not read (one notice), a repeated key is named (prune may repeat), and a
// gust_on not before gust_off puts both back to the preset's with a notice. Keys carry
// `prefix` ("tree." on a composed page; keys without it belong to other studies and are skipped).
TreeState DecodeTreeHash(std::string_view hash, std::vector<std::string>* notices,
                         std::string_view prefix = "");
// preset, seed, years, the parameters that differ from the preset's, prunes and camera.
std::string EncodeTreeHash(const TreeState& state, std::string_view prefix = "");

}  // namespace niwa
