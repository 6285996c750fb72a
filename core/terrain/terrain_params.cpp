// The terrain table and its figure presets (paper values in docs/terrain-model.md).
#include "terrain/terrain_params.h"

#include "math/det_math.h"
#include "params/embedded_presets.h"
#include "params/param_text.h"

namespace niwa::terrain {
namespace {

using P = TerrainParam;
constexpr int Id(P p) { return static_cast<int>(p); }
constexpr Stage kGrow = Stage::kGrow;
constexpr Stage kMesh = Stage::kMesh;
constexpr Stage kView = Stage::kView;

}  // namespace

const ParamTable& TerrainTable() {
  static const ParamTable table(
      "terrain",
      {
          {Id(P::kMethod), "method", "", "", 3, 0, 3, true, "method", kGrow,
           "0 simple (§3), 1 midpoint displacement (§4.1), 2 Fourier descriptors (§4.2), 3 "
           "improved "
           "(§4.3)."},
          {Id(P::kJoin), "join", "", "", 3, 0, 3, true, "shrink", kGrow,
           "Valley join: 0 miter (Fig 5a), 1 bevel (5b), 2 round (5c), 3 capped polyline (Fig 7)."},
          {Id(P::kD), "d", "d", "m", 20, 0.01, 100000, false, "shrink", kGrow,
           "Horizontal offset between successive contours."},
          {Id(P::kDh), "dh", "Δh", "m", 10, 0.001, 100000, false, "shrink", kGrow,
           "Contour interval."},
          {Id(P::kH0), "h0", "h_0", "m", 0, -100000, 100000, false, "shrink", kGrow,
           "Elevation of the seed contour."},
          {Id(P::kC), "c", "c", "", 3, 1, 100, false, "shrink", kGrow,
           "Fig 7 cap: the join point lies at most c·d (= d') from the valley vertex."},
          {Id(P::kD2), "d2", "d''", "d", 0.5, 0, 10, false, "midpoint", kGrow,
           "Cap of one midpoint displacement, as a multiple of d (Fig 12)."},
          {Id(P::kThetaMin), "theta_min", "θ_min", "deg", 20, 0, 89, false, "midpoint", kGrow,
           "Smallest displacement angle θ (Fig 12)."},
          {Id(P::kThetaMax), "theta_max", "θ_max", "deg", 40, 0, 89, false, "midpoint", kGrow,
           "Largest displacement angle θ (Fig 12)."},
          {Id(P::kNfft), "nfft", "n", "", 1024, 16, 16384, true, "fourier", kGrow,
           "FFT samples (equal edges) per contour (§4.2: 1,024)."},
          {Id(P::kF0), "f0", "f_0", "", 256, 1, 8192, true, "fourier", kGrow,
           "Phases of every component with |k| ≥ f0 are randomised; at most nfft/2."},
          {Id(P::kPhaseAmp), "phase_amp", "a", "rad", det::kPi, 0, det::kPi, false, "fourier",
           kGrow, "Phase noise: arg c(k) + U(−a, a); π is a fully random phase."},
          {Id(P::kLongFrac), "long_frac", "", "", 0.2, 0.01, 1, false, "fourier", kGrow,
           "§4.3 step 1.3: collinear points are removed until this share of edges is ≥ 2·d0."},
          {Id(P::kLoopMethod), "loop_method", "", "", 2, 1, 2, true, "loops", kGrow,
           "§4.4 loop removal: 1 delete small faces, 2 cut from each crossing to its twin."},
          {Id(P::kLoopFaces), "loop_faces", "T", "", 5, 3, 100000, true, "loops", kGrow,
           "Method 1: faces with fewer segments are deleted (Fig 18: any value > 4)."},
          {Id(P::kLoopRun), "loop_run", "T_2", "", 5, 1, 100000, true, "loops", kGrow,
           "Method 2: the walk starts on a run of at least this many points."},
          {Id(P::kCleanLen), "clean_len", "", "d", 0.05, 0, 1, false, "shrink", kGrow,
           "Fig 8 pre-clean: a point of an edge shorter than this (× d) is dropped."},
          {Id(P::kCleanAngle), "clean_angle", "", "deg", 10, 0, 60, false, "shrink", kGrow,
           "Fig 8 pre-clean: a vertex whose angle is sharper than this is dropped."},
          {Id(P::kMaxLevels), "max_levels", "", "", 1000, 1, 10000, true, "method", kGrow,
           "Levels grown at most (the result says truncated when hit)."},
          {Id(P::kDown), "down", "", "", 0, 0, 1000, true, "method", kGrow,
           "Contours grown below the seed by enlarging it (§2, clockwise offset)."},
          {Id(P::kRes), "res", "", "cells", 256, 8, 4096, true, "surface", kMesh,
           "Heightfield cells along the longer side of the mountain."},
          {Id(P::kTint), "tint", "", "", 1, 0, 1, true, "surface", kView,
           "Hypsometric vertex colours on the mesh (1) or plain grey (0)."},
          {Id(P::kDhRatio), "dh_ratio", "q", "", 1, 0.5, 2, false, "shrink", kGrow,
           "Profile: the interval from level k to k + 1 is Δh·q^k; above 1 the peaks are steeper "
           "than the foothills, below 1 gentler (1: the paper's equal intervals)."},
          {Id(P::kErosion), "erosion", "", "", 0, 0, 3, true, "erosion", kMesh,
           "Erosion of the grown surface (beyond the paper): 0 off, 1 thermal, 2 hydraulic, 3 "
           "both. "
           "Re-run on the kept surface when only an erosion row changes."},
          {Id(P::kErosionIterations), "erosion_iterations", "", "", 20, 1, 1000, true, "erosion",
           kMesh, "Erosion passes (each: thermal, then hydraulic, as erosion says)."},
          {Id(P::kErosionTalus), "erosion_talus", "", "deg", 35, 1, 89, false, "erosion", kMesh,
           "Thermal: material on a slope to a neighbour steeper than this slips down (talus)."},
          {Id(P::kErosionCapacity), "erosion_capacity", "K_c", "m", 1, 0, 10, false, "erosion",
           kMesh,
           "Hydraulic: sediment water can carry, per cell of rain drained and unit slope (m over "
           "a cell)."},
          {Id(P::kErosionSolubility), "erosion_solubility", "K_s", "", 0.3, 0, 1, false, "erosion",
           kMesh, "Hydraulic: share of the capacity's deficit a cell loses to the water per pass."},
          {Id(P::kErosionDeposition), "erosion_deposition", "K_d", "", 0.3, 0, 1, false, "erosion",
           kMesh, "Hydraulic: share of the capacity's excess the water drops on a cell per pass."},
          {Id(P::kErosionEvaporation), "erosion_evaporation", "K_e", "", 0.01, 0, 0.99, false,
           "erosion", kMesh, "Hydraulic: share of the water lost at each cell it passes."},
      },
      {{"method", "Method"},
       {"shrink", "Shrinking (Figs 5-8)"},
       {"midpoint", "Midpoint displacement (§4.1)"},
       {"fourier", "Fourier descriptors (§4.2-4.3)"},
       {"loops", "Loops (§4.4)"},
       {"surface", "Surface"},
       {"erosion", "Erosion (beyond the paper)"}});
  return table;
}

const ParamTable& TableOf(TerrainParam) { return TerrainTable(); }

const char* MethodName(int method) {
  static const char* names[] = {"simple", "midpoint", "fourier", "improved"};
  return method >= 0 && method < 4 ? names[method] : "";
}
int MethodFromName(const std::string& name) {
  for (int i = 0; i < 4; ++i)
    if (name == MethodName(i)) return i;
  return -1;
}
const char* JoinName(int join) {
  static const char* names[] = {"miter", "bevel", "round", "capped"};
  return join >= 0 && join < 4 ? names[join] : "";
}
int JoinFromName(const std::string& name) {
  for (int i = 0; i < 4; ++i)
    if (name == JoinName(i)) return i;
  return -1;
}

// core/terrain/presets/figure_presets.json (embedded; docs/terrain-model.md), read once.
const std::vector<FigurePreset>& FigurePresets() {
  static const std::vector<FigurePreset> presets = [] {
    std::vector<FigurePreset> out;
    for (const ListedPreset& p : StudyPresetLists("terrain", TerrainTable())) {
      FigurePreset preset{p.name, p.caption, {}};
      for (const auto& [key, value] : p.values)
        preset.values.emplace_back(static_cast<TerrainParam>(*TerrainTable().Find(key)), value);
      out.push_back(std::move(preset));
    }
    return out;
  }();
  return presets;
}

Status ApplyPreset(const std::string& name, TerrainParams* params) {
  std::string key = name;
  if (name == "simple") key = "fig9c";
  if (name == "midpoint") key = "fig13b";
  if (name == "fourier") key = "fig15";
  if (name == "improved") key = "fig16";
  for (const FigurePreset& p : FigurePresets()) {
    if (key != p.name) continue;
    for (const auto& [row, value] : p.values) NIWA_RETURN_IF_ERROR(params->Set(row, value));
    return Status::Ok();
  }
  return Status::Error("preset", "'" + name +
                                     "' is unknown; must be simple, midpoint, fourier, improved, "
                                     "fig9a-c, fig10a-b, fig13a-c, fig14a-c, fig15 or fig16");
}

Status CheckTerrainParams(const TerrainParams& p) {
  if (p.GetInt(P::kF0) > p.GetInt(P::kNfft) / 2) {
    return Status::Error("f0", FormatNumber(p.Get(P::kF0)) +
                                   " is out of range; must be a whole "
                                   "number in [1, nfft/2 = " +
                                   std::to_string(p.GetInt(P::kNfft) / 2) + "]");
  }
  if (p.Get(P::kThetaMin) > p.Get(P::kThetaMax)) {
    return Status::Error("theta_min", FormatNumber(p.Get(P::kThetaMin)) +
                                          " is out of range; must be a number in [0, theta_max = " +
                                          FormatNumber(p.Get(P::kThetaMax)) + "]");
  }
  return Status::Ok();
}

}  // namespace niwa::terrain
