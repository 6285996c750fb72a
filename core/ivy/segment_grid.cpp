// The uniform hash grid of internodes (segment_grid.h).
#include "ivy/segment_grid.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>

namespace niwa::ivy {

SegmentGrid::Cell SegmentGrid::CellOf(const glm::dvec3& p) const {
  // Clamped so far-away coordinates (up to the seed limit 1e30) stay in int64 range: the clamped
  // cells only gather more candidates.
  const auto index = [this](double v) {
    const double c = std::floor(v / cell_);
    return static_cast<int64_t>(std::clamp(c, -1e15, 1e15));
  };
  return {index(p.x), index(p.y), index(p.z)};
}

uint64_t SegmentGrid::Key(const Cell& c) {
  // 21 bits per axis (cells far apart may share a key: they only add candidates, never lose one).
  const auto bits = [](int64_t v) { return static_cast<uint64_t>(v) & ((uint64_t{1} << 21) - 1); };
  return bits(c.x) | (bits(c.y) << 21) | (bits(c.z) << 42);
}

void SegmentGrid::Insert(int id, const glm::dvec3& a, const glm::dvec3& b) {
  if (static_cast<std::size_t>(id) >= seen_.size())
    seen_.resize(static_cast<std::size_t>(id) + 1, 0);
  const Cell lo = CellOf(glm::min(a, b)), hi = CellOf(glm::max(a, b));
  for (int64_t x = lo.x; x <= hi.x; ++x)
    for (int64_t y = lo.y; y <= hi.y; ++y)
      for (int64_t z = lo.z; z <= hi.z; ++z) {
        std::vector<int>& list = cells_[Key({x, y, z})];
        // A key shared by two cells of one segment: list it once.
        if (list.empty() || list.back() != id) list.push_back(id);
      }
}

}  // namespace niwa::ivy
