// The moss study's parameter table ("moss"; Nomura 2010, paper 001; ../shared/specs/moss.md §2):
// the weather of table 4.3, the soil laws of table 3.4, the constants of tables 3.5 and 3.6, the
// light, the life cycle, and the three species of table 4.2 as rows, each with the thesis's symbol,
// unit, range and stage; the presets nomura2010 (the literal equations) and nomura2010-sky (sky
// light and sky-view longwave, spec §3.1) from core/moss/presets/; typed views of the rows the soil
// and fitness models read; the cross-row checks. Does not: compute soil or fitness (soil.h,
// fitness.h), parse text or JSON (params/, io/hash_codec), or hold a run's state (days, seed).
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "base/status.h"
#include "moss/moss.h"
#include "params/param_table.h"

namespace niwa::moss {

// One entry per row of the moss table, in panel order within each group (links and JSON carry the
// rows' keys, not these ids).
enum class MossParam : int {
  // climate (table 4.3; table 3.1's inputs)
  kT,
  kRh,
  kPYear,
  kPDays,
  kU,
  kN0,
  kN,
  kSunAltitude,
  kSunAzimuth,
  kRainRandom,
  // soil heat and water (eqs 3.2-3.16, table 3.4, §3.5.2-3.5.3)
  kHumusF1,
  kHumusF2,
  kHumusThetaSat,
  kSandyF1,
  kSandyF2,
  kSandyThetaSat,
  kAsphaltF1,
  kAsphaltF2,
  kAsphaltThetaSat,
  kHMax,
  kHWall,
  kOStart,
  kCHMin,
  kCHMax,
  kRCH,
  kMCH,
  kDeltaForm,
  kLongwave,
  // constants (tables 3.5, 3.6)
  kSigma,
  kP,
  kRef,
  kDAtm,
  kIota,
  kRho,
  kCpRho,
  // light (§3.4, §3.5.1; spec §1.3)
  kPhotons,
  kIndirect,
  kRhoMesh,
  kRhoMoss,
  kMaxBounces,
  kRGather,
  kIBeam,
  kSSky,
  kSunDistance,
  kSunSize,
  kSunPath,
  kLightSmoothingDays,
  // life cycle (§3.3, §3.6, §3.8; spec §1.5)
  kGForm,
  kMaxMosses,
  kSeedCap,
  kNInit,
  kImmigrationDays,
  kMossSize,
  kGemmaStep,
  kSporeG,
  kLSpore0,
  kLSpore1,
  kLGemma0,
  kLGemma1,
  kKGemma,
  kLSporeDistance,
  kInteriorCount,
  kInteriorRadius,
  kOverlap,
  kSoilEdge,
  // species (table 4.2): 13 rows each, gingoke, haigoke, sugigoke in that order
  kSpeciesFirst,
  kCount = kSpeciesFirst + 3 * 13
};

// The columns of a species block (table 4.2), in row order.
constexpr int kSpeciesColumns = 13;
// The row of column `column` (0 T_0 ... 12 τ_d) of a species.
MossParam SpeciesRow(Species species, int column);

const ParamTable& MossTable();
const ParamTable& TableOf(MossParam);
using MossParams = StudyParams<MossParam>;

// delta_form: eq 3.15 as corrected (e_SAT(T) where the thesis prints 6.1078; spec §4.12) or
// literal. longwave: eq 3.3 on every cell (the thesis) or weighted by the cell's sky view (spec
// §3.1). g_form: eq 3.19 clamped to [0, 1] or the normalised form (spec §4.14).
enum class DeltaForm : int { kCorrected = 0, kLiteral = 1 };
enum class Longwave : int { kThesis = 0, kSkyView = 1 };
enum class GForm : int { kClamped = 0, kNormalized = 1 };

// Typed views of the rows the models read.
GeologyLaw GeologyLawOf(const MossParams& params, Geology geology);
SpeciesRanges SpeciesOf(const MossParams& params, Species species);

// Cross-row checks the ranges cannot state: N ≤ N_0, C_Hmin ≤ C_Hmax, each species' T_0 < T_1,
// rh_0 < rh_1, S_0 < S_1, and the germination windows L_0 < L_1. The error names the row.
Status CheckMossParams(const MossParams& params);

// The preset names, in the order `niwa presets moss` prints them (nomura2010, nomura2010-sky).
const std::vector<std::string>& MossPresetNames();
// The preset's source line (what it reproduces); "" when unknown.
std::string MossPresetSource(std::string_view name);
// The table defaults with the preset's values; the error names "preset" and the allowed names.
Result<MossParams> MossPreset(std::string_view name);
// The values one preset sets, as (key, value) pairs (for printing).
std::vector<std::pair<std::string, double>> MossPresetValues(std::string_view name);

}  // namespace niwa::moss
