// Leaves the moss study does not grow (a tree's crown over a garden's moss) as a shade the photons
// cross: spheres of leaf area, each with its extinction σ, so that a photon crossing a chord of
// length c inside one is intercepted with probability 1 − exp(−σ·c) (Beer–Lambert, as the tree
// thesis's light model 2.3.2 shades its leaf spheres). Overlapping spheres add their σ. Where a
// photon is intercepted is drawn from the path's optical depth (photons.h TracePhotons draws the
// depth; this finds the point). Does not: store photons on leaves (leaves hold no soil), grow or
// move the leaves (the caller hands in each year's), or know which study made them.
// Why no library: the spheres' optical depth along a ray with an exact crossing point is not a
// ray-tracing library's query (three-mesh-bvh and Embree answer first hits on surfaces); the grid
// is small (its lists: sphere_cells.h, shared with the mosses' grid) and tested against a pass
// over every sphere (InterceptLinear).
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace niwa::moss {

// ---- data ----

struct CanopySphere {
  glm::dvec3 centre{0};
  double radius = 0;  // m
  double sigma = 0;   // extinction inside [1/m]
};

// ---- the shade ----

class CanopyShade {
 public:
  // Indexes the spheres (copied) in a uniform grid (cells about one per 8 spheres over the box, at
  // most 2^20 cells); spheres with radius or sigma <= 0 are left out.
  void Build(std::vector<CanopySphere> spheres);
  bool empty() const { return spheres_.empty(); }
  std::size_t size() const { return spheres_.size(); }
  const std::vector<CanopySphere>& spheres() const { return spheres_; }
  // The t in (0, max_t] at which the optical depth of origin + t·dir (dir unit) reaches `depth`
  // (> 0); false when the path's whole depth up to max_t is less. The spheres' chords are swept in
  // order of t (ties by sphere index), so the answer does not depend on the grid.
  bool Intercept(const glm::dvec3& origin, const glm::dvec3& dir, double max_t, double depth,
                 double* t) const;
  // The same by testing every sphere (the oracle).
  bool InterceptLinear(const glm::dvec3& origin, const glm::dvec3& dir, double max_t, double depth,
                       double* t) const;
  // The optical depth of origin + t·dir over t in (0, max_t] (for tests and the stats).
  double OpticalDepth(const glm::dvec3& origin, const glm::dvec3& dir, double max_t) const;

 private:
  struct Chord {
    double t0, t1, sigma;
    uint32_t sphere;
  };
  // Appends sphere s's chord on (0, max_t] when the path crosses it.
  void AddChord(uint32_t s, const glm::dvec3& origin, const glm::dvec3& dir, double max_t,
                std::vector<Chord>* chords) const;
  // The chords of every sphere the grid's cells along the path list, each once.
  void Collect(const glm::dvec3& origin, const glm::dvec3& dir, double max_t,
               std::vector<Chord>* chords) const;
  static bool Sweep(std::vector<Chord>* chords, double depth, double* t);

  std::vector<CanopySphere> spheres_;
  glm::dvec3 lo_{0}, hi_{0};
  double cell_ = 1;
  int dims_[3] = {0, 0, 0};
  std::vector<uint32_t> start_, items_;
  // Collect's marks: sphere s was met by the path numbered stamp_[s] (a scratch of the calls,
  // which are not made from two threads at once).
  mutable std::vector<uint32_t> stamp_;
  mutable uint32_t path_ = 0;
};

}  // namespace niwa::moss
