// The 4-layer model (paper 003 §4, Figs 6-8, Table 4; ../shared/specs/bark.md §1.7-1.8): three
// spring layers, surface S, intermediate M1 and intermediate M2, each a full lattice (the 2-layer
// model's torus, same (i, j) indexing) over the kinematic inner layer I, with shear springs S→M1,
// M1→M2 and M2→I at equal (i, j). Radial positions follow Fig. 7 (layers.h: r_I linear, M2
// thickening 0 → d_c within a cycle, M1 and S of thickness d_c outside it; each layer's nodes at
// its mid-radius, its anchors scaled with it). M2's stiffness and mass follow its thickness
// (D·τ, floored at 0.05·D). Every spring of every layer breaks by the 2-layer law. At the start of
// each cycle after the first the roles move outward: what is left of S is SHED (its plates and
// area counted), M1 → S, M2 → M1, and a new M2 is born at r_I with thickness 0, stress free, its
// thresholds drawn from that cycle's PCG32 stream. Peeling (Table 4): the S→M1 shear springs
// break when a node's shear strain |slip − slip at bond birth|/D passes its limit κ_h(1 + σξ),
// which decays as exp(−γ·Δt/T) from the time the node first lies within η of a broken S spring
// or a peeled node (drying); every 100 steps the closed regions of S (its plates, as the region
// measure and the maps see them, not wrapping the torus) with S_r/S_b > A (or no bond at all)
// peel: their nodes leave S and M1 shows beneath. Deterministic like the 2-layer model (float32
// state, fixed order). Does not: schedule a run's cycles, budgets or outputs (bark_run.h), draw
// (bark_maps.h), model radial motion or curl, or break the M1→M2 and M2→I shear springs (spec
// §1.6).
#pragma once

#include <cstdint>
#include <vector>

#include "bark/bark_params.h"
#include "bark/lattice.h"
#include "bark/springs.h"
#include "bark/step_lanes.h"

namespace niwa::bark {

constexpr int kPeelCheckSteps = 100;  // the area rule and the drying run every 100 steps

// The constants of a 4-layer run.
struct FourLayerMechanics {
  Mechanics base;  // the 2-layer constants at thickness D (k, c, k_s, c_s, mass, κ̄, σ)
  double dt = 0;   // 0.3·√(m/K) at the stiffest layer (M2 at its 0.05·D floor), T/dt whole
  int steps_per_cycle = 0;
  double r_o = 0;      // the lattice radius: where a layer's spacing is the lattice's
  double delta_r = 0;  // ΔR: inner radius growth per cycle (cm) = dR·R_o
  double cork = 0;     // d_c: cork thickness made per cycle (cm) = cork·D
  double d = 0;        // D (cm)
  double period = 0;   // T (s)
  double kappa_h = 0, eta = 0, gamma = 0, area_ratio = 0;  // Table 4
};
FourLayerMechanics FourLayerMechanicsOf(const BarkParams& params, const Lattice& lattice);

// Roles, outermost first.
enum Role : int { kS = 0, kM1 = 1, kM2 = 2 };

// One spring layer and its bond (shear springs) to the layer beneath.
struct CorkLayer {
  Surface s;
  int born = 0;                  // the cycle that bore it (the initial S and M1: −2 and −1)
  double rest[2] = {0, 0};       // rest lengths of its axial and diagonal springs (cm)
  std::vector<uint8_t> present;  // 1 while the node belongs to the layer; 0 once peeled (S)
  std::vector<uint8_t> bonded;   // its shear spring to the layer beneath is intact
  std::vector<float> bond_x, bond_z;  // slip (u − u_below) when that bond was made
  std::vector<float> kappa_h;         // the bond's critical shear strain κ_h(1 + σξ)
  std::vector<int> dry_step;          // step at which drying began near the node (−1: not yet)
  std::vector<float> shear_limit2;    // (κ_h,i(t)·D)², refreshed every kPeelCheckSteps
};

// Per-role view of the layout at one instant.
struct LayerGrowth {
  Growth g[3];              // anchor scale factors and their rates, per role
  double mid[3];            // mid-radius per role (cm)
  double r_inner = 0;       // r_I
  double thickness_m2 = 0;  // d_c·τ: M2's radial thickness (for the height map)
  double stiffness_m2 = 0;  // M2's mechanical thickness share max(τ, 0.05)
};

struct FourLayer {
  FourLayerMechanics m;
  CorkLayer layer[3];  // indexed by Role
  int step = 0;        // steps integrated
  int cycle = 0;       // role exchanges done (= the cycle the layout is in)
  int growth_steps = 0;
  // Tallies over the run.
  int bonds_broken = 0;  // S→M1 shear springs broken
  int peel_events = 0, peeled_nodes = 0;
  int shed_regions = 0, shed_nodes = 0;
  int first_peel_step = -1, first_crack_step = -1;
  // The node's springs (CSR over the lattice), for peeling a node out of S.
  std::vector<int32_t> node_spring_start, node_springs;
};

// The three layers at rest at t = 0 (S, M1, M2 born at cycles −2, −1, 0, each stress free at its
// mid-radius), for `cycles` growth periods.
FourLayer StartFourLayer(const Lattice& lattice, const FourLayerMechanics& m, uint64_t seed,
                         int cycles);

// The layout at the model's current step (growth frozen after growth_steps).
LayerGrowth LayerGrowthAt(const FourLayer& f);

// One step of all three layers; every kPeelCheckSteps steps the drying and the area rule (after
// the step). True when the step ended a growth cycle: the caller then exchanges the roles if
// another cycle follows (step < growth_steps). With lanes, the spring pass and the node pass are
// each split in two halves of the nodes, one a lane (step_lanes.h): the same bits as without.
bool StepFourLayer(const Lattice& lattice, FourLayer* f, StepLanes* lanes = nullptr);

// Role exchange now: S shed (counted), M1 → S, M2 → M1, a new M2 born at r_I from cycle
// f->cycle + 1's stream.
void ExchangeRoles(const Lattice& lattice, uint64_t seed, FourLayer* f);

// Drying onsets, shear limits and the area rule on S now (what every kPeelCheckSteps does). With
// lanes, the drying and the measure of S's plates run as two chunks (the same bits).
void CheckPeeling(const Lattice& lattice, FourLayer* f, StepLanes* lanes = nullptr);

// S's nodes still present.
int PresentNodes(const FourLayer& f);

// Which layer shows in each triangle: 0 = S, 1 = M1, 2 = M2, 3 = the inner layer (the first role
// whose triangle has three intact springs; a peeled S node's springs count as broken).
std::vector<uint8_t> VisibleLayer(const Lattice& lattice, const FourLayer& f);

}  // namespace niwa::bark
