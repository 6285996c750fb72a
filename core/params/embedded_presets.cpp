// One study's share of the embedded preset files (cmake/embed_presets.cmake), and its list files
// read.
#include "params/embedded_presets.h"

#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>

#include "params/param_json.h"

namespace niwa {

std::vector<EmbeddedPreset> EmbeddedPresets(std::string_view study) {
  std::vector<EmbeddedPreset> out;
  for (const EmbeddedPreset& f : EmbeddedPresetFiles())
    if (study == f.study) out.push_back(f);
  return out;
}

Result<std::vector<ListedPreset>> ReadPresetLists(std::string_view study, const ParamTable& table) {
  std::vector<ListedPreset> out;
  for (const EmbeddedPreset& f : EmbeddedPresets(study)) {
    const std::string field = std::string(study) + "/presets/" + f.file;
    NIWA_RETURN_IF_ERROR(CheckJsonKeys(f.json, field));
    const nlohmann::ordered_json j = nlohmann::ordered_json::parse(f.json, nullptr, false);
    if (j.is_discarded() || !j.is_object() || !j.contains("presets") || !j["presets"].is_array()) {
      return Status::Error(field, "must be {\"presets\": [...]}");
    }
    for (const nlohmann::ordered_json& p : j["presets"]) {
      if (!p.is_object() || !p.contains("name") || !p["name"].is_string() ||
          !p.contains("params") || !p["params"].is_object()) {
        return Status::Error(field, "each preset must have a \"name\" and a \"params\" object");
      }
      ListedPreset preset;
      preset.name = p["name"].get<std::string>();
      for (const auto& [key, value] : p.items()) {
        if (key == "name" || key == "params") continue;
        if (!value.is_string() || (key != "title" && key != "source" && key != "caption")) {
          return Status::Error(field, preset.name + ": '" + key +
                                          "' is unknown; must be title, source or caption (text)");
        }
        (key == "title"    ? preset.title
         : key == "source" ? preset.source
                           : preset.caption) = value.get<std::string>();
      }
      ParamSet check(table);
      NIWA_RETURN_IF_ERROR(
          ApplyParamsJson(p["params"].dump(), &check).Within(field + ": " + preset.name));
      for (const auto& [key, value] : p["params"].items())
        preset.values.emplace_back(key, value.get<double>());
      out.push_back(std::move(preset));
    }
  }
  return out;
}

std::vector<ListedPreset> StudyPresetLists(std::string_view study, const ParamTable& table) {
  Result<std::vector<ListedPreset>> listed = ReadPresetLists(study, table);
  if (!listed.ok()) {
    std::fprintf(stderr, "niwa: %s\n", listed.status().Line().c_str());
    std::abort();
  }
  return std::move(listed).value();
}

}  // namespace niwa
