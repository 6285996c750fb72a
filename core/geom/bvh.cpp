// Deterministic binned-SAH BVH build (Wald 2007, "On fast Construction of SAH-based Bounding
// Volume Hierarchies": centroid bins, cost C = N_L·A_L + N_R·A_R).
#include "geom/bvh.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace niwa::geom {
namespace {

// Beyond this depth the build halves ranges instead of SAH splits, so depth stays <= this + 32 and
// the queries' fixed stacks (bvh_traversal.h kMaxStack) never overflow.
constexpr int kSahDepthLimit = 100;

struct Builder {
  const BvhOptions& options;
  std::vector<Bounds3> tri_bounds;
  std::vector<glm::vec3> centroids;
  std::vector<uint32_t>& order;
  std::vector<BvhNode>& nodes;
  int max_depth = 0;

  // Pads a node box outward by about 8 float ulps of its largest coordinate, so double-precision
  // query rounding and the Möller–Trumbore edge slack never put a hit outside its leaf's box.
  static void Pad(Bounds3* b) {
    float m = 0.0f;
    for (int k = 0; k < 3; ++k) m = std::max({m, std::fabs(b->min[k]), std::fabs(b->max[k])});
    float pad = m * 1e-6f + 1e-30f;
    b->min -= glm::vec3(pad);
    b->max += glm::vec3(pad);
  }

  Bounds3 RangeBounds(std::size_t begin, std::size_t end) const {
    Bounds3 b;
    for (std::size_t i = begin; i < end; ++i) b.Extend(tri_bounds[order[i]]);
    return b;
  }

  // Bin index of a centroid coordinate; the same expression in the sweep and the partition.
  static int BinOf(float c, float lo, float scale, int bins) {
    float f = (c - lo) * scale;
    int i = f > 0.0f ? static_cast<int>(f) : 0;  // NaN and negatives go to bin 0
    return std::min(i, bins - 1);
  }

  void Build(uint32_t node_index, std::size_t begin, std::size_t end, int depth) {
    max_depth = std::max(max_depth, depth);
    Bounds3 bounds = RangeBounds(begin, end);
    Pad(&bounds);
    nodes[node_index].bounds = bounds;
    const std::size_t count = end - begin;
    if (count <= static_cast<std::size_t>(options.max_leaf_triangles)) {
      nodes[node_index].first = static_cast<uint32_t>(begin);
      nodes[node_index].count = static_cast<uint32_t>(count);
      return;
    }
    std::size_t mid = begin + count / 2;  // fallback: halve the range in its current order
    if (depth < kSahDepthLimit) {
      Bounds3 cb;
      for (std::size_t i = begin; i < end; ++i) cb.Extend(centroids[order[i]]);
      const int bins = options.bins;
      int best_axis = -1, best_split = 0;
      double best_cost = 0.0;
      for (int axis = 0; axis < 3; ++axis) {
        float lo = cb.min[axis], extent = cb.max[axis] - lo;
        if (!(extent > 0.0f)) continue;
        float scale = static_cast<float>(bins) / extent;
        Bounds3 bin_bounds[64];
        std::size_t bin_count[64] = {};
        for (std::size_t i = begin; i < end; ++i) {
          uint32_t t = order[i];
          int b = BinOf(centroids[t][axis], lo, scale, bins);
          bin_bounds[b].Extend(tri_bounds[t]);
          ++bin_count[b];
        }
        double right_area[64];
        std::size_t right_count[64];
        Bounds3 acc;
        std::size_t n = 0;
        for (int b = bins - 1; b > 0; --b) {  // right side of split b: bins b .. bins-1
          acc.Extend(bin_bounds[b]);
          n += bin_count[b];
          right_area[b] = acc.SurfaceArea();
          right_count[b] = n;
        }
        acc = Bounds3();
        n = 0;
        for (int b = 1; b < bins; ++b) {  // left side of split b: bins 0 .. b-1
          acc.Extend(bin_bounds[b - 1]);
          n += bin_count[b - 1];
          if (n == 0 || right_count[b] == 0) continue;
          double cost = static_cast<double>(n) * acc.SurfaceArea() +
                        static_cast<double>(right_count[b]) * right_area[b];
          if (best_axis < 0 || cost < best_cost) {  // ties: lowest axis, then lowest bin
            best_axis = axis;
            best_split = b;
            best_cost = cost;
          }
        }
      }
      if (best_axis >= 0) {
        float lo = cb.min[best_axis];
        float scale = static_cast<float>(bins) / (cb.max[best_axis] - lo);
        // Hand-written partition (std::partition's order differs between libstdc++ and libc++).
        std::size_t i = begin, j = end;
        while (i < j) {
          if (BinOf(centroids[order[i]][best_axis], lo, scale, bins) < best_split) {
            ++i;
          } else {
            --j;
            std::swap(order[i], order[j]);
          }
        }
        mid = i;
      }
    }
    uint32_t left = static_cast<uint32_t>(nodes.size());
    nodes.emplace_back();
    nodes.emplace_back();
    nodes[node_index].first = left;
    nodes[node_index].count = 0;
    Build(left, begin, mid, depth + 1);
    Build(left + 1, mid, end, depth + 1);
  }
};

}  // namespace

Bvh Bvh::Build(const TriMesh& mesh, const BvhOptions& options_in) {
  BvhOptions options = options_in;
  options.bins = std::clamp(options.bins, 2, 64);
  options.max_leaf_triangles = std::clamp(options.max_leaf_triangles, 1, 16);
  Bvh bvh;
  const std::size_t tris = mesh.triangle_count();
  if (tris == 0) return bvh;
  Builder b{options, {}, {}, bvh.order_, bvh.nodes_};
  b.tri_bounds.resize(tris);
  b.centroids.resize(tris);
  bvh.order_.resize(tris);
  for (std::size_t t = 0; t < tris; ++t) {
    Bounds3 tb;
    for (int k = 0; k < 3; ++k)
      tb.Extend(mesh.positions[mesh.indices[3 * t + static_cast<std::size_t>(k)]]);
    b.tri_bounds[t] = tb;
    b.centroids[t] = (tb.min + tb.max) * 0.5f;
    bvh.order_[t] = static_cast<uint32_t>(t);
  }
  bvh.nodes_.reserve(2 * tris / static_cast<std::size_t>(options.max_leaf_triangles) + 1);
  bvh.nodes_.emplace_back();
  b.Build(0, 0, tris, 1);
  bvh.depth_ = b.max_depth;
  return bvh;
}

}  // namespace niwa::geom
