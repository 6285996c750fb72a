// Uniform bucket grid over 2-D segments (see segment_grid.h).
#include "terrain/segment_grid.h"

#include <algorithm>
#include <cmath>

namespace niwa::terrain {

void SegmentGrid::AddRing(const Ring& ring) {
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    a_.push_back(ring[i]);
    b_.push_back(ring[(i + 1) % n]);
  }
}

void SegmentGrid::Build(double min_bucket) {
  if (a_.empty()) return;
  double x1 = a_[0].x, y1 = a_[0].y;
  x0_ = x1;
  y0_ = y1;
  for (const Vec2& v : a_) {
    x0_ = std::min(x0_, v.x);
    y0_ = std::min(y0_, v.y);
    x1 = std::max(x1, v.x);
    y1 = std::max(y1, v.y);
  }
  const double w = std::max(x1 - x0_, 1e-9), h = std::max(y1 - y0_, 1e-9);
  // Buckets twice the mean segment length (a few segments each along the rings), at most about
  // 16 buckets per segment and 1024 along a side.
  double perimeter = 0;
  for (std::size_t s = 0; s < a_.size(); ++s)
    perimeter += std::hypot(b_[s].x - a_[s].x, b_[s].y - a_[s].y);
  const double n = static_cast<double>(a_.size());
  cell_ = std::max(
      {2 * perimeter / n, std::sqrt(w * h / (16 * n)), std::max(w, h) / 1024.0, min_bucket});
  nx_ = std::max(1, static_cast<int>(std::ceil(w / cell_)));
  ny_ = std::max(1, static_cast<int>(std::ceil(h / cell_)));
  std::vector<uint32_t> count(static_cast<std::size_t>(nx_) * ny_ + 1, 0);
  const auto cover = [&](std::size_t s, auto&& visit) {
    const int i0 =
        std::clamp(static_cast<int>((std::min(a_[s].x, b_[s].x) - x0_) / cell_), 0, nx_ - 1);
    const int i1 =
        std::clamp(static_cast<int>((std::max(a_[s].x, b_[s].x) - x0_) / cell_), 0, nx_ - 1);
    const int j0 =
        std::clamp(static_cast<int>((std::min(a_[s].y, b_[s].y) - y0_) / cell_), 0, ny_ - 1);
    const int j1 =
        std::clamp(static_cast<int>((std::max(a_[s].y, b_[s].y) - y0_) / cell_), 0, ny_ - 1);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) visit(static_cast<std::size_t>(j) * nx_ + i);
  };
  for (std::size_t s = 0; s < a_.size(); ++s) cover(s, [&](std::size_t c) { ++count[c + 1]; });
  for (std::size_t c = 1; c < count.size(); ++c) count[c] += count[c - 1];
  start_ = count;
  items_.assign(count.back(), 0);
  for (std::size_t s = 0; s < a_.size(); ++s)
    cover(s, [&](std::size_t c) { items_[count[c]++] = static_cast<uint32_t>(s); });
}

double SegmentGrid::Dist2(const Vec2& p, std::size_t s) const {
  return SegmentDist2(p, a_[s], b_[s]);
}

double SegmentGrid::Distance(const Vec2& p, int* hint) const {
  if (a_.empty()) return 1e300;
  double best = 1e300;
  int best_s = -1;
  if (hint && *hint >= 0 && static_cast<std::size_t>(*hint) < a_.size()) {
    best = Dist2(p, static_cast<std::size_t>(*hint));
    best_s = *hint;
  }
  const auto col = [this](double x) {
    return std::clamp(static_cast<int>(std::floor((x - x0_) / cell_)), 0, nx_ - 1);
  };
  const auto row = [this](double y) {
    return std::clamp(static_cast<int>(std::floor((y - y0_) / cell_)), 0, ny_ - 1);
  };
  // A bucket is skipped when its box lies farther than the best so far (with a hair for the
  // rounding): the nearest point q of a segment lies in a bucket that lists it and is no farther
  // from p than q, so the least distance is still found.
  const auto scan = [&](int i, int j) {
    const double bx0 = x0_ + i * cell_, by0 = y0_ + j * cell_;
    const double gx = std::max({0.0, bx0 - p.x, p.x - (bx0 + cell_)});
    const double gy = std::max({0.0, by0 - p.y, p.y - (by0 + cell_)});
    if (gx * gx + gy * gy > best * (1 + 1e-9) + 1e-12 * cell_ * cell_) return;
    const std::size_t c = static_cast<std::size_t>(j) * nx_ + i;
    for (uint32_t k = start_[c]; k < start_[c + 1]; ++k) {
      const double d2 = Dist2(p, items_[k]);
      if (d2 < best) {
        best = d2;
        best_s = static_cast<int>(items_[k]);
      }
    }
  };
  const int ci = col(p.x), cj = row(p.y);
  for (int r = 0;; ++r) {
    const int i0 = ci - r, i1 = ci + r, j0 = cj - r, j1 = cj + r;
    // The ring r only: its top and bottom rows whole, the other rows' two ends.
    for (int j = std::max(j0, 0); j <= std::min(j1, ny_ - 1); ++j) {
      if (j == j0 || j == j1) {
        for (int i = std::max(i0, 0); i <= std::min(i1, nx_ - 1); ++i) scan(i, j);
      } else {
        if (i0 >= 0) scan(i0, j);
        if (i1 < nx_ && i1 != i0) scan(i1, j);
      }
    }
    // Every segment not yet seen lies wholly beyond one of the visited square's inner sides (less
    // a hair for the rounding of the bucket division).
    double bound = 1e300;
    bool more = false;
    const auto side = [&](bool inner, double gap) {
      if (!inner) return;
      more = true;
      bound = std::min(bound, std::max(0.0, gap - cell_ * 1e-9));
    };
    side(i0 > 0, p.x - (x0_ + i0 * cell_));
    side(i1 < nx_ - 1, x0_ + (i1 + 1) * cell_ - p.x);
    side(j0 > 0, p.y - (y0_ + j0 * cell_));
    side(j1 < ny_ - 1, y0_ + (j1 + 1) * cell_ - p.y);
    if (!more || best <= bound * bound) break;
  }
  if (hint) *hint = best_s;
  return std::sqrt(best);
}

}  // namespace niwa::terrain
