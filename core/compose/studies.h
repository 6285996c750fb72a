// The registry of studies (tree, ivy, terrain, bark, moss, and the garden that composes them):
// each one's name, time unit, parameter table, presets and share-link codec behind one shape, so
// the web module's generic bindings (tableJson(study), decodeHash(study, hash, prefix)), the tests
// and a composed page reach every study the same way (the CLI's `niwa params STUDY` and `niwa
// presets STUDY` read each study's command file, native_cli/<study>_commands.cpp). Does not: grow
// anything (core/<study>/*_run, compose/garden_run), or know a front end (errors name state
// fields).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "base/status.h"
#include "params/param_table.h"

namespace niwa::compose {

struct StudyInfo {
  std::string name;  // "tree", "ivy", "terrain": the key prefix on a composed page is name + "."
  std::string unit;  // what a run advances in: "years", "steps", "levels", "cycles", "days"
  const ParamTable& (*table)();
  // The table as the page's panel reads it (params/param_json ParamTableJson; the tree's with its
  // Getting started rows).
  std::string (*table_json)();
  // The presets as the study's page reads them: a JSON array of {name, ...}.
  std::string (*presets_json)();
  // {"state": {...every value...}, "notices": [...]} of a share-link hash whose keys carry
  // `prefix` (bad values clamped or dropped with a notice, as the CLI's --url reads them).
  std::string (*decode_hash)(std::string_view hash, std::string_view prefix);
  // The hash (keys prefixed) of a state JSON (as the study's state JSON reads it), or the error
  // naming the state field.
  Result<std::string> (*encode_hash)(const std::string& state_json, std::string_view prefix);
};

// Every study: tree, ivy, terrain, bark, moss, then the garden.
const std::vector<StudyInfo>& Studies();

// The study named `name`, or nullptr.
const StudyInfo* FindStudy(std::string_view name);

// "tree, ivy, terrain, bark, moss or garden": the names for an error line.
std::string StudyNames();

}  // namespace niwa::compose
