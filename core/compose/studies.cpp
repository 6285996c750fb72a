// The registry of studies (and the garden that composes them): each one's table, presets and hash
// codec behind one shape.
#include "compose/studies.h"

#include <nlohmann/json.hpp>

#include "bark/bark_params.h"
#include "bark/bark_state.h"
#include "compose/garden_params.h"
#include "compose/garden_state.h"
#include "ivy/ivy_params.h"
#include "ivy/ivy_state.h"
#include "moss/moss_params.h"
#include "moss/moss_state.h"
#include "params/param_json.h"
#include "terrain/terrain_params.h"
#include "terrain/terrain_state.h"
#include "tree/presets.h"
#include "tree/tree_params.h"
#include "tree/tree_simple.h"
#include "tree/tree_state.h"

namespace niwa::compose {
namespace {

using nlohmann::ordered_json;

// Notices and errors may echo hostile text: bytes that are not UTF-8 are replaced.
std::string Dump(const ordered_json& j) {
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string DecodedJson(const std::string& state_json, const std::vector<std::string>& notices) {
  ordered_json out;
  out["state"] = ordered_json::parse(state_json);
  out["notices"] = notices;
  return Dump(out);
}

// ---------------------------------------------------------------- tree (thesis ch. 2-4)
std::string TreePresetsJson() {
  ordered_json out = ordered_json::array();
  for (const Preset& p : Presets()) {
    ordered_json j;
    j["name"] = p.name;
    j["title"] = p.title;
    j["years"] = p.years;
    j["seed"] = p.seed;
    j["source"] = p.source;
    j["params"] = ordered_json::parse(ParamsToJson(p.params, -1));
    out.push_back(std::move(j));
  }
  return out.dump();
}

std::string TreeDecode(std::string_view hash, std::string_view prefix) {
  std::vector<std::string> notices;
  const TreeState state = DecodeTreeHash(hash, &notices, prefix);
  return DecodedJson(TreeStateJson(state), notices);
}

Result<std::string> TreeEncode(const std::string& state_json, std::string_view prefix) {
  TreeState state;
  NIWA_RETURN_IF_ERROR(ApplyStateJson(state_json, &state));
  return EncodeTreeHash(state, prefix);
}

// ---------------------------------------------------------------- ivy (paper 004)
std::string IvyPresetsJson() {
  ordered_json out = ordered_json::array();
  for (const std::string& name : IvyPresetNames()) {
    ordered_json j;
    j["name"] = name;
    ordered_json overrides = ordered_json::object();
    for (const auto& [key, value] : IvyPresetOverrides(name)) overrides[key] = value;
    j["overrides"] = overrides;
    j["params"] = ordered_json::parse(ParamsToJson(*IvyPreset(name), -1));
    out.push_back(std::move(j));
  }
  return out.dump();
}

std::string IvyDecode(std::string_view hash, std::string_view prefix) {
  ivy::IvyState state;
  std::vector<std::string> notices;
  ivy::ApplyIvyHash(hash, prefix, &state, &notices);
  return DecodedJson(ivy::IvyStateJson(state), notices);
}

Result<std::string> IvyEncode(const std::string& state_json, std::string_view prefix) {
  ivy::IvyState state;
  NIWA_RETURN_IF_ERROR(ivy::ApplyIvyStateJson(state_json, &state));
  return ivy::EncodeIvyHash(state, prefix);
}

// ---------------------------------------------------------------- terrain (paper 002)
std::string TerrainPresetsJson() {
  ordered_json out = ordered_json::array();
  for (int m = 0; m < 4; ++m)
    out.push_back({{"name", terrain::MethodName(m)}, {"caption", "the method's preset"}});
  for (const terrain::FigurePreset& p : terrain::FigurePresets())
    out.push_back({{"name", p.name}, {"caption", p.caption}});
  return out.dump();
}

std::string TerrainDecode(std::string_view hash, std::string_view prefix) {
  terrain::TerrainState state;
  std::vector<std::string> notices;
  terrain::ApplyTerrainHash(hash, prefix, &state, &notices);
  return DecodedJson(terrain::TerrainStateJson(state), notices);
}

Result<std::string> TerrainEncode(const std::string& state_json, std::string_view prefix) {
  terrain::TerrainState state;
  NIWA_RETURN_IF_ERROR(terrain::ApplyTerrainStateJson(state_json, &state));
  return terrain::EncodeTerrainHash(state, prefix);
}

// ---------------------------------------------------------------- bark (paper 003)
std::string BarkPresetsJson() {
  ordered_json out = ordered_json::array();
  for (const std::string& name : bark::BarkPresetNames()) {
    ordered_json j;
    j["name"] = name;
    j["source"] = bark::BarkPresetSource(name);
    j["params"] = ordered_json::parse(ParamsToJson(*bark::BarkPreset(name), -1));
    out.push_back(std::move(j));
  }
  return out.dump();
}

std::string BarkDecode(std::string_view hash, std::string_view prefix) {
  bark::BarkState state;
  std::vector<std::string> notices;
  bark::ApplyBarkHash(hash, prefix, &state, &notices);
  return DecodedJson(bark::BarkStateJson(state), notices);
}

Result<std::string> BarkEncode(const std::string& state_json, std::string_view prefix) {
  bark::BarkState state;
  NIWA_RETURN_IF_ERROR(bark::ApplyBarkStateJson(state_json, &state));
  return bark::EncodeBarkHash(state, prefix);
}

// ---------------------------------------------------------------- moss (paper 001)
std::string MossPresetsJson() {
  ordered_json out = ordered_json::array();
  for (const std::string& name : moss::MossPresetNames()) {
    ordered_json j;
    j["name"] = name;
    j["source"] = moss::MossPresetSource(name);
    j["params"] = ordered_json::parse(ParamsToJson(*moss::MossPreset(name), -1));
    out.push_back(std::move(j));
  }
  return out.dump();
}

std::string MossDecode(std::string_view hash, std::string_view prefix) {
  moss::MossState state;
  std::vector<std::string> notices;
  moss::ApplyMossHash(hash, prefix, &state, &notices);
  return DecodedJson(moss::MossStateJson(state), notices);
}

Result<std::string> MossEncode(const std::string& state_json, std::string_view prefix) {
  moss::MossState state;
  NIWA_RETURN_IF_ERROR(moss::ApplyMossStateJson(state_json, &state));
  return moss::EncodeMossHash(state, prefix);
}

// ---------------------------------------------------------------- garden (issue 33)
// One preset: the small default garden every front end starts from (DefaultGardenState), as
// `niwa presets garden` lists it.
std::string GardenPresetsJson() {
  ordered_json out = ordered_json::array();
  out.push_back({{"name", "default"},
                 {"caption",
                  "the small default garden: a 40 m terrain ground, a wall, two rocks, a stone "
                  "lantern, a keyaki by hand, keyaki, sakura and maple by the rules"}});
  return out.dump();
}

// The default garden with the link's keys (as the garden page and `niwa garden grow --url` read
// a link; ApplyGardenHash lays the default objects out for the link's size, keeping its ivy).
std::string GardenDecode(std::string_view hash, std::string_view prefix) {
  GardenState state = DefaultGardenState();
  std::vector<std::string> notices;
  ApplyGardenHash(hash, prefix, &state, &notices);
  return DecodedJson(GardenStateJson(state), notices);
}

Result<std::string> GardenEncode(const std::string& state_json, std::string_view prefix) {
  GardenState state = DefaultGardenState();
  NIWA_RETURN_IF_ERROR(ApplyGardenStateJson(state_json, &state));
  return EncodeGardenHash(state, prefix);
}

}  // namespace

const std::vector<StudyInfo>& Studies() {
  static const std::vector<StudyInfo> studies = {
      {"tree", "years", &TreeParamTable, &TreeParamTableJsonWithSimple, &TreePresetsJson,
       &TreeDecode, &TreeEncode},
      {"ivy", "steps", &IvyTable, [] { return ParamTableJson(IvyTable()); }, &IvyPresetsJson,
       &IvyDecode, &IvyEncode},
      {"terrain", "levels", &terrain::TerrainTable,
       [] { return ParamTableJson(terrain::TerrainTable()); }, &TerrainPresetsJson, &TerrainDecode,
       &TerrainEncode},
      {"bark", "cycles", &bark::BarkTable, [] { return ParamTableJson(bark::BarkTable()); },
       &BarkPresetsJson, &BarkDecode, &BarkEncode},
      {"moss", "days", &moss::MossTable, [] { return ParamTableJson(moss::MossTable()); },
       &MossPresetsJson, &MossDecode, &MossEncode},
      {"garden", "years", &GardenTable, [] { return ParamTableJson(GardenTable()); },
       &GardenPresetsJson, &GardenDecode, &GardenEncode},
  };
  return studies;
}

const StudyInfo* FindStudy(std::string_view name) {
  for (const StudyInfo& s : Studies())
    if (s.name == name) return &s;
  return nullptr;
}

std::string StudyNames() {
  std::string out;
  const std::vector<StudyInfo>& all = Studies();
  for (std::size_t i = 0; i < all.size(); ++i)
    out += (i == 0 ? "" : i + 1 == all.size() ? " or " : ", ") + all[i].name;
  return out;
}

}  // namespace niwa::compose
