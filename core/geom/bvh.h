// Bvh: a deterministic bounding volume hierarchy over a TriMesh's triangles (binned SAH, flat node
// array), the accelerator under closest_point, ray_cast and their users (ivy adhesion and
// collisions, moss photons). Does not: answer queries (closest_point.h, ray_cast.h do), refit or
// update after the mesh changes (build again), or own the mesh.
//
// Why no library (apt-cache, 2026-12-01; none of these is installed here, none was built):
// libembree-dev (Embree 3: compiled x86 SIMD kernels, no Emscripten build), libbullet-dev
// (compiled .so; btDbvt is a dynamic AABB tree) and libcgal-dev 5.5.1 (AABB_tree is header-only
// but needs the Boost headers, and GMP unless CGAL_DISABLE_GMP; not tried under em++ 3.1.6).
// `apt-cache search bvh` finds no BVH library. Beyond the build, the callers need what none of them
// gives: the very per-triangle routine and lowest-index tie rule of the brute-force twins (same
// triangle, same distance bits), segment any-hit with a stated edge epsilon, and visit counts
// (QueryStats). So this is a small one, checked against linear_queries.h on every test mesh.
//
// Build: centroids binned along the widest axis (Wald 2007), SAH cost N_L·A_L + N_R·A_R per bin
// boundary, leaves of at most max_leaf_triangles.
//
// Layout (why: at 4 M triangles the tree is ~67 MB and a query's cost is cache misses, one per
// level, not box tests): the binary SAH tree (nodes(), 32-byte nodes, children as a pair) is
// collapsed into a 4-wide tree (wide_nodes()), which is what the queries traverse. A wide node is
// 64 bytes (one cache line; it was 128 with float child boxes, see BvhWideNode), holds its
// up-to-four children's boxes side by side (so they are tested from the parent, and a pruned child
// is never fetched) and is stored depth first. That halves the dependent fetches per query (depth
// 13 -> 6 on a 16 k wall); pushed children are prefetched (a hint; its own gain was within the
// noise). Measured (native, one interleaved run of 5 rounds against the binary traversal, loaded
// 2-core machine, median ns per query, 4 M / 4 k): closest 5.2x -> 3.4x, closest-walk 6.9x -> 3.3x,
// segment 5.2x -> 4.3x (fastest reps: 6.1 -> 3.7, 5.6 -> 4.0, 2.9 -> 2.6). Tried and dropped:
// reading order() only for a winning triangle (did not pay). The binary nodes stay (the wide tree
// adds ~1/6 of their count at 64 bytes each): the build, the structure tests and the determinism
// digest read them.
//
// Closest-point growth 4 k -> 4 M (issue 15's 3x goal; NOT shown met; 2026-12-03). Quiet records
// gave 571 -> 1834 ns (3.2x) at 2.15x the instructions (callgrind; 21.9 -> 46.2 box tests, wide
// depth 5 -> 10): the rest is the bottom node levels (~21 MB) and the leaves missing cache and TLB
// one after another down one path. Cutting instructions per box cannot close it (4 k speeds up as
// much and the ratio rises), so these cut the memory chain; each was measured with a probe (the
// walls and queries of bench/geom_workloads.cpp; thread CPU time, so other processes' time slices
// are not counted; 10 batches of 2,000 queries, each timed 9 times, fastest kept; old and new in
// alternate processes, 3 times each; 2 cores at load average 9-18, which inflates the old ratio
// to 3.9-4.8x), ns per closest query, old -> new:
// - prefetching the nearest inner child's 4 depth-first successors with it (two levels above the
//   leaves they are exactly its children) in trees of >= 16 k wide nodes, plus each leaf
//   triangle's index stored beside its corners (40-byte records, order() not read): 4 k
//   460/491/501 -> 490/488/478, 65 k 748/826/796 -> 866/831/805, 1 M 1403/1750/1576 ->
//   1462/1451/1458, 4 M 1837/2232/1974 -> 2078/2051/1936 (4M/4k 4.00/4.55/3.94x ->
//   4.24/4.21/4.05x; segment 4 M 443/549/489 -> 499/489/463): within the noise, not kept.
// - the same plus the two query arrays on 2 MB pages (an allocator that madvise(MADV_HUGEPAGE)s
//   arrays of >= 4 MB before first use; 186 MB of AnonHugePages at 4 M): 4 M 2209/2348/2466 ->
//   1716/1837/1810 (4M/4k 4.53-4.75x -> 3.40-3.67x; segment 4 M 549-602 -> 419-451); huge pages
//   alone -4 to -12 % at 4 M. Not kept: the bench runner's builds got slower (interleaved, load
//   7-9, ns per triangle: 262 k warm 313 -> 470, cold 4 M 570 -> 684; without huge pages 305 and
//   578), fresh 2 MB pages being faulted in on every build. Huge pages alone on today's code
//   (probe, load 4, the arrays collapsed after the build with MADV_COLLAPSE): 4 M 2162/1739/1998
//   -> 1522/1579/1606 ns with 4 k unchanged (461-482), 4M/4k 3.77-4.49x -> 3.30-3.45x; the wide
//   nodes alone (20 MB) gave under half of that. But the collapse itself took 193-457 ms at 4 M
//   (+0.05-0.11 s per million triangles on a ~0.35 s build) and 17-56 ms at 1 M. So this is the
//   one lever seen to cut 4 M by a fifth or more, and every way of getting the pages found here
//   costs the build 15-50 %; it needs arrays kept across builds (a pool) to be worth it.
// - that pool (page_pool.h on branch hugepool15, 2026-12-03; NOT merged, the branch keeps the code): 2 MB-aligned mmap regions
//   advised MADV_HUGEPAGE, kept on a process-wide free list across builds, for every array of
//   >= 4 MB (B: nodes, wide nodes, order, corners, the build's scratch) or the query arrays only
//   (C). Bench runner, main (A) against B (and C), interleaved in fresh processes, 3 runs of 8, 6
//   and 6 rounds at load average 1.3-5.8; ns per query, fastest rep (median of run medians):
//   closest 4 M A 1765-1860 (2284-2427), B 1629-1716 (1980-2078), C 1655-1740 (1927-2212), 4 k
//   451-474 in all; 4M/4k closest A 3.79-4.05x (3.61-4.77x), B 3.45-3.81x (3.71-3.79x), C
//   3.65-3.83x (3.62-4.18x); segment (4 M A 447-463, B 390-395, C 403-411) A 3.51-3.64x, B
//   2.92-3.02x, C 3.18-3.20x. Warm builds (regions reused) about even, ns per triangle fastest: 1 M
//   A 160-163, B 145-199, C 148-173; 262 k A 139-148, B 143-150, C 170-178. But the first build in
//   a process is slower: bvh-build-cold/wall-4m A 219-264, B 450-539, C 355-399 (medians A
//   353-374, B 507-606, C 475-521; B breaks the 0.5 s per million goal), while cold 1 M was A
//   214-244, B 177-198, C 217-269. Cause, on this VM: the virtio balloon has free page reporting,
//   so free 2 MB blocks are handed back to the host and a fresh huge page faults there too (first
//   touch of 450 MB after 10 s idle: 1.6-1.7 s in 2 MB pages against 0.21-0.27 s in 4 KiB pages,
//   0.05-0.07 s in 2 MB pages right after another such touch; cold 4 M build, /usr/bin/time, sys
//   0.57 s A, 0.79 s C, 0.96 s B). So the pool pays only in a process that builds more than once
//   (the CLI builds once; WASM has no pool), its first build costs up to ~0.3 s per million more
//   here, and closest stays above 3x: not kept.
// - 8-wide nodes (128 bytes, wide depth 10 -> 7 at 4 M): slower at both ends (4 k 538-607 against
//   482-487, 4 M 2685-3106 against 2337-2407: 28 and 60 box tests instead of 22 and 46, two lines
//   a node); a float pre-reject of the child boxes before the double test (scalar: g++ -O3 did not
//   vectorise it): 4 k +8-13 %, 4 M +12-21 %; prefetching every line of a leaf, not its first:
//   4 M +11-30 %.
// The ratio itself moves with the machine: the unchanged code gave 4.18x and 4.73x in the bench
// runner (niwa_bench_runner --filter closest/wall-, fastest reps; 4 k 451/452, 4 M 1884/2139 ns)
// at load average 2.7, against the records' 3.2x: the 4 M cost depends on cache and memory state
// beyond this 2-core VM (its 32 MB L3 is shared), so a goal on it needs one fixed quiet machine.
//
// Determinism: the build runs in a fixed order (recursive, left child first), with float bounds
// and double SAH costs; ties between split candidates go to the lowest axis and bin. Natively
// (NIWA_HAVE_THREADS) the root's two halves of a mesh of 64 k triangles or more are built on two
// threads, each into its own array, and spliced in the one-thread order. Same mesh, same options:
// the same nodes, bit for bit, on every build, with or without threads (native == WASM).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "geom/bounds.h"
#include "geom/tri_mesh.h"

namespace niwa::geom {

struct BvhOptions {
  int bins = 16;               // SAH bins per axis, clamped to [2, 64]
  int max_leaf_triangles = 4;  // a node with at most this many triangles stays a leaf; [1, 16]
  bool all_axes = false;       // SAH over all three axes, not only the widest (slower build)
  bool threads = true;         // where the build has threads: the root's halves on two (same nodes)
};

// One node, 32 bytes. A leaf (count > 0) holds triangles order[first .. first + count); an inner
// node (count == 0) has children first and first + 1 (allocated as a pair).
struct BvhNode {
  Bounds3 bounds;  // padded a few ulps outward so rounding in the queries never misses a triangle
  uint32_t first = 0;
  uint32_t count = 0;
  bool is_leaf() const { return count > 0; }
};

// The queries' tree: the binary tree collapsed to 4 wide (each node keeps up to four of the binary
// nodes below it, splitting the child of largest surface area first). A node holds its children's
// boxes, so a traversal tests all four from the parent and fetches only the children it enters:
// one 64-byte, 64-aligned node (one cache line) per step, about half the binary depth.
// The child boxes are quantised to 8 bits per side on a grid over the node's own box (origin plus
// q * 2^exponent per axis), rounded outward and checked in the build with the very float
// expression ChildBounds() uses, so a decoded box always contains the binary child's box: the
// queries prune a little less, never wrongly, and their answers stay those of the linear twins.
struct alignas(64) BvhWideNode {
  static constexpr uint8_t kEmpty = 0xff;  // count of an unused slot (slots fill from 0)
  float origin[3];     // the grid's origin: the min corner of the union of the child boxes
  int8_t exponent[3];  // grid step 2^exponent per axis, in [-126, 127]
  uint8_t count[4];    // 0: inner child; 1..16: a leaf of that many triangles; kEmpty: unused
  uint8_t lo[3][4];    // child k's box on axis a: origin[a] + lo[a][k] * step[a] ..
  uint8_t hi[3][4];    //                          origin[a] + hi[a][k] * step[a]
  uint32_t child[4];   // inner child: its wide node index; leaf child: its first slot in order()
  static float Step(int8_t e) {  // 2^e for e in [-126, 127], from its bits (no libm)
    uint32_t bits = static_cast<uint32_t>(e + 127) << 23;
    float f;
    std::memcpy(&f, &bits, sizeof f);
    return f;
  }
  static float Decode(float origin, uint8_t q, float step) {
    return origin + static_cast<float>(q) * step;
  }
  Bounds3 ChildBounds(int k) const {
    glm::vec3 lo_c, hi_c;
    for (int a = 0; a < 3; ++a) {
      const float step = Step(exponent[a]);
      lo_c[a] = Decode(origin[a], lo[a][k], step);
      hi_c[a] = Decode(origin[a], hi[a][k], step);
    }
    return Bounds3{lo_c, hi_c};
  }
};
static_assert(sizeof(BvhWideNode) == 64, "one cache line");

// A wide node's four child boxes decoded (BvhWideNode::ChildBounds' floats, every slot's bytes, the
// empty slots' too), side by side per axis for four float lanes: lo[a][k], hi[a][k]. Bvh keeps them
// beside the wide nodes on request (Bvh::DecodeWideBoxes), for ray casts that key the children in
// float lanes without decoding the bytes at every visit (the moss photons: ~4 nodes a ray).
struct alignas(32) BvhWideBoxes {
  float lo[3][4];
  float hi[3][4];
};
static_assert(sizeof(BvhWideBoxes) == 96, "three half lines");

class Bvh {
 public:
  Bvh() = default;
  // Builds over every triangle of `mesh` (which should pass ValidateMesh; queries must pass the
  // same, unchanged mesh; a mesh with no triangles gives an empty tree that every query misses).
  // Degenerate triangles are kept (they never win a query the linear twins would not also give
  // them).
  static Bvh Build(const TriMesh& mesh, const BvhOptions& options = {});
  // The tree of a mesh made of `first`'s mesh's triangles followed by `second`'s (its triangle
  // indices offset by first.triangle_count(), its vertices the same floats), from the two trees as
  // they are: a root over the two roots, then the wide tree again. Not Build's nodes over the
  // joined mesh, but the same answers to every query (closest_point's and ray_cast's ties go to the
  // lowest triangle index, so an answer does not depend on the tree's shape). For a part that does
  // not change (the garden's ground and objects, built once) beside one that does (its trunks).
  static Bvh Join(const Bvh& first, const Bvh& second);

  int node_count() const { return static_cast<int>(nodes_.size()); }
  int depth() const { return depth_; }  // levels; 1 for a single leaf, 0 when empty
  std::size_t triangle_count() const { return order_.size(); }
  bool empty() const { return nodes_.empty(); }

  // Root is node 0.
  const std::vector<BvhNode>& nodes() const { return nodes_; }
  // The 4-wide tree the queries traverse (root is node 0; empty when nodes() is), and its depth
  // in wide levels.
  const std::vector<BvhWideNode>& wide_nodes() const { return wide_; }
  int wide_depth() const { return wide_depth_; }
  // wide_nodes()' child boxes decoded, one entry a wide node, after DecodeWideBoxes (else empty).
  // 96 bytes a wide node more (1.5x the wide tree); FirstHit reads them when they are there (the
  // same keys as the bytes give, so the same walk and hit).
  const std::vector<BvhWideBoxes>& wide_boxes() const { return wide_boxes_; }
  void DecodeWideBoxes();
  // Triangle indices in leaf order.
  const std::vector<uint32_t>& order() const { return order_; }
  // The corners of order()[i] at 3i, 3i+1, 3i+2: a copy of the mesh's positions in leaf order, so a
  // leaf's triangles are read from one run of memory (36 bytes per triangle).
  const std::vector<glm::vec3>& corners() const { return corners_; }

 private:
  friend struct BvhTestAccess;  // tests break a node on purpose to see the oracle tests fail
  void BuildWide();             // wide_ from nodes_ (deterministic: depth first, left to right)
  std::vector<BvhNode> nodes_;
  std::vector<BvhWideNode> wide_;
  std::vector<BvhWideBoxes> wide_boxes_;
  int wide_depth_ = 0;
  std::vector<uint32_t> order_;
  std::vector<glm::vec3> corners_;
  int depth_ = 0;
};

}  // namespace niwa::geom
