// The leaves' shade the moss photons cross (canopy.h).
#include "moss/canopy.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

#include "moss/sphere_cells.h"

namespace niwa::moss {

void CanopyShade::Build(std::vector<CanopySphere> spheres) {
  spheres_.clear();
  for (const CanopySphere& s : spheres)
    if (s.radius > 0 && s.sigma > 0 && std::isfinite(s.radius) && std::isfinite(s.sigma) &&
        std::isfinite(s.centre.x) && std::isfinite(s.centre.y) && std::isfinite(s.centre.z))
      spheres_.push_back(s);
  start_.clear();
  items_.clear();
  dims_[0] = dims_[1] = dims_[2] = 0;
  if (spheres_.empty()) return;
  lo_ = glm::dvec3(std::numeric_limits<double>::infinity());
  hi_ = -lo_;
  double diameters = 0;
  for (const CanopySphere& s : spheres_) {
    lo_ = glm::min(lo_, s.centre - glm::dvec3(s.radius));
    hi_ = glm::max(hi_, s.centre + glm::dvec3(s.radius));
    diameters += 2 * s.radius;
  }
  // Cells of the mean diameter, or wider so that the box holds about one cell for every 8
  // spheres: a garden's crowns stand apart, and most photons cross the box without meeting one
  // (cells of a leaf sphere's size made the walk through empty cells 20 % of a garden's time);
  // widened until the grid has at most 2^20 cells.
  const glm::dvec3 extent = hi_ - lo_;
  const double volume = std::max(1e-9, extent.x * extent.y * extent.z);
  cell_ = std::max({1e-3, diameters / static_cast<double>(spheres_.size()),
                    std::cbrt(volume * 8.0 / static_cast<double>(spheres_.size()))});
  for (;;) {
    for (int a = 0; a < 3; ++a)
      dims_[a] = std::max(1, static_cast<int>(std::ceil(extent[a] / cell_)));
    if (static_cast<double>(dims_[0]) * dims_[1] * dims_[2] <= static_cast<double>(1 << 20)) break;
    cell_ *= 1.5;
  }
  stamp_.assign(spheres_.size(), 0);
  path_ = 0;
  ListSpheresInCells(
      spheres_.size(), [&](uint32_t s) -> const glm::dvec3& { return spheres_[s].centre; },
      [&](uint32_t s) { return spheres_[s].radius; }, lo_, cell_, dims_, &start_, &items_);
}

void CanopyShade::AddChord(uint32_t s, const glm::dvec3& origin, const glm::dvec3& dir,
                           double max_t, std::vector<Chord>* chords) const {
  const CanopySphere& sphere = spheres_[s];
  const glm::dvec3 m = origin - sphere.centre;
  const double b = glm::dot(m, dir);
  const double disc = b * b - (glm::dot(m, m) - sphere.radius * sphere.radius);
  if (disc <= 0.0) return;
  const double h = std::sqrt(disc);
  const double t0 = std::max(0.0, -b - h), t1 = std::min(max_t, -b + h);
  if (t1 > t0) chords->push_back({t0, t1, sphere.sigma, s});
}

void CanopyShade::Collect(const glm::dvec3& origin, const glm::dvec3& dir, double max_t,
                          std::vector<Chord>* chords) const {
  chords->clear();
  if (spheres_.empty()) return;
  // The path's part inside the grid's box.
  double t_in = 0, t_out = max_t;
  for (int a = 0; a < 3; ++a) {
    if (dir[a] == 0.0) {
      if (origin[a] < lo_[a] || origin[a] > hi_[a]) return;
      continue;
    }
    double ta = (lo_[a] - origin[a]) / dir[a], tb = (hi_[a] - origin[a]) / dir[a];
    if (ta > tb) std::swap(ta, tb);
    t_in = std::max(t_in, ta);
    t_out = std::min(t_out, tb);
  }
  if (!(t_in <= t_out)) return;
  // The cells the path crosses (Amanatides–Woo), their spheres' chords added once each (the
  // chords' order does not matter: Sweep sorts them).
  if (++path_ == 0) {
    std::fill(stamp_.begin(), stamp_.end(), 0);
    path_ = 1;
  }
  int cell[3], step[3];
  double t_next[3], t_delta[3];
  const glm::dvec3 p = origin + t_in * dir;
  for (int a = 0; a < 3; ++a) {
    cell[a] = std::clamp(static_cast<int>(std::floor((p[a] - lo_[a]) / cell_)), 0, dims_[a] - 1);
    step[a] = dir[a] > 0 ? 1 : -1;
    if (dir[a] == 0.0) {
      t_next[a] = t_delta[a] = std::numeric_limits<double>::infinity();
    } else {
      const double edge = lo_[a] + (cell[a] + (dir[a] > 0 ? 1 : 0)) * cell_;
      t_next[a] = (edge - origin[a]) / dir[a];
      t_delta[a] = cell_ / std::abs(dir[a]);
    }
  }
  for (;;) {
    const std::size_t k =
        (static_cast<std::size_t>(cell[2]) * dims_[1] + cell[1]) * dims_[0] + cell[0];
    for (uint32_t e = start_[k]; e < start_[k + 1]; ++e) {
      const uint32_t s = items_[e];
      if (stamp_[s] == path_) continue;
      stamp_[s] = path_;
      AddChord(s, origin, dir, max_t, chords);
    }
    const int a =
        t_next[0] < t_next[1] ? (t_next[0] < t_next[2] ? 0 : 2) : (t_next[1] < t_next[2] ? 1 : 2);
    if (t_next[a] > t_out) break;
    cell[a] += step[a];
    if (cell[a] < 0 || cell[a] >= dims_[a]) break;
    t_next[a] += t_delta[a];
  }
}

bool CanopyShade::Sweep(std::vector<Chord>* chords, double depth, double* t) {
  if (chords->empty()) return false;
  struct Event {
    double t;
    uint32_t sphere;
    int enter;  // 1 entering, 0 leaving (leaving first at the same t and sphere)
    double sigma;
  };
  static thread_local std::vector<Event> events;
  events.clear();
  for (const Chord& c : *chords) {
    events.push_back({c.t0, c.sphere, 1, c.sigma});
    events.push_back({c.t1, c.sphere, 0, c.sigma});
  }
  std::sort(events.begin(), events.end(), [](const Event& a, const Event& b) {
    if (a.t != b.t) return a.t < b.t;
    if (a.sphere != b.sphere) return a.sphere < b.sphere;
    return a.enter < b.enter;
  });
  double rate = 0, acc = 0, prev = events.front().t;
  int inside = 0;
  for (const Event& e : events) {
    const double seg = e.t - prev;
    if (inside > 0 && rate > 0 && acc + rate * seg >= depth) {
      *t = prev + std::max(0.0, depth - acc) / rate;
      return true;
    }
    acc += rate * seg;
    prev = e.t;
    if (e.enter) {
      rate += e.sigma;
      ++inside;
    } else if (--inside == 0) {
      rate = 0;  // no drift carried across a gap between crowns
    } else {
      rate -= e.sigma;
    }
  }
  return false;
}

bool CanopyShade::Intercept(const glm::dvec3& origin, const glm::dvec3& dir, double max_t,
                            double depth, double* t) const {
  static thread_local std::vector<Chord> chords;
  Collect(origin, dir, max_t, &chords);
  return Sweep(&chords, depth, t);
}

bool CanopyShade::InterceptLinear(const glm::dvec3& origin, const glm::dvec3& dir, double max_t,
                                  double depth, double* t) const {
  std::vector<Chord> chords;
  for (uint32_t s = 0; s < spheres_.size(); ++s) AddChord(s, origin, dir, max_t, &chords);
  return Sweep(&chords, depth, t);
}

double CanopyShade::OpticalDepth(const glm::dvec3& origin, const glm::dvec3& dir,
                                 double max_t) const {
  std::vector<Chord> chords;
  Collect(origin, dir, max_t, &chords);
  double sum = 0;
  for (const Chord& c : chords) sum += c.sigma * (c.t1 - c.t0);
  return sum;
}

}  // namespace niwa::moss
