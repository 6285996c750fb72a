// Parses each embedded preset JSON file once, on first use (they are checked by tests, so a bad
// file fails loudly).
#include "tree/presets.h"

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>

#include "params/param_json.h"
#include "params/embedded_presets.h"

namespace niwa {

namespace {

// core/tree/presets/*.json, in file-name order.
const std::vector<EmbeddedPreset>& TreeFiles() {
  static const std::vector<EmbeddedPreset> files = EmbeddedPresets("tree");
  return files;
}

Preset ParsePreset(const EmbeddedPreset& file) {
  nlohmann::json j = nlohmann::json::parse(file.json, nullptr, false);
  Preset preset;
  std::string error = j.is_discarded()
                          ? "malformed JSON"
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
  return preset;
}

// One slot per embedded file, each parsed on first use: a fresh 'niwa tree grow --preset X'
// parses the default preset and X, not every file (issue 17 item 7: cold start).
struct PresetSlots {
  std::vector<Preset> presets;
  std::unique_ptr<std::once_flag[]> parsed;
};

PresetSlots& Slots() {
  static PresetSlots slots = [] {
    const std::size_t n = TreeFiles().size();
    return PresetSlots{std::vector<Preset>(n), std::make_unique<std::once_flag[]>(n)};
  }();
  return slots;
}

const Preset& PresetAt(std::size_t i) {
  PresetSlots& slots = Slots();
  std::call_once(slots.parsed[i], [&] { slots.presets[i] = ParsePreset(TreeFiles()[i]); });
  return slots.presets[i];
}

}  // namespace

const std::vector<Preset>& Presets() {
  static const bool all = [] {
    for (std::size_t i = 0; i < TreeFiles().size(); ++i) (void)PresetAt(i);
    return true;
  }();
  (void)all;
  return Slots().presets;
}

const std::vector<std::string_view>& PresetFileFields() {
  static const std::vector<std::string_view> fields = {"name", "title", "source", "years", "seed"};
  return fields;
}

const Preset* FindPreset(const std::string& name) {
  // The file named after the preset first (sakura-thesis.json holds "sakura-thesis").
  const std::vector<EmbeddedPreset>& files = TreeFiles();
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (std::string_view(files[i].file) == name + ".json" && PresetAt(i).name == name) {
      return &PresetAt(i);
    }
  }
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
