// The tree page's Save and Open: its state file (core/tree/tree_state.h TreeStateFileJson), as
// JSON text for web/worker/tree_handler.js. One EMSCRIPTEN_BINDINGS block (niwa_tree_state).
// Does not: check anything itself (the core does), or hold state between calls.
#include <emscripten/bind.h>

#include <nlohmann/json.hpp>
#include <string>

#include "error_record.h"
#include "tree/tree_params.h"
#include "tree/tree_state.h"

namespace niwa {

// The page's Save: {ok: true, json} the state file (TreeStateFileJson: changed parameters only)
// of a page state {preset, seed, years, params, prunes, camera}, or the error record.
std::string StateFileJson(const std::string& state_json) {
  TreeState state;
  Status status = ApplyStateJson(state_json, &state);
  if (!status.ok()) return ErrorRecordJson(status);
  nlohmann::ordered_json out;
  out["ok"] = true;
  out["json"] = TreeStateFileJson(state);
  return JsonText(out);
}

// The page's Open: {ok: true, state} (every value, as decodeHash gives it) of a state file read
// onto the default state (missing keys take the preset's values), or the error record naming the
// bad field.
std::string OpenStateFileJson(const std::string& text) {
  TreeState state;
  Status status = ApplyStateJson(text, &state);
  if (status.ok()) status = CheckGustOrder(state.params);
  if (!status.ok()) return ErrorRecordJson(status);
  nlohmann::ordered_json out;
  out["ok"] = true;
  out["state"] = nlohmann::ordered_json::parse(TreeStateJson(state));
  return JsonText(out);
}

}  // namespace niwa

EMSCRIPTEN_BINDINGS(niwa_tree_state) {
  using namespace emscripten;
  function("stateFile", &niwa::StateFileJson);
  function("openStateFile", &niwa::OpenStateFileJson);
}
