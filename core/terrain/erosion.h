// An optional erosion pass on the grown heightfield (issue 31 item 3, beyond the paper; docs/
// terrain-model.md "Erosion (beyond the paper)"): thermal (talus slippage: Musgrave, Kolb & Mace
// 1989 §4; Olsen 2004 §3.1) and hydraulic (one cell of rain a cell, routed downhill to the lower
// neighbours in shares ∝ slope⁴ (Holmgren 1994), a sediment capacity ∝ water × slope (Musgrave
// et al. 1989 §5), erosion below it and deposition above it, cells taken from the top down in
// one topological order a pass as stream-power landscape models do (Braun & Willett 2013), flats
// crossed towards their way down (Garbrecht & Martz 1997), closed basins filled as lakes by a
// priority flood (Barnes, Lehman & Mulla 2014)). Deterministic (no RNG; every order is by height
// and cell index), volume-conserving (Σh after + what left the grid at its edge = Σh before,
// within rounding; a load reaches the edge only across a flat of the plain) and with no new pits
// (each pass ends by levelling every new strict minimum with its lowest neighbour: both take
// their mean, volume kept). Also the D8 drainage measures the tests and --stats use.
// Why hand-written: no erosion library builds for both targets in our toolchain (/work/shared/
// TOOLCHAIN.md lists none; the usual ones are Python or GPU code), and the pass must use only
// +, −, ×, ÷ and sqrt so that native and WASM give the same bytes.
// Does not: change the contours, the band map or anything but the heights; model water depth,
// rivers as lines, or time (iterations are passes, not years); scale with res (its rain and
// capacity are per cell, so a finer grid cuts more).
#pragma once

#include <vector>

#include "base/status.h"
#include "terrain/heightfield.h"
#include "terrain/terrain_params.h"

namespace niwa::terrain {

enum class ErosionMode : int { kOff = 0, kThermal = 1, kHydraulic = 2, kBoth = 3 };

struct ErosionParams {
  int mode = 0;           // ErosionMode
  int iterations = 20;    // passes; each: thermal, then hydraulic (as the mode says)
  double talus_deg = 35;  // thermal: material above this slope to a neighbour slips
  double capacity = 1.0;  // hydraulic Kc: sediment (m over a cell) per cell of water and unit slope
  double solubility = 0.3;    // Ks: share of the capacity's deficit a cell loses per pass
  double deposition = 0.3;    // Kd: share of the capacity's excess a cell gains per pass
  double evaporation = 0.01;  // share of the water lost at each cell it passes
};

// D8 flow (each cell to its steepest strictly lower neighbour, distances 1 and √2 cells) over the
// whole grid; measured on the mountain's cells (band ≥ 0).
struct DrainageMeasure {
  double threshold = 0;          // cells: a channel cell drains at least this many (cells / 100)
  double channel_share = 0;      // share of the mountain's cells that are channel cells
  double max_accumulation = 0;   // cells draining through the busiest mountain cell
  double mean_accumulation = 0;  // mean over the mountain's cells (the mean flow-path length)
};
// Each cell's D8 accumulation (itself included), in cells.
std::vector<double> D8Accumulation(const Heightfield& hf);
DrainageMeasure MeasureDrainage(const Heightfield& hf);

// Strict local minima among the cells with 8 neighbours (all 8 strictly higher), any band.
int CountStrictPits(const Heightfield& hf);

struct ErosionReport {
  double volume_moved = 0;  // m³ taken from the cells that went down (Σ of their cuts · cell²)
  double volume_laid = 0;   // m³ laid on the cells that went up; moved = laid + exported
  double max_cut = 0;       // m: the deepest lowering of a cell
  double max_deposit = 0;   // m: the largest raise of a cell
  double sum_before = 0, sum_after = 0;  // Σh (m): sum_after + exported = sum_before (rounding)
  double exported = 0;         // Σh (m) of the load that left the grid at its edge, across a flat
  double volume_exported = 0;  // the same in m³
  int pits_before = 0, pits_after = 0;  // CountStrictPits
  int pits_levelled = 0;  // new strict minima the final step levelled with a neighbour
  DrainageMeasure drainage_before, drainage_after;
};

// The erosion rows of the terrain table (their ranges are the table's).
ErosionParams ErosionParamsOf(const TerrainParams& params);
// Each value against its row's range: the table's one line naming the key ("erosion_talus").
Status CheckErosionParams(const ErosionParams& p);
// Erodes hf in place (mode kOff: nothing, an empty report but the sums and pits).
ErosionReport Erode(const ErosionParams& p, Heightfield* hf);

// Adds to target (another grid over the same ground, e.g. HeightmapGrid's) the erosion's change
// eroded − raw, interpolated bilinearly at target's cell centres (clamped to raw's extent).
void AddErosionChange(const Heightfield& raw, const Heightfield& eroded, Heightfield* target);

}  // namespace niwa::terrain
