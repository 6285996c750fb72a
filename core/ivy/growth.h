// Ivy growth (§3): the support (a TriMesh with its BVH, or none: the RNG-free "free" replay), the
// seed placement, and Grow: S steps of rules p0-p3 with the nutrient bookkeeping (E1-E5) and the
// directed random walk (E6-E10, then the tangent fan when tangent_retry is on) that places every
// new internode. Does not: mesh, print or report.
#pragma once

#include <cstdint>
#include <functional>
#include <glm/vec3.hpp>
#include <memory>
#include <vector>

#include "base/status.h"
#include "geom/bvh.h"
#include "geom/tri_mesh.h"
#include "ivy/ivy.h"
#include "ivy/ivy_params.h"

namespace niwa::ivy {

// What the ivy climbs. mesh == nullptr: no support (every search accepts p + L·v0; the nutrient
// replay of the spec). The mesh and BVH must outlive the grow.
struct Support {
  const geom::TriMesh* mesh = nullptr;  // every triangle: collisions (E8 "collision")
  const geom::Bvh* bvh = nullptr;
  Accel accel = Accel::kBvh;
  // Optional: the triangles ivy may attach to (distances, anchors, seeds); nullptr = all of mesh.
  // Obstacle-only triangles (material "noivy*" or extras.niwa_ivy false) are in mesh, not here.
  const geom::TriMesh* attach_mesh = nullptr;
  const geom::Bvh* attach_bvh = nullptr;
};

constexpr int kMaxSteps = 10000;
constexpr int kMaxSeedPoints = 64;

struct IvyGrowLimits;  // ivy_budget.h

// Grows one plant from every seed point for `steps` steps (stops early when no A or D is left, or
// before a step whose worst case would cross `limits`: log->truncated_by then holds the line).
// Errors name state fields: "steps" (outside [0, 10000]), "seed_points" (none, more than 64, not
// finite, or one farther than d from every face: "point 1: (600, 10, 450) is 50 from the nearest
// face; must be within d = 20"), "mesh" (no support triangle), or a parameter.
// on_step (optional) is called after every step with (step, steps) and the model and log so far:
// progress for a page's worker, and the run's check that the outputs asked for still fit the
// budget (IvyRunOptions::planned); it cannot change the growth, only stop it: false cancels (Grow
// returns run::CancelledStatus()).
using StepObserver =
    std::function<bool(int step, int steps, const IvyModel& model, const GrowLog& log)>;
Result<IvyModel> Grow(const Support& support, const std::vector<glm::dvec3>& seeds,
                      const IvyParams& params, int steps, uint64_t seed, GrowLog* log,
                      const IvyGrowLimits* limits = nullptr, const StepObserver& on_step = {});

// Grow's steps a stretch at a time, with the support replaceable between stretches: the garden
// (compose/garden_run) grows its ivy year by year on the trunks as they stand that year. Grow is
// this with one stretch on one support, so both make the same bytes. Replacing the support keeps
// every bud where it grew; a bud anchored on a triangle at or past `kept_triangles` (the part of
// the support that changed) is re-anchored to the new support's closest point (its position,
// direction and side stay), so the anchors name the current support's triangles.
class IvyGrowth {
 public:
  // Places the seeds on `support` (errors as Grow's). `steps` is the growth's last step (the
  // lines' "of N" and the end); nothing grows until GrowTo. The support's mesh and BVH must
  // outlive the growth or the next SetSupport.
  static Result<IvyGrowth> Start(const Support& support, const std::vector<glm::dvec3>& seeds,
                                 const IvyParams& params, int steps, uint64_t seed);
  IvyGrowth(IvyGrowth&&) noexcept;
  IvyGrowth& operator=(IvyGrowth&&) noexcept;
  ~IvyGrowth();
  void SetSupport(const Support& support, uint32_t kept_triangles);
  // Grows steps up to `to` (at most the growth's steps), as Grow's loop: the limits checked before
  // each step, on_step after it; stops for good when no A or D is left or a limit stops it.
  Status GrowTo(int to, const IvyGrowLimits* limits, const StepObserver& on_step = {});
  bool finished() const;  // at its steps, extinct, or stopped by a limit
  int steps() const;
  const IvyModel& model() const;
  const GrowLog& log() const;
  // Hands over the model and log (ms_rules set); the growth is spent.
  IvyModel TakeModel();
  GrowLog TakeLog();

 private:
  struct Impl;
  explicit IvyGrowth(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

// The geometric normal of a triangle (unit, from its winding).
glm::dvec3 TriangleNormal(const geom::TriMesh& mesh, uint32_t triangle);

// Shortest distance between segments p1-q1 and p2-q2 (Ericson, RTCD §5.1.9), in double.
double SegmentSegmentDistance(const glm::dvec3& p1, const glm::dvec3& q1, const glm::dvec3& p2,
                              const glm::dvec3& q2);

}  // namespace niwa::ivy
