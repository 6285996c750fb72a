// A uniform hash grid of segments for "is this segment within r of any stored one?" (the
// improved preset's branch avoidance, spec E8 "crowding"): each stored segment is listed in every
// cell its box touches; a query tests only the segments listed in the cells its box, grown by r,
// touches, each once. It answers exactly what the loop over every segment answers (a candidate
// set that holds every segment within r), in O(segments near the query) instead of O(all).
// Why no library: nanoflann (the kd-tree we use elsewhere) indexes points, not segments with a
// radius, and a grid of equal-length internodes is the right structure and about 60 lines.
// Does not: remove segments, measure distances itself (the caller's test does), or order results.
#pragma once

#include <cstdint>
#include <glm/common.hpp>
#include <glm/vec3.hpp>
#include <unordered_map>
#include <vector>

namespace niwa::ivy {

class SegmentGrid {
 public:
  // cell: the cell edge (the internode length L is a good one); must be > 0.
  explicit SegmentGrid(double cell) : cell_(cell) {}

  // Stores segment `id` (ids 0, 1, 2, ... in insertion order) from a to b.
  void Insert(int id, const glm::dvec3& a, const glm::dvec3& b);

  // Calls near(id) for every stored segment whose box comes within r of the box of a-b (each at
  // most once) until one returns true; returns whether one did.
  template <typename Near>
  bool Any(const glm::dvec3& a, const glm::dvec3& b, double r, Near near) const {
    if (++stamp_ == 0) {  // after 2^32 queries: forget every stamp
      seen_.assign(seen_.size(), 0);
      stamp_ = 1;
    }
    const Cell lo = CellOf(glm::min(a, b) - glm::dvec3(r)),
               hi = CellOf(glm::max(a, b) + glm::dvec3(r));
    for (int64_t x = lo.x; x <= hi.x; ++x)
      for (int64_t y = lo.y; y <= hi.y; ++y)
        for (int64_t z = lo.z; z <= hi.z; ++z) {
          auto it = cells_.find(Key({x, y, z}));
          if (it == cells_.end()) continue;
          for (int id : it->second) {
            if (seen_[static_cast<std::size_t>(id)] == stamp_) continue;
            seen_[static_cast<std::size_t>(id)] = stamp_;
            if (near(id)) return true;
          }
        }
    return false;
  }

  std::size_t size() const { return seen_.size(); }

 private:
  struct Cell {
    int64_t x, y, z;
  };
  Cell CellOf(const glm::dvec3& p) const;
  static uint64_t Key(const Cell& c);

  double cell_;
  std::unordered_map<uint64_t, std::vector<int>> cells_;
  mutable std::vector<uint32_t> seen_;  // per segment: the stamp of the last query that saw it
  mutable uint32_t stamp_ = 0;
};

}  // namespace niwa::ivy
