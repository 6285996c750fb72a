// The moss state's preset and values, and its share-link hash.
#include "moss/moss_state.h"

#include "io/hash_codec.h"

namespace niwa::moss {

Status SetMossPreset(std::string_view name, MossState* state) {
  Result<MossParams> params = MossPreset(name);
  if (!params.ok()) return params.status();
  state->preset = std::string(name);
  state->params = *params;
  return Status::Ok();
}

void ApplyMossHash(std::string_view hash, std::string_view prefix, MossState* state,
                   std::vector<std::string>* notices) {
  const std::string pre(prefix);
  const HashPairs pairs = SplitHash(hash, notices);
  // The preset first, so the rows go on top of it whatever their order.
  for (const auto& [key, value] : pairs) {
    if (key != pre + "preset") continue;
    const Status s = SetMossPreset(value, state);
    if (s.ok()) continue;
    std::string names;
    for (const std::string& n : MossPresetNames()) names += (names.empty() ? "" : " or ") + n;
    notices->push_back(Printable(key) + ": '" + Printable(value) + "' is unknown; must be " +
                       names);
  }
  for (const auto& [key, value] : pairs) {
    if (key == pre + "preset") continue;
    if (ApplyHashParam(key, value, prefix, &state->params, notices)) continue;
    if (prefix.empty() || key.rfind(pre, 0) == 0)
      notices->push_back("unknown key '" + Printable(key) + "' dropped");
  }
}

std::string EncodeMossHash(const MossState& state, std::string_view prefix) {
  Result<MossParams> base = MossPreset(state.preset);
  return std::string(prefix) + "preset=" + PercentEncode(state.preset) +
         EncodeChangedParams(state.params, base.ok() ? *base : MossParams(), prefix);
}

}  // namespace niwa::moss
