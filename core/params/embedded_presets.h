// Every study's preset JSON files as compiled-in text: core/<study>/presets/*.json, embedded by
// the one build step cmake/embed_presets.cmake (the .cpp is generated), and the reader of a study's
// preset list file. Does not: know any study's rows (the table is passed in) or apply a preset.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "base/status.h"
#include "params/param_table.h"

namespace niwa {

struct EmbeddedPreset {
  const char* study;  // the folder: "tree", "ivy", "terrain"
  const char* file;   // "sakura.json"
  const char* json;
};

// Every embedded file, by study then file name (generated).
const std::vector<EmbeddedPreset>& EmbeddedPresetFiles();

// The files of one study, in file-name order (none for a study without presets/).
std::vector<EmbeddedPreset> EmbeddedPresets(std::string_view study);

// One preset of a list file ({"presets": [{"name", "title"?, "source"?, "caption"?, "params"}]}):
// its row values in the file's order, each checked against the table.
struct ListedPreset {
  std::string name;
  std::string title, source, caption;  // "" when the file leaves them out
  std::vector<std::pair<std::string, double>> values;
};

// Every preset of `study`'s list files, in order; an error names the file and the field (a
// build-time data error: each study's tests read its presets).
Result<std::vector<ListedPreset>> ReadPresetLists(std::string_view study, const ParamTable& table);

// ReadPresetLists for a study's own presets: a bad embedded file is a build-time data error, so
// it prints its line and aborts (each study's preset tests read every file, so it fails there).
std::vector<ListedPreset> StudyPresetLists(std::string_view study, const ParamTable& table);

}  // namespace niwa
