// niwa CLI commands of the moss study (Nomura 2010, paper 001; core/moss, docs/moss-model.md):
// 'moss soil' (one soil cell: every term of eqs 3.2-3.16 and the energy balance's residuals) and
// 'moss fitness' (eqs 3.17-3.20 for one place), each one JSON object on stdout; the table and
// presets for 'niwa params moss' and 'niwa presets moss'. Thin adapters: flags into a state and a
// cell, the core's reports (core/moss/moss_report.h) out.
// cli-order: 50
#include <CLI/CLI.hpp>
#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "base/echo.h"
#include "cli_common.h"
#include "moss/moss_params.h"
#include "moss/moss_report.h"
#include "moss/moss_state.h"
#include "moss/soil.h"
#include "params/param_text.h"
#include "run/field_names.h"

namespace niwa::cli {
namespace {

using moss::MossParam;

// The one table of the moss commands' names for state and cell fields (run/field_names.h).
const run::FieldNames kFieldFlags = {
    {"preset", "--preset"}, {"geology", "--geology"}, {"theta", "--theta"},     {"S", "--S"},
    {"m_over_M", "--mM"},   {"V_sky", "--V"},         {"species", "--species"}, {"T_s", "--Ts"},
    {"rh_s", "--rhs"},
};

// Ranges of the flags that are not table rows (the soil cell's and the fitness place's inputs).
constexpr FlagRange kThetaRange{0, 1, false, " (at most the geology's theta_SAT)"};
constexpr FlagRange kLightRange{0, 1e6, false, " (W/m2)"};
constexpr FlagRange kShareRange{0, 1};
constexpr FlagRange kSurfaceTRange{100, 400, false, " (K)"};
constexpr FlagRange kSurfaceRhRange{0, 100};

FlagRange MossRowRange(MossParam row) {
  return RowFlagRange(moss::MossTable().row(static_cast<std::size_t>(row)));
}

// The flags every moss command shares: the state (--url, then --preset, then --set).
struct StateOptions {
  std::string url, preset;
  std::vector<std::string> sets;
};
void AddStateOptions(CLI::App* cmd, StateOptions* o) {
  cmd->add_option("--preset", o->preset,
                  "nomura2010 (default) or nomura2010-sky (niwa presets moss)");
  cmd->add_option("--set", o->sets, "KEY=VALUE of the moss table (niwa params moss)");
  cmd->add_option("--url", o->url, "A share-link hash (preset=...&T=...); other flags override it");
}

moss::MossState ResolveState(const StateOptions& o) {
  moss::MossState state;
  if (!o.url.empty()) {
    std::vector<std::string> notices;
    moss::ApplyMossHash(o.url, "", &state, &notices);
    if (!notices.empty()) throw BadInput{"--url: " + notices.front()};
  }
  if (!o.preset.empty())
    Check(run::RenameField(moss::SetMossPreset(o.preset, &state), kFieldFlags));
  for (const std::string& s : o.sets) Check(state.params.SetFromAssignment(s).Within("--set"));
  return state;
}

struct SoilOptions {
  StateOptions state;
  std::string geology;
  double theta = 0, S = 0, T = 0, m_over_M = 0, V = 1;
};

// moss soil: one cell and day, every term of eqs 3.2-3.16 (core/moss/soil.h).
int RunSoil(const SoilOptions& o, bool T_given, bool V_given, std::ostream& out) {
  moss::MossState state = ResolveState(o.state);
  if (T_given) Check(AsFlag(state.params.Set(MossParam::kT, o.T), "--T"));
  Check(moss::CheckMossParams(state.params));
  // The sky view is read by the sky-view longwave only: given to the thesis's eq 3.3 it would be
  // silently ignored, so it is refused.
  if (V_given &&
      state.params.GetInt(MossParam::kLongwave) != static_cast<int>(moss::Longwave::kSkyView))
    Fail(Status::Error(
        "--V",
        "only applies with longwave=1 (sky-view: --preset nomura2010-sky or --set longwave=1)"));
  moss::Geology geology;
  if (!moss::GeologyFromName(o.geology.c_str(), &geology))
    Fail(Status::Error("--geology",
                       "'" + Echo(o.geology) + "' is unknown; must be humus, sandy or asphalt"));
  moss::SoilCell cell;
  cell.law = moss::GeologyLawOf(state.params, geology);
  cell.theta = o.theta;
  cell.S = o.S;
  cell.m_over_M = o.m_over_M;
  cell.V_sky = o.V;
  Check(run::RenameField(moss::CheckSoilCell(cell), kFieldFlags));
  const nlohmann::ordered_json j = moss::SoilReport(state, geology, cell);
  out << j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
  return 0;
}

struct FitnessOptions {
  StateOptions state;
  std::string species;
  double T_s = 0, rh_s = 0, S = 0;
};

// moss fitness: eqs 3.17-3.20 for one place, for one species or all three (core/moss/fitness.h).
int RunFitness(const FitnessOptions& o, std::ostream& out) {
  moss::MossState state = ResolveState(o.state);
  Check(moss::CheckMossParams(state.params));
  std::vector<moss::Species> which;
  if (o.species.empty()) {
    which = {moss::Species::kGingoke, moss::Species::kHaigoke, moss::Species::kSugigoke};
  } else {
    moss::Species s;
    if (!moss::SpeciesFromName(o.species.c_str(), &s))
      Fail(Status::Error("--species", "'" + Echo(o.species) +
                                          "' is unknown; must be gingoke, haigoke or sugigoke"));
    which = {s};
  }
  const nlohmann::ordered_json j = moss::FitnessReport(state, which, o.T_s, o.rh_s, o.S);
  out << j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
  return 0;
}

void PrintPresets(std::ostream& out) {
  for (const std::string& name : moss::MossPresetNames()) {
    out << name;
    for (const auto& [key, value] : moss::MossPresetValues(name))
      out << "\t" << key << "=" << FormatNumber(value);
    out << "\t" << moss::MossPresetSource(name) << "\n";
  }
}

}  // namespace

void AddMossCommands(CLI::App& app, CommandList& commands) {
  commands.studies.push_back(
      {"moss",
       &moss::MossTable(),
       &PrintPresets,
       {},
       {"moss", "soil", "--geology", "humus", "--theta", "0.2", "--S", "25"}});
  CLI::App* moss_app = Subcommand(app, "moss", "Moss on soil under light (Nomura 2010)");
  moss_app->require_subcommand(1);

  CLI::App* soil = moss_app->add_subcommand(
      "soil",
      "One soil cell for one day: every term of eqs 3.2-3.16 (longwave, bucket, evaporation "
      "efficiency, linearised energy balance) and the balance's residuals, as one JSON object");
  auto so = std::make_shared<SoilOptions>();
  soil->add_option("--geology", so->geology, "humus, sandy or asphalt (table 3.4)")->required();
  AddNumberFlag(soil, "--theta", &so->theta, kThetaRange,
                "Volumetric water content theta, " + RangeHelp(kThetaRange) +
                    " (at most the geology's theta_SAT)")
      ->required();
  AddNumberFlag(soil, "--S", &so->S, kLightRange, "Light S (W/m2), " + RangeHelp(kLightRange))
      ->required();
  AddNumberFlag(soil, "--T", &so->T, MossRowRange(MossParam::kT),
                "Air temperature (K; the T row), " + RangeHelp(MossRowRange(MossParam::kT)));
  AddNumberFlag(soil, "--mM", &so->m_over_M, kShareRange,
                "m/M of eq 3.5 (moss density near the cell), " + RangeHelp(kShareRange));
  AddNumberFlag(soil, "--V", &so->V, kShareRange,
                "Sky view V (read by longwave=1, sky-view), " + RangeHelp(kShareRange));
  AddStateOptions(soil, &so->state);
  commands.push_back({soil,
                      [so, soil](std::ostream& out) {
                        return RunSoil(*so, soil->count("--T") > 0, soil->count("--V") > 0, out);
                      },
                      {"--geology", "humus", "--theta", "0.2", "--S", "25"}});

  CLI::App* fitness = moss_app->add_subcommand(
      "fitness",
      "Fitness G of eq 3.17 (with each factor's s and g, eqs 3.18-3.19) and the day's growth D "
      "(eq 3.20) at one place, for one species or all three, as one JSON object");
  auto fo = std::make_shared<FitnessOptions>();
  fitness->add_option("--species", fo->species,
                      "gingoke, haigoke or sugigoke (default: all three)");
  AddNumberFlag(fitness, "--Ts", &fo->T_s, kSurfaceTRange,
                "Surface temperature T_s (K), " + RangeHelp(kSurfaceTRange))
      ->required();
  AddNumberFlag(fitness, "--rhs", &fo->rh_s, kSurfaceRhRange,
                "Surface humidity rh_s (may exceed 1), " + RangeHelp(kSurfaceRhRange))
      ->required();
  AddNumberFlag(fitness, "--S", &fo->S, kLightRange, "Light S (W/m2), " + RangeHelp(kLightRange))
      ->required();
  AddStateOptions(fitness, &fo->state);
  commands.push_back({fitness,
                      [fo](std::ostream& out) { return RunFitness(*fo, out); },
                      {"--species", "haigoke", "--Ts", "286", "--rhs", "1", "--S", "20"}});
}

}  // namespace niwa::cli
