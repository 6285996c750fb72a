// Bindings shared by every study page: the parameter table, the presets and the share-link hash
// codec, as JSON text for the worker (web/worker/worker.js). One EMSCRIPTEN_BINDINGS block
// (niwa_common) in the one WASM module niwa_web; each study's session is in <study>_bindings.cpp.
// Does not: check anything itself (the core does), or hold state between calls.
#include <emscripten/bind.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "params/param_json.h"
#include "tree/presets.h"
#include "tree/tree_params.h"
#include "tree/tree_simple.h"
#include "tree/tree_state.h"

namespace niwa {
namespace {

using nlohmann::json;
using nlohmann::ordered_json;

// {"key": value} for every parameter (full values), as a JSON object.
ordered_json ParamsObject(const ParamSet& params) {
  return ordered_json::parse(ParamsToJson(params, -1));
}

}  // namespace

// The tree's table with its Getting started group (core/tree/tree_simple.h) on its rows.
std::string ParamTableJsonForJs() { return TreeParamTableJsonWithSimple(); }

std::string PresetsJson() {
  ordered_json out = ordered_json::array();
  for (const Preset& p : Presets()) {
    ordered_json j;
    j["name"] = p.name;
    j["title"] = p.title;
    j["years"] = p.years;
    j["seed"] = p.seed;
    j["source"] = p.source;
    j["params"] = ParamsObject(p.params);
    out.push_back(std::move(j));
  }
  return out.dump();
}

std::string DecodeHashJson(const std::string& hash) {
  std::vector<std::string> notices;
  TreeState state = DecodeTreeHash(hash, &notices);
  ordered_json out;
  out["state"] = ordered_json::parse(TreeStateJson(state));
  out["notices"] = notices;
  // Notices echo pieces of the (hostile) hash; replace bytes that are not valid UTF-8 for dump().
  return out.dump(-1, ' ', false, json::error_handler_t::replace);
}

std::string EncodeHashJson(const std::string& state_json) {
  TreeState state;
  ordered_json out;
  std::string error = ApplyStateJson(state_json, &state).Line();
  if (error.empty()) {
    out["hash"] = EncodeTreeHash(state);
  } else {
    out["error"] = error;
  }
  return out.dump(-1, ' ', false, json::error_handler_t::replace);
}

// The page's Save: {json} the state file (TreeStateFileJson: changed parameters only) of a page
// state {preset, seed, years, params, prunes, camera}, or {error}.
std::string StateFileJson(const std::string& state_json) {
  TreeState state;
  ordered_json out;
  std::string error = ApplyStateJson(state_json, &state).Line();
  if (error.empty()) {
    out["json"] = TreeStateFileJson(state);
  } else {
    out["error"] = error;
  }
  return out.dump(-1, ' ', false, json::error_handler_t::replace);
}

// The page's Open: {state} (every value, as decodeHash gives it) of a state file read onto the
// default state (missing keys take the preset's values), or {error} naming the bad field.
std::string OpenStateFileJson(const std::string& text) {
  TreeState state;
  ordered_json out;
  Status status = ApplyStateJson(text, &state);
  if (status.ok()) status = CheckGustOrder(state.params);
  if (status.ok()) {
    out["state"] = ordered_json::parse(TreeStateJson(state));
  } else {
    out["error"] = status.Line();
  }
  return out.dump(-1, ' ', false, json::error_handler_t::replace);
}

}  // namespace niwa

EMSCRIPTEN_BINDINGS(niwa_common) {
  using namespace emscripten;
  function("paramTableJson", &niwa::ParamTableJsonForJs);
  function("presetsJson", &niwa::PresetsJson);
  function("decodeHash", &niwa::DecodeHashJson);
  function("encodeHash", &niwa::EncodeHashJson);
  function("stateFile", &niwa::StateFileJson);
  function("openStateFile", &niwa::OpenStateFileJson);
}
