// The tree study's parameter table ("tree"): growth (thesis ch. 2), sway and wind (ch. 3) and
// rendering (ch. 4) rows, with their bare keys (alpha_t, wind_speed, ...) as old links, JSON files
// and CLI flags use them. Does not: parse text or JSON (params/, io/hash_codec) or grow anything.
//
// A study copies this pattern: an enum with one value per row and kCount, TableOf(enum) returning
// its ParamTable, and a StudyParams<enum> alias for the values it stores.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

#include "params/param_table.h"

namespace niwa {

// One entry per parameter; the order is the order of the web panel within each group.
enum class TreeParam : int {
  // hormone model (thesis 2.4.2, eqs. 2.1-2.3)
  kAlphaT,
  kAlphaTl,
  kAlphaL,
  kBetaC,
  kBetaP,
  kHS,
  kHL,
  kGamma,
  kHShort,
  kHInit,
  kHSat,
  // branching model (thesis 2.3.1, table 2.1)
  kNLow,
  kNHigh,
  kDLow,
  kDHigh,
  kDwarfInternodeRatio,
  kLengthStep,
  kBT,
  kBTl,
  kBL,
  kPhi,
  kThetaN,
  kSympodial,
  kPsiT,
  kPsiTl,
  kPsiL,
  kPTlS,
  kPTlL,
  kPLYoung,
  kPLOld,
  kPLYears,
  kDwarfLateralFlowers,
  kClearStem,       // not in the thesis: nursery crown raising (docs/tree-species.md)
  kTrimHeight,      // not in the thesis: hanging shoots cut above the ground (docs/tree-species.md)
  kStandardHeight,  // not in the thesis: the leader trained up a stake (docs/tree-species.md)
  kBasalShoots,     // not in the thesis: shoots from the root collar (docs/tree-species.md)
  kBasalYears,      // the last year basal shoots break
  kBH,              // not in the thesis: plagiotropism of side shoots (docs/tree-species.md)
  // light model (thesis 2.3.2, 2.4.1)
  kUseLight,
  kKDeath,
  kSphereOpacity,
  kSunElevation,
  kSunAzimuth,
  kSunWeight,
  kSkyZenithRatio,
  kLightScale,
  // bending (thesis 2.4.3, eqs. 2.4-2.9)
  kBLLow,
  kBLHigh,
  kBGLow,
  kBGHigh,
  kThetaBmaxN,
  kThetaBmaxB,
  kBLByLight,
  // dormancy break (thesis 2.4.6)
  kHBL,
  kDeltaL,
  kBBL,
  kHNL,
  kHBD,
  kDeltaD,
  kBBD,
  kHND,
  // shape (thickness, leaves) and limits
  kUseHormone,
  kPipeAreaPerLeaf,
  kLeafSize,
  kMaxInternodes,
  // wind sway, node-point model (thesis ch. 3, eqs. 3.1-3.16, table 3.1; docs/sway-model.md)
  kKWind,
  kKDirTrunk,
  kKDirTip,
  kKRev,
  kKVdel,
  kWoodDensity,
  kMLeaf,
  kSLeaf,
  kSwayAlpha,
  kGravity,
  kGravityPreload,
  kSwayDt,
  kOmitLimit,
  // wind: the thesis's sudden gust (3.5) and a field varying in space and time (not in the thesis)
  kWindSpeed,
  kWindDir,
  kGustOn,
  kGustOff,
  kGustFrontSpeed,
  kWindVariation,
  kWindWavelength,
  kWindPeriod,
  kSwayDuration,
  // rendering (thesis chapter 4, docs/rendering-model.md)
  kRenderMode,        // 0: full polygons, 1: hybrid cards + lines
  kLineThreshold,     // eq. 4.1 threshold on D_i, px
  kCardPlanes,        // card planes per branch
  kLeafClusterCards,  // 1: leaf-cluster cards (thesis 5.2), 0: leaves on branch cards (4.2.1)
  // look (not in the thesis; core/tree/tree_look.h): leaf shape, season, autumn colour
  kLeafShape,
  kLeafCard,   // not in the thesis: the drawn leaf card over leaf_size (a pine's needle fascicle)
  kLeafSpray,  // not in the thesis: leaves painted on each drawn card (a twig with n leaves)
  kSeason,
  kAutumnColour,
  // flowers (not in the thesis; core/tree/tree_look.h, growth.cpp): colour and form of the flower
  // cards, and terminal flower buds (Rhododendron)
  kFlowerColour,
  kFlowerForm,
  kTerminalFlowers,
  // bark (not in the thesis; core/compose/bark_on_tree: the bark study on the tree's trunk)
  kBark,       // 0: the procedural texture, 1: the bark study's maps
  kBarkModel,  // 2: the 2-layer model, 4: the 4-layer model
  kCount
};

// The tree's table (name "tree"), indexed by TreeParam.
const ParamTable& TreeParamTable();
inline const ParamTable& TableOf(TreeParam) { return TreeParamTable(); }
// Every value of the tree table; default-constructed at the table defaults.
using TreeParams = StudyParams<TreeParam>;

constexpr std::size_t kParamCount = static_cast<std::size_t>(TreeParam::kCount);
// The tree code's older name for TreeParam (growth, sway and render read rows through it).
using ParamId = TreeParam;

inline const ParamSpec& Spec(TreeParam id) {
  return TreeParamTable().row(static_cast<std::size_t>(id));
}
// Finds a tree parameter by its key; nullopt when unknown.
std::optional<TreeParam> FindParam(std::string_view key);

}  // namespace niwa
