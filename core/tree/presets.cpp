// Parses the embedded preset JSON files once (they are checked by tests, so a bad file fails
// loudly).
#include "tree/presets.h"

#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>

#include "params/param_json.h"
#include "tree/presets_embedded.h"

namespace niwa {

const std::vector<Preset>& Presets() {
  static const std::vector<Preset> presets = [] {
    std::vector<Preset> list;
    for (const EmbeddedPreset& file : EmbeddedPresets()) {
      nlohmann::json j = nlohmann::json::parse(file.json, nullptr, false);
      Preset preset;
      std::string error =
          j.is_discarded() ? "malformed JSON"
                           : ApplyParamsJson(file.json, &preset.params, PresetFileFields()).Line();
      if (!error.empty() || !j.contains("name") || !j.contains("years")) {
        std::fprintf(stderr, "niwa: preset file %s is invalid: %s\n", file.file, error.c_str());
        std::abort();  // a build-time data error, caught by the preset tests
      }
      preset.name = j["name"].get<std::string>();
      preset.title = j.value("title", preset.name);
      preset.source = j.value("source", "");
      preset.years = j["years"].get<int>();
      preset.seed = j.value("seed", 1ULL);
      list.push_back(std::move(preset));
    }
    return list;
  }();
  return presets;
}

const std::vector<std::string_view>& PresetFileFields() {
  static const std::vector<std::string_view> fields = {"name", "title", "source", "years", "seed"};
  return fields;
}

const Preset* FindPreset(const std::string& name) {
  for (const Preset& p : Presets()) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

std::string PresetNames() {
  std::string names;
  for (const Preset& p : Presets()) names += (names.empty() ? "" : ", ") + p.name;
  return names;
}

}  // namespace niwa
