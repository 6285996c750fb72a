// Deterministic binned-SAH BVH build (Wald 2007, "On fast Construction of SAH-based Bounding
// Volume Hierarchies": centroid bins, cost C = N_L·A_L + N_R·A_R).
#include "geom/bvh.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <exception>
#include <glm/common.hpp>
#include <memory>
#if NIWA_HAVE_THREADS
#include <thread>
#endif

namespace niwa::geom {
namespace {

// Beyond this depth the build halves ranges instead of SAH splits, so depth stays <= this + 32 and
// the queries' fixed stacks (query_detail.h kMaxStack) never overflow.
constexpr int kSahDepthLimit = 100;
constexpr int kMaxBins = 64;

// One triangle's box and centroid (the box centre), moved as a whole by the partition so every
// pass over a node's range reads memory in order.
struct Prim {
  glm::vec3 lo, hi;  // the triangle's box; its centroid is the box centre, C() (28 bytes in all)
  uint32_t tri;
  glm::vec3 C() const { return (lo + hi) * 0.5f; }
  float C(int axis) const { return (lo[axis] + hi[axis]) * 0.5f; }
};

struct Bin {
  Bounds3 bounds;  // union of the triangle boxes: min of their lo, max of their hi
  std::size_t count = 0;
};

#if NIWA_HAVE_THREADS
// Ranges at least this long have their two halves built on two threads (native builds with
// NIWA_HAVE_THREADS): each half into its own node array, spliced back in the order the one-thread
// build allocates (so the nodes are the same, bit for bit, with or without threads).
constexpr std::size_t kParallelMin = 1 << 16;
#endif

struct Builder {
  Builder(const BvhOptions& o, std::vector<BvhNode>& n, std::vector<Prim>& p)
      : options(o), prims(p), nodes(n) {}
  const BvhOptions& options;
  std::vector<Prim>& prims;  // shared: each builder partitions only its own range
  std::vector<BvhNode>& nodes;
  int max_depth = 0;
  // Scratch, reused by every node (not on the recursion's stack): two sets that take alternate
  // triangles, so a run of triangles falling in one bin does not wait on its own last store, then
  // merged (min, max and sums: the same bins as one set would give, bit for bit).
  Bin bins[3][kMaxBins];
  Bin bins_odd[3][kMaxBins];

  // Pads a node box outward by about 8 float ulps of its largest coordinate, so double-precision
  // query rounding and the Möller–Trumbore edge slack never put a hit outside its leaf's box.
  static Bounds3 Padded(Bounds3 b) {
    float m = 0.0f;
    for (int k = 0; k < 3; ++k) m = std::max({m, std::fabs(b.min[k]), std::fabs(b.max[k])});
    float pad = m * 1e-6f + 1e-30f;
    b.min -= glm::vec3(pad);
    b.max += glm::vec3(pad);
    return b;
  }

  void RangeBounds(std::size_t begin, std::size_t end, Bounds3* b, Bounds3* cb) const {
    for (std::size_t i = begin; i < end; ++i) {
      b->Extend(prims[i].lo);
      b->Extend(prims[i].hi);
      cb->Extend(prims[i].C());
    }
  }

  // Bin index of a centroid coordinate; the same expression in the binning and the partition.
  static int BinOf(float c, float lo, float scale, int bins) {
    float f = (c - lo) * scale;
    int i = f > 0.0f ? static_cast<int>(f) : 0;  // NaN and negatives go to bin 0
    return std::min(i, bins - 1);
  }

  // bounds/cbounds: the exact union of the range's triangle boxes and of its centroids.
  void Build(uint32_t node_index, std::size_t begin, std::size_t end, int depth,
             const Bounds3& bounds, const Bounds3& cbounds) {
    max_depth = std::max(max_depth, depth);
    nodes[node_index].bounds = Padded(bounds);
    const std::size_t count = end - begin;
    if (count <= static_cast<std::size_t>(options.max_leaf_triangles)) {
      nodes[node_index].first = static_cast<uint32_t>(begin);
      nodes[node_index].count = static_cast<uint32_t>(count);
      return;
    }
    const int nb = options.bins;
    int best_axis = -1, best_split = 0;
    Bounds3 left_b, left_cb, right_b, right_cb;
    if (depth < kSahDepthLimit) {
      float lo[3] = {0, 0, 0}, scale[3] = {0, 0, 0};
      bool axis_ok[3] = {false, false, false};
      // Bins along the axis of largest centroid extent only (Wald 2007, section 3.1; ties: lowest
      // axis). all_axes bins all three in the same pass (a little better trees, ~2x the work).
      int dominant = 0;
      glm::vec3 extent = cbounds.max - cbounds.min;
      for (int a = 1; a < 3; ++a)
        if (extent[a] > extent[dominant]) dominant = a;
      for (int a = 0; a < 3; ++a) {
        lo[a] = cbounds.min[a];
        axis_ok[a] = extent[a] > 0.0f && (options.all_axes || a == dominant);
        scale[a] = axis_ok[a] ? static_cast<float>(nb) / extent[a] : 0.0f;
      }
      // Two sets pay on long ranges only; most nodes are small, and clearing bins is their cost.
      const bool two_sets = count >= 64;
      for (int a = 0; a < 3; ++a) {
        if (!axis_ok[a]) continue;
        for (int b = 0; b < nb; ++b) bins[a][b] = Bin();
        if (two_sets)
          for (int b = 0; b < nb; ++b) bins_odd[a][b] = Bin();
      }
      auto add = [&](Bin(*set)[kMaxBins], const Prim& p) {
        for (int a = 0; a < 3; ++a) {
          if (!axis_ok[a]) continue;
          Bin& bin = set[a][BinOf(p.C(a), lo[a], scale[a], nb)];
          bin.bounds.min = glm::min(bin.bounds.min, p.lo);
          bin.bounds.max = glm::max(bin.bounds.max, p.hi);
          ++bin.count;
        }
      };
      std::size_t i = begin;
      if (two_sets) {
        for (; i + 1 < end; i += 2) {  // one pass bins every axis in use
          add(bins, prims[i]);
          add(bins_odd, prims[i + 1]);
        }
      }
      for (; i < end; ++i) add(bins, prims[i]);
      for (int a = 0; a < 3 && two_sets; ++a) {
        if (!axis_ok[a]) continue;
        for (int b = 0; b < nb; ++b) {
          bins[a][b].bounds.Extend(bins_odd[a][b].bounds);
          bins[a][b].count += bins_odd[a][b].count;
        }
      }
      double best_cost = 0.0;
      for (int a = 0; a < 3; ++a) {
        if (!axis_ok[a]) continue;
        double right_area[kMaxBins];
        std::size_t right_count[kMaxBins];
        Bounds3 acc;
        std::size_t n = 0;
        for (int b = nb - 1; b > 0; --b) {  // right of split b: bins b .. nb-1
          acc.Extend(bins[a][b].bounds);
          n += bins[a][b].count;
          right_area[b] = acc.SurfaceArea();
          right_count[b] = n;
        }
        acc = Bounds3();
        n = 0;
        for (int b = 1; b < nb; ++b) {  // left of split b: bins 0 .. b-1
          acc.Extend(bins[a][b - 1].bounds);
          n += bins[a][b - 1].count;
          if (n == 0 || right_count[b] == 0) continue;
          double cost = static_cast<double>(n) * acc.SurfaceArea() +
                        static_cast<double>(right_count[b]) * right_area[b];
          if (best_axis < 0 || cost < best_cost) {  // ties: lowest axis, then lowest bin
            best_axis = a;
            best_split = b;
            best_cost = cost;
          }
        }
      }
      if (best_axis >= 0) {
        for (int b = 0; b < nb; ++b)
          (b < best_split ? left_b : right_b).Extend(bins[best_axis][b].bounds);
      }
    }
    std::size_t mid;
    if (best_axis >= 0) {
      float lo = cbounds.min[best_axis];
      float scale = static_cast<float>(nb) / (cbounds.max[best_axis] - lo);
      // Hand-written Hoare partition (std::partition's order differs between libstdc++ and
      // libc++): one swap per misplaced pair, and each side's centroid bounds gathered in the same
      // pass for the children's bins.
      auto left_of = [&](const Prim& p) {
        return BinOf(p.C(best_axis), lo, scale, nb) < best_split;
      };
      auto gather = [](Bounds3* cb, const Prim& p) {
        const glm::vec3 c = p.C();
        cb->min = glm::min(cb->min, c);
        cb->max = glm::max(cb->max, c);
      };
      std::size_t i = begin, j = end;
      for (;;) {
        while (i < j && left_of(prims[i])) gather(&left_cb, prims[i++]);
        while (i < j && !left_of(prims[j - 1])) gather(&right_cb, prims[--j]);
        if (i >= j) break;
        std::swap(prims[i], prims[j - 1]);
        gather(&left_cb, prims[i++]);
        gather(&right_cb, prims[--j]);
      }
      mid = i;
    } else {  // no SAH split (equal centroids, or too deep): halve the range in its order
      mid = begin + count / 2;
      RangeBounds(begin, mid, &left_b, &left_cb);
      RangeBounds(mid, end, &right_b, &right_cb);
    }
    uint32_t left = static_cast<uint32_t>(nodes.size());
    nodes.emplace_back();
    nodes.emplace_back();
    nodes[node_index].first = left;
    nodes[node_index].count = 0;
#if NIWA_HAVE_THREADS
    if (options.threads && depth == 1 && count >= kParallelMin) {
      BuildHalvesInParallel(left, begin, mid, end, depth + 1, left_b, left_cb, right_b, right_cb);
      return;
    }
#endif
    Build(left, begin, mid, depth + 1, left_b, left_cb);
    Build(left + 1, mid, end, depth + 1, right_b, right_cb);
  }

#if NIWA_HAVE_THREADS
  // Builds nodes left and left + 1 (the children of a node whose pair was just allocated, with
  // nothing allocated after it): each into its own array from a local root 0, the left one on a
  // second thread, then copies them back, local node k >= 1 of the left half at left + 1 + k and
  // of the right half after the whole left half, as the one-thread recursion would place them.
  void BuildHalvesInParallel(uint32_t left, std::size_t begin, std::size_t mid, std::size_t end,
                             int depth, const Bounds3& left_b, const Bounds3& left_cb,
                             const Bounds3& right_b, const Bounds3& right_cb) {
    std::vector<BvhNode> half_nodes[2];
    auto half_builder = [&](int h) {
      half_nodes[h].reserve(2 * ((h == 0 ? mid - begin : end - mid) /
                                 static_cast<std::size_t>(options.max_leaf_triangles)) +
                            1);
      half_nodes[h].emplace_back();
      return std::make_unique<Builder>(options, half_nodes[h], prims);
    };
    std::unique_ptr<Builder> halves[2] = {half_builder(0), half_builder(1)};
    std::exception_ptr failure;
    std::thread worker([&] {
      try {
        halves[0]->Build(0, begin, mid, depth, left_b, left_cb);
      } catch (...) {
        failure = std::current_exception();
      }
    });
    try {
      halves[1]->Build(0, mid, end, depth, right_b, right_cb);
    } catch (...) {
      worker.join();
      throw;
    }
    worker.join();
    if (failure) std::rethrow_exception(failure);
    const uint32_t base[2] = {left + 2 - 1,
                              left + 2 - 1 + static_cast<uint32_t>(half_nodes[0].size() - 1)};
    nodes.reserve(nodes.size() + half_nodes[0].size() + half_nodes[1].size() - 2);
    for (int h = 0; h < 2; ++h) {
      for (std::size_t k = 0; k < half_nodes[h].size(); ++k) {
        BvhNode n = half_nodes[h][k];
        if (!n.is_leaf()) n.first += base[h];  // a local pair k >= 1 moves to base + k
        if (k == 0)
          nodes[left + static_cast<uint32_t>(h)] = n;
        else
          nodes.push_back(n);
      }
      max_depth = std::max(max_depth, halves[h]->max_depth);
    }
  }
#endif
};

// Collapses the binary tree into 4-wide nodes, depth first (a node's first inner child follows it
// in memory), children kept in their left-to-right binary order.
struct Widener {
  const std::vector<BvhNode>& nodes;
  std::vector<BvhWideNode>& wide;
  int max_depth = 0;

  // Fills node n's slots with the binary nodes kids[0..k): counts, children, and the child boxes
  // on an 8-bit grid over their union, each side rounded outward until the decoded float (the
  // expression ChildBounds() uses) contains the binary box exactly.
  void Quantise(BvhWideNode& n, const uint32_t* kids, int k) const {
    Bounds3 all;
    for (int i = 0; i < k; ++i) all.Extend(nodes[kids[i]].bounds);
    for (int a = 0; a < 3; ++a) {
      const float origin = all.min[a];
      // The smallest step 2^e with origin + 255 * 2^e >= the union's max (e in [-126, 127]).
      int e = -126;
      const double extent = static_cast<double>(all.max[a]) - static_cast<double>(origin);
      if (extent > 0.0) {
        std::frexp(extent / 255.0, &e);  // extent / 255 < 2^e
        e = std::clamp(e, -126, 127);
      }
      while (e < 127 && BvhWideNode::Decode(origin, 255,
                                            BvhWideNode::Step(static_cast<int8_t>(e))) < all.max[a])
        ++e;
      n.origin[a] = origin;
      n.exponent[a] = static_cast<int8_t>(e);
      const float step = BvhWideNode::Step(n.exponent[a]);
      for (int i = 0; i < 4; ++i) {
        if (i >= k) {
          n.lo[a][i] = n.hi[a][i] = 0;
          continue;
        }
        const Bounds3& b = nodes[kids[i]].bounds;
        const double lo_q = std::floor((static_cast<double>(b.min[a]) - origin) / step);
        const double hi_q = std::ceil((static_cast<double>(b.max[a]) - origin) / step);
        int lo = static_cast<int>(std::clamp(lo_q, 0.0, 255.0));
        int hi = static_cast<int>(std::clamp(hi_q, 0.0, 255.0));
        while (lo > 0 && BvhWideNode::Decode(origin, static_cast<uint8_t>(lo), step) > b.min[a])
          --lo;
        while (hi < 255 && BvhWideNode::Decode(origin, static_cast<uint8_t>(hi), step) < b.max[a])
          ++hi;
        n.lo[a][i] = static_cast<uint8_t>(lo);
        n.hi[a][i] = static_cast<uint8_t>(hi);
      }
    }
    for (int i = 0; i < 4; ++i) {
      if (i >= k) {
        n.count[i] = BvhWideNode::kEmpty;
        n.child[i] = 0;
        continue;
      }
      const BvhNode& c = nodes[kids[i]];
      n.count[i] = static_cast<uint8_t>(c.count);
      n.child[i] = c.first;
    }
  }

  // b: a binary node; returns the index of the wide node holding b's children (or b itself when b
  // is a leaf, which happens only for a single-leaf tree's root).
  uint32_t Emit(uint32_t b, int depth) {
    max_depth = std::max(max_depth, depth);
    const uint32_t w = static_cast<uint32_t>(wide.size());
    wide.emplace_back();
    uint32_t kids[4];
    int k = 0;
    if (nodes[b].is_leaf()) {
      kids[k++] = b;
    } else {
      kids[k++] = nodes[b].first;
      kids[k++] = nodes[b].first + 1;
    }
    while (k < 4) {  // open the inner child of largest surface area (ties: the leftmost)
      int pick = -1;
      float best = 0.0f;
      for (int i = 0; i < k; ++i) {
        if (nodes[kids[i]].is_leaf()) continue;
        float a = nodes[kids[i]].bounds.SurfaceArea();
        if (pick < 0 || a > best) {
          pick = i;
          best = a;
        }
      }
      if (pick < 0) break;
      const uint32_t first = nodes[kids[pick]].first;
      for (int i = k; i > pick + 1; --i) kids[i] = kids[i - 1];
      kids[pick] = first;
      kids[pick + 1] = first + 1;
      ++k;
    }
    Quantise(wide[w], kids, k);
    for (int i = 0; i < k; ++i) {
      if (nodes[kids[i]].is_leaf()) continue;
      const uint32_t child = Emit(kids[i], depth + 1);  // may grow `wide`: index it afresh
      wide[w].child[i] = child;
    }
    return w;
  }
};

}  // namespace

void Bvh::BuildWide() {
  wide_.clear();
  wide_depth_ = 0;
  if (nodes_.empty()) return;
  wide_.reserve(nodes_.size() / 3 + 1);
  Widener widener{nodes_, wide_};
  widener.Emit(0, 1);
  wide_depth_ = widener.max_depth;
}

void Bvh::DecodeWideBoxes() {
  wide_boxes_.resize(wide_.size());
  for (std::size_t w = 0; w < wide_.size(); ++w) {
    const BvhWideNode& n = wide_[w];
    for (int a = 0; a < 3; ++a) {
      const float step = BvhWideNode::Step(n.exponent[a]);
      for (int k = 0; k < 4; ++k) {  // ChildBounds' expression, so its floats
        wide_boxes_[w].lo[a][k] = BvhWideNode::Decode(n.origin[a], n.lo[a][k], step);
        wide_boxes_[w].hi[a][k] = BvhWideNode::Decode(n.origin[a], n.hi[a][k], step);
      }
    }
  }
}

Bvh Bvh::Build(const TriMesh& mesh, const BvhOptions& options_in) {
  BvhOptions options = options_in;
  options.bins = std::clamp(options.bins, 2, kMaxBins);
  options.max_leaf_triangles = std::clamp(options.max_leaf_triangles, 1, 16);
  Bvh bvh;
  const std::size_t tris = mesh.triangle_count();
  if (tris == 0) return bvh;
  std::vector<Prim> prims(tris);
  auto builder = std::make_unique<Builder>(options, bvh.nodes_, prims);
  Builder& b = *builder;
  Bounds3 bounds, cbounds;
  for (std::size_t t = 0; t < tris; ++t) {
    Bounds3 tb;
    for (int k = 0; k < 3; ++k)
      tb.Extend(mesh.positions[mesh.indices[3 * t + static_cast<std::size_t>(k)]]);
    Prim& p = b.prims[t];
    p.lo = tb.min;
    p.hi = tb.max;
    p.tri = static_cast<uint32_t>(t);
    bounds.Extend(tb);
    cbounds.Extend(p.C());
  }
  bvh.nodes_.reserve(2 * tris / static_cast<std::size_t>(options.max_leaf_triangles) + 1);
  bvh.nodes_.emplace_back();
  b.Build(0, 0, tris, 1, bounds, cbounds);
  bvh.order_.resize(tris);
  bvh.corners_.resize(3 * tris);
  for (std::size_t i = 0; i < tris; ++i) {
    uint32_t t = b.prims[i].tri;
    bvh.order_[i] = t;
    for (std::size_t k = 0; k < 3; ++k)
      bvh.corners_[3 * i + k] = mesh.positions[mesh.indices[3 * static_cast<std::size_t>(t) + k]];
  }
  bvh.depth_ = b.max_depth;
  bvh.BuildWide();
  return bvh;
}

Bvh Bvh::Join(const Bvh& first, const Bvh& second) {
  if (second.empty()) return first;
  if (first.empty()) return second;  // no offset: first has no triangles
  const auto offset = static_cast<uint32_t>(first.order_.size());
  const auto n1 = static_cast<uint32_t>(first.nodes_.size());
  Bvh bvh;
  // Node 0 the new root, its children first's root (1) and second's (2), then first's other nodes
  // (i -> i + 2) and second's (j -> j + n1 + 1); children stay pairs, leaves keep their order()
  // ranges (second's after first's).
  bvh.nodes_.reserve(first.nodes_.size() + second.nodes_.size() + 1);
  BvhNode root;
  root.bounds = first.nodes_[0].bounds;
  root.bounds.Extend(second.nodes_[0].bounds);
  root.first = 1;
  root.count = 0;
  bvh.nodes_.push_back(root);
  auto moved = [](BvhNode n, uint32_t child_shift, uint32_t order_shift) {
    n.first += n.is_leaf() ? order_shift : child_shift;
    return n;
  };
  bvh.nodes_.push_back(moved(first.nodes_[0], 2, 0));
  bvh.nodes_.push_back(moved(second.nodes_[0], n1 + 1, offset));
  for (std::size_t i = 1; i < first.nodes_.size(); ++i)
    bvh.nodes_.push_back(moved(first.nodes_[i], 2, 0));
  for (std::size_t j = 1; j < second.nodes_.size(); ++j)
    bvh.nodes_.push_back(moved(second.nodes_[j], n1 + 1, offset));
  bvh.order_.reserve(first.order_.size() + second.order_.size());
  bvh.order_.insert(bvh.order_.end(), first.order_.begin(), first.order_.end());
  for (uint32_t t : second.order_) bvh.order_.push_back(t + offset);
  bvh.corners_.reserve(first.corners_.size() + second.corners_.size());
  bvh.corners_.insert(bvh.corners_.end(), first.corners_.begin(), first.corners_.end());
  bvh.corners_.insert(bvh.corners_.end(), second.corners_.begin(), second.corners_.end());
  bvh.depth_ = std::max(first.depth_, second.depth_) + 1;
  bvh.BuildWide();
  return bvh;
}

}  // namespace niwa::geom
