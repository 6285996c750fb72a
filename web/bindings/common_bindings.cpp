// Bindings shared by every study page: the parameter table, the presets and the share-link hash
// codec, as JSON text for the worker (web/worker/worker.js). One EMSCRIPTEN_BINDINGS block
// (niwa_common) in the one WASM module niwa_web; each study's session is in <study>_bindings.cpp.
// Does not: check anything itself (the core does), or hold state between calls.
#include <emscripten/bind.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "io/json_io.h"
#include "io/url_codec.h"
#include "params/param_table.h"
#include "state_json.h"
#include "tree/presets.h"

namespace niwa {

using nlohmann::json;
using nlohmann::ordered_json;

std::string ParamTableJsonForJs() { return ParamTableJson(); }

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
  TreeState state = DecodeStateHash(hash, &notices);
  ordered_json out;
  out["state"] = StateObject(state);
  out["notices"] = notices;
  // Notices echo pieces of the (hostile) hash; replace bytes that are not valid UTF-8 for dump().
  return out.dump(-1, ' ', false, json::error_handler_t::replace);
}

std::string EncodeHashJson(const std::string& state_json) {
  TreeState state;
  ordered_json out;
  std::string error = StateFromJson(state_json, &state);
  if (error.empty()) {
    out["hash"] = EncodeStateHash(state);
  } else {
    out["error"] = error;
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
}
