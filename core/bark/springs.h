// The 2-layer model's mechanics (paper 003 §3.1; ../shared/specs/bark.md §1.4-1.6): the surface
// layer's nodes tied to a kinematic inner layer that grows (R and H linear in time), springs of
// two families with stiffness from Table 2's moduli, shear springs to the inner layer, dashpots,
// symplectic Euler steps, and breaking: a spring stretched past its own ratio κ_s breaks for good,
// so cracks run by themselves (the load of a broken spring falls on its neighbours). State is the
// displacement u = x − anchor and its rate w (float32, structure of arrays); one pass over the
// springs per step (break checks, in ascending index, on the positions the step starts from;
// then forces) and one over the nodes. Deterministic: the project's PCG32 for the thresholds,
// det:: maths, no FMA contraction. The spring pass takes four springs a batch (math/simd4.h lanes:
// indexed loads, IEEE arithmetic lane by lane, the same bits as the scalar tail), or eight in AVX2
// where the CPU has it and in WASM (BatchLanes, math/simd8.h), writing each spring's force to its
// slot; the node pass the same. Does not: measure regions (regions.h), draw (bark_maps.h),
// schedule cycles or check budgets (bark_run.h), or model radial motion, curl or peeling.
#pragma once

#include <cstdint>
#include <vector>

#include "bark/bark_params.h"
#include "bark/lattice.h"
#include "random/pcg32.h"

// Whether this build also compiles the spring and node passes for AVX2 (x86-64 GCC; chosen at run
// time, BatchLanes).
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define NIWA_BARK_AVX2 1
#else
#define NIWA_BARK_AVX2 0
#endif
// Whether this build has the eight-lane passes at all: the AVX2 ones above, or WASM simd128's,
// where an eight-lane operation is two v128 ones (more independent work a loop turn for V8's code;
// always there, no run-time choice). NIWA_BARK_EIGHT_TARGET marks the eight-lane loops' functions.
#if NIWA_BARK_AVX2
#define NIWA_BARK_EIGHT 1
#define NIWA_BARK_EIGHT_TARGET __attribute__((target("avx2")))
#elif defined(__wasm_simd128__)
#define NIWA_BARK_EIGHT 1
#define NIWA_BARK_EIGHT_TARGET
#else
#define NIWA_BARK_EIGHT 0
#define NIWA_BARK_EIGHT_TARGET
#endif

namespace niwa::bark {

// Springs and nodes a batch of the passes: 8 where the build has the AVX2 path and the CPU AVX2,
// and in WASM simd128 (math/simd8.h: the same IEEE operations lane by lane, so the bits of 4), else
// 4 (SSE2). SetBatchLanes(4 or 8) sets it for the process (8 only where EightLanesAvailable; for a
// test's comparison or a measurement) and returns the previous value.
int BatchLanes();
int SetBatchLanes(int lanes);
bool EightLanesAvailable();

// The constants of one run, from the table (spec §1.5).
struct Mechanics {
  double node_area = 0;  // A_n = (√3/2)·L_o²
  double mass = 0;       // m = ρ·A_n·D
  double k[2] = {0, 0};  // spring constants of the families: (√3/2)·E_t·D
  double c[2] = {0, 0};  // their dashpots: ζ_t·2√(k_t·m/2)
  double k_s = 0;        // shear spring: G·A_n/D
  double c_s = 0;        // its dashpot: ζ_s·2√(k_s·m)
  double dt = 0;         // T / steps_per_cycle
  int steps_per_cycle = 0;
  double kappa_mean[2] = {0, 0};  // κ̄_1, κ̄_2
  double sigma = 0;
  double strain_rate_theta = 0;  // d(ε_θ)/dt = δr/R_o
  double strain_rate_z = 0;      // d(ε_z)/dt = δh/H_o
};
// dt = 0.3·√(m/(k_s + 2k_1 + 4k_2)), shrunk so that T/dt is whole.
Mechanics MechanicsOf(const BarkParams& params);

// The surface layer's state.
struct Surface {
  std::vector<float> ux, uz;  // displacement from the anchor (cm)
  std::vector<float> wx, wz;  // its rate (cm/s)
  std::vector<float> fx, fz;  // force accumulators (zero between steps)
  std::vector<float> gx, gz;  // each spring's force on its node a in a step, by slot (lattice.h)
  // By slot (lattice.h: Lattice::slot(spring)), so the spring pass reads them in runs:
  // (κ_s·L_o)²: squared length that breaks the spring; +inf once broken (the mark the spring pass
  // reads: a spring at +inf exerts no force and never breaks again).
  std::vector<float> limit2;
  std::vector<uint8_t> broken;   // by spring
  int broken_count[2] = {0, 0};  // per family
};

// At rest on its anchors, every spring with its break ratio κ_s = 1 + (κ̄_t − 1)(1 + σξ_s), ξ_s
// standard normal (Box-Muller on PCG32(seed)), redrawn while |ξ| > 3, κ_s − 1 floored at 1e−4;
// drawn in spring order.
Surface InitialSurface(const Lattice& lattice, const Mechanics& mech, uint64_t seed);

// A layer born at rest whose springs' rest lengths are rest[family] (cm; InitialSurface's are L_o):
// the break ratios as InitialSurface draws them, from PCG32(seed, stream), each limit
// (κ_s·rest[family])². The 4-layer model's layers (four_layer.h) are born this way, one stream a
// birth.
Surface BornSurface(const Lattice& lattice, const Mechanics& mech, uint64_t seed, uint64_t stream,
                    const double rest[2]);

// One standard normal deviate after another, |ξ| ≤ 3 (Box-Muller on PCG32(seed, stream), both of
// each pair used, redrawn past 3): the thresholds' law, for other per-node draws too.
class TruncatedNormal {
 public:
  TruncatedNormal(uint64_t seed, uint64_t stream);
  double Next();

 private:
  Pcg32 rng_;
  double spare_ = 0;
  bool has_spare_ = false;
};

// The growth factors of the anchors at a time: s_θ = 1 + ε_θ, s_z = 1 + ε_z, and their rates (0
// while the inner layer is frozen).
struct Growth {
  float s_theta = 1, s_z = 1;
  float rate_theta = 0, rate_z = 0;
};

// One step: break checks and forces over every spring, then v += dt·F/m, u += dt·v per node.
// Returns the springs broken in this step.
int Step(const Lattice& lattice, const Mechanics& mech, const Growth& growth, Surface* surface);

// The spring pass of one step alone (what Step does before its node pass): break checks and
// forces of both families with constants k, c and rest lengths rest (family 1, 2), the anchors
// scaled by growth; adds to the force accumulators and broken_count. Returns the springs broken.
int SpringForces(const Lattice& lattice, const float k[2], const float c[2], const float rest[2],
                 const Growth& growth, Surface* surface);

// SpringForces in two halves, for a node pass that sums its own forces: the springs' forces into
// gx, gz by slot (not the accumulators); the node pass (Step's, four_layer.cpp's) then sums a
// node's six springs in ascending index from 0 (lattice.h inc_slot, inc_a), as lanes where the
// nodes' springs lie in runs (node_run4, node_run8), as the accumulators did, so the bits are
// theirs.
int SpringSlotForces(const Lattice& lattice, const float k[2], const float c[2],
                     const float rest[2], const Growth& growth, Surface* surface);
// SpringSlotForces of the springs of nodes [begin, end) alone (begin a multiple of four; gx, gz
// sized): the same bits spring by spring, the breaks added to broke[family] (not broken_count), so
// two lanes (step_lanes.h) can each take a range.
void SpringSlotForcesRange(const Lattice& lattice, const float k[2], const float c[2],
                           const float rest[2], const Growth& growth, Surface* surface, int begin,
                           int end, int broke[2]);
// The strain l/L_o − 1 of spring s at the growth (a test's and a report's view).
double SpringStrain(const Lattice& lattice, const Surface& surface, const Growth& growth, int s);

// Elastic energy of the intact springs and shear springs plus the kinetic energy of the nodes'
// motion relative to their anchors (erg).
double Energy(const Lattice& lattice, const Mechanics& mech, const Growth& growth,
              const Surface& surface);

}  // namespace niwa::bark
