// The one table of model parameters: key, paper symbol, unit, default, range, group and help.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace niwa {

// One entry per parameter; the order is the order of the web panel within each group.
enum class ParamId : int {
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
  kCount
};

constexpr std::size_t kParamCount = static_cast<std::size_t>(ParamId::kCount);

struct ParamSpec {
  ParamId id;
  const char* key;     // stable name used in JSON, URL hash and CLI --set
  const char* symbol;  // the paper's symbol, e.g. "α_t"
  const char* unit;    // "" when dimensionless
  double default_value;
  double min_value;
  double max_value;
  bool integer;       // value must be a whole number
  const char* group;  // "hormone", "branching", "light", "bending", "dormancy_break", "shape",
                      // "sway", "wind"
  const char* help;
};

// The table itself, indexed by ParamId.
const std::array<ParamSpec, kParamCount>& ParamTable();
const ParamSpec& Spec(ParamId id);
// Finds a parameter by its key; nullopt when unknown.
std::optional<ParamId> FindParam(std::string_view key);

// A full set of parameter values, indexed by ParamId.
class ParamSet {
 public:
  ParamSet();  // every value at its table default
  double Get(ParamId id) const { return values_[static_cast<std::size_t>(id)]; }
  int GetInt(ParamId id) const { return static_cast<int>(Get(id)); }
  bool GetBool(ParamId id) const { return Get(id) != 0.0; }
  // Sets a value after checking it; returns an error line naming the key and range, or "" on
  // success.
  std::string Set(ParamId id, double value);
  // Parses text (e.g. from --set key=value or a URL) and sets it; error line or "".
  std::string SetFromText(std::string_view key, std::string_view text);
  bool operator==(const ParamSet& other) const { return values_ == other.values_; }
  bool operator!=(const ParamSet& other) const { return !(*this == other); }

 private:
  std::array<double, kParamCount> values_;
};

// "alpha_t must be a number in [0, 1]" style description of the allowed range.
std::string RangeText(const ParamSpec& spec);
std::string RangeText(double min_value, double max_value, bool integer);
// "" when value lies in [min, max] (and is whole when integer), else the one-line error
// "key: 1.5 is out of range; must be a number in [0, 1]". Shared by every parameter table.
std::string CheckValue(const char* key, double value, double min_value, double max_value,
                       bool integer);
// Shortest text that parses back to exactly the same double.
std::string FormatNumber(double value);
// Strict number parser: whole text must be a finite decimal number.
std::optional<double> ParseNumber(std::string_view text);

}  // namespace niwa
