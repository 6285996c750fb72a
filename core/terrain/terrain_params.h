// The terrain study's parameter table (Misawa, Chiba, Saito 1987; docs/terrain-model.md): one row
// per constant of the contour generation methods and the surface, and the figure presets (Figs 9,
// 10, 13, 14, 15, 16) as row values. Does not: grow anything (generate.h), or hold the RNG seed (a
// state field, as the tree's and the ivy's: terrain_state.h).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "base/status.h"
#include "params/param_table.h"

namespace niwa::terrain {

enum class TerrainParam : int {
  kMethod,    // 0 simple (§3), 1 midpoint (§4.1), 2 fourier (§4.2), 3 improved (§4.3)
  kJoin,      // 0 miter (Fig 5a), 1 bevel (5b), 2 round (5c), 3 capped (Fig 7)
  kD,         // d: offset between successive contours (m)
  kDh,        // Δh: contour interval (m)
  kH0,        // elevation of the seed contour (m)
  kC,         // c: Fig 7 cap, d' = c·d
  kD2,        // d'' as a multiple of d: cap of a midpoint displacement
  kThetaMin,  // θ range (deg) of the midpoint displacement
  kThetaMax,
  kNfft,        // n: FFT samples per contour
  kF0,          // f0: first randomised frequency
  kPhaseAmp,    // a: phase = arg c(k) + U(−a, a)
  kLongFrac,    // share of edges ≥ 2·d0 kept by the collinear removal of §4.3 step 1.3
  kLoopMethod,  // 1 or 2 (§4.4)
  kLoopFaces,   // method 1: delete faces with fewer segments
  kLoopRun,     // method 2: the start run's length
  kCleanLen,    // Fig 8 pre-clean: short edge, as a multiple of d
  kCleanAngle,  // Fig 8 pre-clean: acute angle (deg)
  kMaxLevels,   // level cap
  kDown,        // contours grown below the seed (enlarging, §2)
  kRes,         // heightfield cells along the longer side
  kTint,        // hypsometric vertex colours in the mesh (0/1)
  kDhRatio,     // q: the interval from level k to k + 1 is Δh·q^k (the profile; 1: equal)
  // Erosion (beyond the paper, erosion.h): stage mesh, re-run on the kept heightfield.
  kErosion,             // 0 off, 1 thermal, 2 hydraulic, 3 both
  kErosionIterations,   // passes
  kErosionTalus,        // talus angle (deg)
  kErosionCapacity,     // Kc: sediment per cell of water and unit slope (m)
  kErosionSolubility,   // Ks: share of the capacity's deficit eroded per pass
  kErosionDeposition,   // Kd: share of the capacity's excess deposited per pass
  kErosionEvaporation,  // share of the water lost at each cell it passes
  kCount
};

// The RNG seed's range (TerrainState::seed; one PCG32 stream per contour from it and the
// contour's path) and its value when none is given.
constexpr double kMaxTerrainSeed = 4294967295.0;
constexpr uint64_t kDefaultTerrainSeed = 1;

const niwa::ParamTable& TerrainTable();
const niwa::ParamTable& TableOf(TerrainParam);
using TerrainParams = niwa::StudyParams<TerrainParam>;

enum class Method : int { kSimple = 0, kMidpoint = 1, kFourier = 2, kImproved = 3 };
const char* MethodName(int method);           // "simple", ...
int MethodFromName(const std::string& name);  // −1 when unknown
const char* JoinName(int join);
int JoinFromName(const std::string& name);

// A figure preset: its name ("fig16"), what it reproduces, and its row values.
struct FigurePreset {
  std::string name;
  std::string caption;
  std::vector<std::pair<TerrainParam, double>> values;
};
const std::vector<FigurePreset>& FigurePresets();
// Applies a preset by name ("fig9c") or by method name ("improved" = fig16, "simple" = fig9c,
// "midpoint" = fig13b, "fourier" = fig15); error names the field and the allowed names.
Status ApplyPreset(const std::string& name, TerrainParams* params);

// Cross-row checks the table's ranges cannot state (f0 ≤ n/2, θmin ≤ θmax).
Status CheckTerrainParams(const TerrainParams& params);

}  // namespace niwa::terrain
