// Bindings every study page shares, over the core's registry of studies (core/compose/studies.h):
// the parameter table, the presets and the share-link codec of study `study`, with the key prefix
// of a composed page, as JSON text for the worker's handlers. One EMSCRIPTEN_BINDINGS block
// (niwa_common) in the one WASM module niwa_web; each study's session is in <study>_bindings.cpp.
// Does not: check anything itself (the core does), or hold state between calls.
#include <emscripten/bind.h>

#include <nlohmann/json.hpp>
#include <string>

#include "compose/studies.h"
#include "error_record.h"

namespace niwa {
namespace {

using nlohmann::ordered_json;

const compose::StudyInfo* Study(const std::string& name) { return compose::FindStudy(name); }

Status UnknownStudy(const std::string& name) {
  return Status::Error("study",
                       "'" + Echo(name) + "' is unknown; must be " + compose::StudyNames());
}

}  // namespace

// [{name, unit}] of every study, in the nav's order.
std::string StudiesJson() {
  ordered_json out = ordered_json::array();
  for (const compose::StudyInfo& s : compose::Studies())
    out.push_back({{"name", s.name}, {"unit", s.unit}});
  return out.dump();
}

// The study's table as the panel reads it, or an error record naming "study".
std::string TableJson(const std::string& study) {
  const compose::StudyInfo* s = Study(study);
  return s ? s->table_json() : ErrorRecordJson(UnknownStudy(study));
}

// The study's presets (a JSON array), or an error record naming "study".
std::string PresetsJson(const std::string& study) {
  const compose::StudyInfo* s = Study(study);
  return s ? s->presets_json() : ErrorRecordJson(UnknownStudy(study));
}

// {state, notices} of a share-link hash (keys with `prefix`), or an error record naming "study".
std::string DecodeHash(const std::string& study, const std::string& hash,
                       const std::string& prefix) {
  const compose::StudyInfo* s = Study(study);
  return s ? s->decode_hash(hash, prefix) : ErrorRecordJson(UnknownStudy(study));
}

// {ok: true, hash} of a state JSON, or the error record naming its bad field.
std::string EncodeHash(const std::string& study, const std::string& state_json,
                       const std::string& prefix) {
  const compose::StudyInfo* s = Study(study);
  if (!s) return ErrorRecordJson(UnknownStudy(study));
  Result<std::string> hash = s->encode_hash(state_json, prefix);
  if (!hash.ok()) return ErrorRecordJson(hash.status());
  ordered_json out;
  out["ok"] = true;
  out["hash"] = *hash;
  return JsonText(out);
}

}  // namespace niwa

EMSCRIPTEN_BINDINGS(niwa_common) {
  using namespace emscripten;
  function("studiesJson", &niwa::StudiesJson);
  function("tableJson", &niwa::TableJson);
  function("presetsJson", &niwa::PresetsJson);
  function("decodeHash", &niwa::DecodeHash);
  function("encodeHash", &niwa::EncodeHash);
}
