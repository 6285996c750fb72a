// The tree state flags of the niwa CLI, over the core's one state resolver.
#include "tree_cli.h"

#include "base/echo.h"
#include "cli_common.h"
#include "params/param_json.h"
#include "tree/presets.h"
#include "tree/tree_look.h"

namespace niwa::cli {

const run::FieldNames& TreeFlagNames() {
  static const run::FieldNames names = {
      {"preset", "--preset"},
      {"years", "--years"},
      {"seed", "--seed"},
      {"prune", "--prune"},
      {"url", "--url"},
      {"max_triangles", "--max-triangles"},
      {"lod", "--lod"},
      {"cam", "--cam"},
      {"threshold", "--threshold"},
      {"card_planes", "--card-planes"},
      {"line_segments", "--line-segments"},
  };
  return names;
}

void AddStateOptions(CLI::App* cmd, const ParamTable& table, StateOptions* o) {
  const std::string params_command =
      table.name() == "tree" ? "'niwa params'" : "'niwa params " + table.name() + "'";
  cmd->add_option("--preset", o->preset, "Species preset (see 'niwa presets')");
  AddNumberFlag(cmd, "--years", &o->years, {0, kMaxYears, true},
                "Years to grow, " + RangeHelp(0, kMaxYears) + " (default: the preset's)");
  AddNumberFlag(cmd, "--seed", &o->seed, {0, kMaxSeed, true},
                "Random seed, decimal, " + RangeHelp(0, kMaxSeed) + " (default: the preset's)");
  cmd->add_option("--set", o->sets,
                  "Override a parameter: key=value (repeatable; see " + params_command + ")");
  AddInputFlag(cmd, "--params", &o->params_file, "JSON file of parameters {\"key\": value, ...}");
  cmd->add_option(
      "--prune", o->prunes,
      "Prune after a year: YEAR:bID (branch id from the JSON) or YEAR:sinceY (repeatable)");
  cmd->add_option("--url", o->url,
                  "A share link (http://host/#preset=...) or its hash (preset=...&seed=...); "
                  "other flags override it");
  AddInputFlag(cmd, "--state", &o->state_file,
               "A state file {preset, seed, years, params, prunes, camera} (the page's Save; "
               "missing keys take the preset's values); other flags override it")
      ->excludes("--url");
  if (table.name() == "tree") {
    cmd->add_option("--season", o->season,
                    "Season of the view: spring, summer, autumn or winter (the season row; the "
                    "tree is the same)");
    cmd->add_option("--leaf-shape", o->leaf_shape,
                    "Leaf shape: broad, needle, palmate or fan (the leaf_shape row)");
  }
  AddBudgetOptions(cmd, &o->budget);
}

TreeState ResolveTreeState(const StateOptions& o, const CLI::App& cmd) {
  TreeState state;
  if (!o.url.empty()) {
    Result<std::string> hash = TreeHashOfLink(o.url);
    Check(AsFlag(hash.status(), "--url"));
    std::vector<std::string> notices;
    state = DecodeTreeHash(*hash, &notices);
    if (!notices.empty()) Fail(Status::Error("--url", notices.front()));
  }
  if (!o.state_file.empty()) {
    Result<std::string> text = ReadFile(o.state_file, "--state", kMaxParamsFileBytes);
    Check(text.status());
    Check(ApplyStateJson(*text, &state).Within("--state " + Echo(o.state_file)));
  }
  // --preset replaces the base state's preset (and its values) only when it names another one.
  const bool based = !o.url.empty() || !o.state_file.empty();
  if ((cmd.count("--preset") || !based) && (!based || state.preset != o.preset)) {
    Check(AsFlag(SetStatePreset(o.preset, &state), "--preset"));
  }
  if (cmd.count("--years")) Check(AsFlag(SetStateYears(o.years, &state), "--years"));
  if (cmd.count("--seed")) {
    Check(AsFlag(SetStateSeed(static_cast<double>(o.seed), &state), "--seed"));
  }
  if (!o.params_file.empty()) {
    Result<std::string> text = ReadFile(o.params_file, "--params", kMaxParamsFileBytes);
    Check(text.status());
    Check(ApplyParamsJson(*text, &state.params, PresetFileFields())
              .Within("--params " + Echo(o.params_file)));
  }
  for (const std::string& item : o.sets)
    Check(state.params.SetFromAssignment(item).Within("--set"));
  if (!o.season.empty()) {
    std::optional<Season> season = ParseSeason(o.season);
    if (!season) {
      Fail(Status::Error("--season",
                         "'" + Echo(o.season) + "' must be spring, summer, autumn or winter"));
    }
    Check(state.params.Set(TreeParam::kSeason, static_cast<double>(*season)).Within("--season"));
  }
  if (!o.leaf_shape.empty()) {
    std::optional<LeafShape> shape = ParseLeafShape(o.leaf_shape);
    if (!shape) {
      Fail(Status::Error("--leaf-shape",
                         "'" + Echo(o.leaf_shape) + "' must be broad, needle, palmate or fan"));
    }
    Check(state.params.Set(TreeParam::kLeafShape, static_cast<double>(*shape))
              .Within("--leaf-shape"));
  }
  for (const std::string& item : o.prunes) Check(AsFlag(AddStatePrune(item, &state), "--prune"));
  // Refused at load, labelled by the last source that set parameters (applied --url, --params,
  // --set in that order).
  if (Status gust = CheckGustOrder(state.params); !gust.ok()) {
    const char* source = !o.sets.empty()          ? "--set"
                         : !o.params_file.empty() ? "--params"
                         : !o.url.empty()         ? "--url"
                         : !o.state_file.empty()  ? "--state"
                                                  : "--preset";
    Fail(gust.Within(source));
  }
  state.limits = TreeGrowLimits(state.params, ResolveBudget(o.budget), "--years");
  return state;
}

}  // namespace niwa::cli
