// Yearly growth loop of thesis 2.4: bud break, light, hormone, elongation and bending, next year's
// buds.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "random/pcg32.h"
#include "tree/light.h"
#include "tree/prune.h"
#include "tree/tree.h"
#include "tree/tree_budget.h"
#include "tree/tree_params.h"

namespace niwa {

struct GrowRequest {
  std::string preset;
  TreeParams params;
  uint64_t seed = 1;
  int years = 10;
  std::vector<Prune> prunes;
  GrowLimits limits;  // unlimited unless set (the CLI and the page set a budget)
};

// Cosine and sine of a rotation angle.
struct CosSin {
  float c = 1.0f, s = 0.0f;
};

// A shoot being laid out node by node (step 4 of 2.4.3): its current direction, phyllotaxis
// azimuth, bending target v (eq. 2.5) and rate b (eq. 2.4).
struct ShootLayout {
  Branch* shoot = nullptr;
  glm::vec3 direction, azimuth, target;
  float b = 0.0f;
};

// Grows a tree one year at a time, so callers can show every age and report progress.
class Grower {
 public:
  explicit Grower(const GrowRequest& request);
  // Grows one more year (thesis 2.4 steps 1-5) and applies the prunes of that year: StartYear()
  // then FinishYear() without foreign shade.
  void GrowYear();
  // GrowYear in two halves, for trees grown together (core/compose/tree_neighbours), which trade
  // their leaf spheres between the halves. StartYear: the budget check (which may stop the growth),
  // bud break and this year's shoots laid out straight (2.4.3 steps 1 and 4 before light), so that
  // leaf_spheres() are this year's. FinishYear: the light of those spheres shaded also by
  // `foreign_shade` (other trees' leaf spheres in this tree's frame, cm, its trunk foot at the
  // origin; they receive no light), then steps 3-5 and the year's prunes (also when a limit met in
  // the bud break stopped the years after). Each does nothing out of turn (StartYear twice, or
  // FinishYear with no year started); with no foreign shade the pair is GrowYear, bit for bit.
  void StartYear();
  void FinishYear(const std::vector<LeafSphere>& foreign_shade = {});
  // The leaf spheres of the year last started, the ones its light model lights and is shaded by
  // (thesis 2.3.2: one per shoot of the year, around the shoot laid out straight, radius half its
  // length plus half a leaf), in this tree's frame (cm). Empty before the first year.
  const std::vector<LeafSphere>& leaf_spheres() const { return leaf_spheres_; }
  int year() const { return tree_.years; }
  const Tree& tree() const { return tree_; }
  Tree TakeTree() { return std::move(tree_); }
  const GrowthTimings& timings() const { return timings_; }
  // True once a limit of request.limits stopped the yearly loop (Tree::truncated_by says which);
  // GrowYear then does nothing.
  bool stopped() const { return stopped_; }
  // Memory and time the growth so far is estimated to have used (request.limits' constants).
  Estimate estimate() const;

 private:
  void BreakBuds();  // step 1
  // Step 4 geometry of this year's living shoots (also straight, before light).
  void LayOutShoots(bool bend);
  void ComputeLight(const std::vector<LeafSphere>& foreign_shade);  // step 2
  void MakeLeafSpheres();  // leaf_spheres_ of this year's shoots
  void ComputeHormone();   // step 3
  void ThickenBranches();  // 2.4.4
  void SetNextYearBuds();  // step 5, including dormancy break (2.4.6)
  void ApplyPrunes();
  void RaiseCrown();
  // Basal shoots of this year (docs/tree-species.md), made by BreakBuds's make_shoot.
  template <typename MakeShoot>
  void MakeBasalShoots(MakeShoot& make_shoot);
  // True for the seedling and its chain of terminal shoots (the leader).
  bool OnLeader(const Branch& shoot) const;
  void Kill(int branch_id);

  GrowRequest request_;
  Tree tree_;
  GrowthTimings timings_;
  std::vector<int> new_shoots_;    // ids of this year's shoots
  std::vector<int> flowering_;     // ids of the branches with flowers this year
  std::vector<int> kept_foliage_;  // ids whose last year's leaves a budget-cut year kept
  long refused_shoots_ = 0;        // shoots a limit refused (Truncate calls)
  std::vector<CosSin> bud_turns_;  // SetNextYearBuds: turn of each bud awaiting TurnBuds
  std::vector<int> breaking_;      // ids of the branches with a bud to break next year, ascending
  std::vector<float> turn_cos_, turn_sin_;  // phyllotaxis turn 2πϕ·i per node index i
  // Fixed angles of the parameters, computed once per tree: bending caps θ_bmax^b, θ_bmax^N
  // (eqs. 2.7, 2.9), the sympodial turn −θ_N, bud angles ψ_t, ψ_tl, ψ_l, and the turns 2π·k/B
  // around a node for leaves, terminally-lateral and lateral buds.
  CosSin cap_branch_, cap_node_, sympodial_turn_, psi_t_, psi_tl_, psi_l_;
  std::vector<CosSin> around_leaves_, around_tl_, around_laterals_;
  long internodes_ = 0;
  int basal_made_ = 0;  // basal shoots made so far (each turns a golden angle from the last)
  double made_internodes_ = 0;  // every internode made, dead or alive (they stay in memory)
  double made_branches_ = 0;
  double internode_years_ = 0;  // Σ over the years grown of the alive internodes
  bool stopped_ = false;
  // Sets tree_.truncated and, the first time, the line naming `limit`.
  void Truncate(const std::string& limit, const std::string& why, const std::string& change);
  std::vector<int> kill_stack_;  // Kill's work list
  LightGridBuffers light_buffers_;
  std::vector<LeafSphere> leaf_spheres_;
  bool year_started_ = false;  // StartYear ran and FinishYear has not yet
  double ms_started_ = 0;      // StartYear's bud break and straight layout, for the timings
  Pcg32 rng_;
};

// Convenience: grows request.years years in one call.
Tree GrowTree(const GrowRequest& request, GrowthTimings* timings = nullptr);

// Hormone-dependent ranges of table 2.2 ("a ~ b"): value at H = 0 is `low`, at H >= H_sat `high`.
float HormoneRamp(const ParamSet& params, float hormone, ParamId low, ParamId high);
// N or D of a new shoot with initial hormone H⁰ (fig. 2.5, 2.4.3 step 1): HormoneRamp's share t of
// the range, moved by `length_step` j away from the dwarf threshold H_s: (1 − j)·t for a dwarf
// shoot, t + j·(1 − t) for a long one.
float ShootLengthRamp(const ParamSet& params, float hormone_initial, bool dwarf, ParamId low,
                      ParamId high);
// Break probability of a bud with maximum p_dwarf / p_long on a shoot of hormone H (fig. 2.8).
float BreakProbability(float hormone, float h_short, float h_sat, float p_dwarf, float p_long);
// Largest lateral-bud break probability P_l at a tree age in years (fig. 2.9).
float LateralBreakMax(const ParamSet& params, int year);

struct BreakChances {
  float terminal = 1, terminally_lateral = 0, lateral = 0;
};
// The sky the growth model lights its shoots with: the sun and sky rows of the parameters.
Sky GrowthSky(const ParamSet& params);

// Next year's break probability of each kind of bud on a shoot (2.4.5); the maxima without hormone.
BreakChances BudBreakChances(const ParamSet& params, float hormone, int year);

}  // namespace niwa
