// The bark study's parameter table ("bark"; Hirota, Kato, Kaneko c. 1997, paper 003;
// ../shared/specs/bark.md §2): Table 1's growth and material rows (ρ, σ, D, L_o, T, ΔR, ΔH), Table
// 2's species constants (E_1, E_2, G, κ̄_1, κ̄_2), Table 4's peeling constants (κ_h, η, γ, A; read
// by the 4-layer model) and its cork made per cycle, the lattice (N_R × N_H), growth cycles,
// settling steps, damping ratios and the maps' size, each with the paper's symbol, unit, range and
// stage; the species presets camphor, tallow, pine (core/bark/presets/bark_presets.json); the
// cross-row checks. Does not: simulate (lattice.h, springs.h), draw (bark_maps.h), hold a run's
// state (seed, model: bark_state.h) or parse text (params/, io/hash_codec).
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "base/status.h"
#include "params/param_table.h"

namespace niwa::bark {

// One entry per row of the bark table, in panel order within each group.
enum class BarkParam : int {
  // growth (Table 1)
  kRho,
  kSigma,
  kD,
  kLo,
  kT,
  kDeltaR,
  kDeltaH,
  kCycles,
  kSettleSteps,
  // species (Table 2)
  kE1,
  kE2,
  kG,
  kKappa1,
  kKappa2,
  // damping (not in the paper; spec §1.5)
  kZetaS,
  kZetaT,
  // lattice (§3.1 formulas H_o = L_o·N_H, R_o = √3·L_o·N_R/4π)
  kNR,
  kNH,
  // peeling (Table 4; the 4-layer model)
  kKappaH,
  kEta,
  kGamma,
  kA,
  kCork,
  // maps (spec §1.9)
  kMapSize,
  kCount
};

const ParamTable& BarkTable();
const ParamTable& TableOf(BarkParam);
using BarkParams = StudyParams<BarkParam>;

// Largest lattice (nodes) a state may ask for; the budget usually refuses earlier.
constexpr int kMaxNodes = 1 << 20;

// Cross-row checks the ranges cannot state: N_R even (the triangular lattice wraps around the
// trunk only with an even column count), map_size a power of two. The error names the row.
Status CheckBarkParams(const BarkParams& params);

// The species presets, in the order `niwa presets bark` prints them (camphor, tallow, pine).
const std::vector<std::string>& BarkPresetNames();
// The preset's source line; "" when unknown.
std::string BarkPresetSource(std::string_view name);
// The table defaults with the preset's values; the error names "species" and the allowed names.
Result<BarkParams> BarkPreset(std::string_view name);
// The values one preset sets, as (key, value) pairs (for printing).
std::vector<std::pair<std::string, double>> BarkPresetValues(std::string_view name);
// "camphor, tallow or pine".
std::string BarkPresetList();

}  // namespace niwa::bark
