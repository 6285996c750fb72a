// Hash codec for shared links; hostile input is clamped or dropped with a notice, never trusted.
#include "io/url_codec.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "tree/presets.h"

namespace niwa {
namespace {

std::string Decode(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    if (c == '+') {
      out += ' ';
    } else if (c == '%' && i + 2 < text.size() &&
               std::isxdigit(static_cast<unsigned char>(text[i + 1])) &&
               std::isxdigit(static_cast<unsigned char>(text[i + 2]))) {
      out += static_cast<char>(std::stoi(text.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      out += c;
    }
  }
  return out;
}

// Keeps notices printable and short, without markup characters (the page also shows them as text).
std::string Printable(const std::string& text) {
  std::string out;
  for (char c : text.substr(0, 40)) {
    bool markup = c == '<' || c == '>' || c == '&' || c == '"' || c == '\'';
    out += (c >= 32 && c < 127 && !markup) ? c : '?';
  }
  return out;
}

}  // namespace

bool ParsePrune(const std::string& text, Prune* prune, std::string* error) {
  std::size_t colon = text.find(':');
  auto fail = [&]() {
    *error = "prune: '" + Printable(text) + "' must be YEAR:bID or YEAR:sinceY with YEAR in [1, " +
             std::to_string(kMaxYears) + "]";
    return false;
  };
  if (colon == std::string::npos) return fail();
  std::optional<double> year = ParseNumber(text.substr(0, colon));
  std::string selector = text.substr(colon + 1);
  if (!year || *year < 1 || *year > kMaxYears || std::floor(*year) != *year) return fail();
  Prune result;
  result.year = static_cast<int>(*year);
  if (selector.rfind("since", 0) == 0) {
    std::optional<double> since = ParseNumber(selector.substr(5));
    if (!since || *since < 1 || *since > kMaxYears || std::floor(*since) != *since) return fail();
    result.since_year = static_cast<int>(*since);
  } else if (!selector.empty() &&
             (selector[0] == 'b' || std::isdigit(static_cast<unsigned char>(selector[0])))) {
    std::optional<double> id = ParseNumber(selector[0] == 'b' ? selector.substr(1) : selector);
    if (!id || *id < 0 || *id > 1e8 || std::floor(*id) != *id) return fail();
    result.branch = static_cast<int>(*id);
  } else {
    return fail();
  }
  *prune = result;
  return true;
}

std::string FormatPrune(const Prune& prune) {
  return std::to_string(prune.year) + ":" +
         (prune.since_year >= 0 ? "since" + std::to_string(prune.since_year)
                                : "b" + std::to_string(prune.branch));
}

std::string EncodeStateHash(const TreeState& state) {
  std::string out = "preset=" + state.preset + "&seed=" + std::to_string(state.seed) +
                    "&years=" + std::to_string(state.years);
  const Preset* preset = FindPreset(state.preset);
  ParamSet base = preset ? preset->params : ParamSet();
  for (const ParamSpec& spec : ParamTable()) {
    if (state.params.Get(spec.id) != base.Get(spec.id)) {
      out += "&" + std::string(spec.key) + "=" + FormatNumber(state.params.Get(spec.id));
    }
  }
  for (const Prune& prune : state.prunes) out += "&prune=" + FormatPrune(prune);
  if (!state.camera.empty()) out += "&cam=" + state.camera;
  return out;
}

TreeState DecodeStateHash(const std::string& hash, std::vector<std::string>* notices) {
  TreeState state;
  std::string text = hash.size() > 16384 ? hash.substr(0, 16384) : hash;
  if (!text.empty() && text[0] == '#') text.erase(0, 1);
  std::vector<std::pair<std::string, std::string>> pairs;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find('&', start);
    if (end == std::string::npos) end = text.size();
    std::string item = text.substr(start, end - start);
    if (!item.empty()) {
      std::size_t eq = item.find('=');
      std::string key = Decode(item.substr(0, eq));
      std::string value = eq == std::string::npos ? "" : Decode(item.substr(eq + 1));
      pairs.emplace_back(key, value);
    }
    start = end + 1;
  }
  // The preset first: the other values are relative to it.
  for (const auto& [key, value] : pairs) {
    if (key != "preset") continue;
    if (FindPreset(value)) {
      state.preset = value;
    } else {
      notices->push_back("preset: unknown '" + Printable(value) + "', must be one of " +
                         PresetNames());
    }
  }
  const Preset* preset = FindPreset(state.preset);
  if (preset) {
    state.params = preset->params;
    state.years = preset->years;
    state.seed = preset->seed;
  }
  for (const auto& [key, value] : pairs) {
    if (key == "preset") continue;
    if (key == "seed" || key == "years") {
      std::optional<double> number = ParseNumber(value);
      double max = key == "seed" ? 4294967295.0 : kMaxYears;
      double min = key == "seed" ? 0 : 0;
      if (!number || std::floor(*number) != *number) {
        notices->push_back(key + ": '" + Printable(value) +
                           "' dropped, must be a whole number in [" + FormatNumber(min) + ", " +
                           FormatNumber(max) + "]");
        continue;
      }
      double clamped = std::min(max, std::max(min, *number));
      if (clamped != *number) {
        notices->push_back(key + ": clamped to " + FormatNumber(clamped) + ", must be in [" +
                           FormatNumber(min) + ", " + FormatNumber(max) + "]");
      }
      if (key == "seed")
        state.seed = static_cast<uint64_t>(clamped);
      else
        state.years = static_cast<int>(clamped);
    } else if (key == "prune") {
      Prune prune;
      std::string error;
      if (state.prunes.size() >= 256) {
        notices->push_back("prune: more than 256 prunes, rest dropped");
      } else if (ParsePrune(value, &prune, &error)) {
        state.prunes.push_back(prune);
      } else {
        notices->push_back(error + " (dropped)");
      }
    } else if (key == "cam") {
      bool ok = value.size() < 128 && std::all_of(value.begin(), value.end(), [](char c) {
                  return std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == ',' ||
                         c == '-' || c == 'e';
                });
      if (ok)
        state.camera = value;
      else
        notices->push_back("cam: '" + Printable(value) +
                           "' dropped, must be numbers separated by commas");
    } else if (std::optional<ParamId> id = FindParam(key)) {
      const ParamSpec& spec = Spec(*id);
      std::optional<double> number = ParseNumber(value);
      if (!number) {
        notices->push_back(key + ": '" + Printable(value) + "' dropped, must be " +
                           RangeText(spec));
        continue;
      }
      double clamped = std::min(spec.max_value, std::max(spec.min_value, *number));
      if (spec.integer) clamped = std::round(clamped);
      if (clamped != *number) {
        notices->push_back(key + ": clamped to " + FormatNumber(clamped) + ", must be " +
                           RangeText(spec));
      }
      state.params.Set(*id, clamped);
    } else {
      notices->push_back("unknown key '" + Printable(key) + "' dropped");
    }
  }
  return state;
}

}  // namespace niwa
