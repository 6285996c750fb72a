// Internal to core/geom: the per-triangle steps and result building that the BVH queries and
// their linear twins share, so both give the same bits. Does not: traverse anything.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <glm/vec3.hpp>
#include <limits>
#include <utility>

#include "geom/bounds.h"
#include "geom/bvh.h"
#include "geom/closest_point.h"
#include "geom/ray_cast.h"
#include "geom/tri_mesh.h"
#include "geom/triangle_queries.h"
#include "math/simd4.h"

namespace niwa::geom::detail {

// The traversal stacks' size. A wide node pushes at most 4 entries for the 1 it pops, and the wide
// tree is no deeper than the binary one (bvh.cpp keeps that <= 132): <= 3 * 132 + 1 entries.
constexpr int kMaxStack = 512;

// A stack entry of the wide traversals: a wide node (count == 0) or a leaf's triangles order()
// [index, index + count); key: the box's squared distance or slab entry, for pruning on pop.
struct WideEntry {
  uint32_t index;
  uint32_t count;
  double key;
};

// Sorts kids[0..k) by key, largest first, so pushing them in this order puts the nearest on top
// (on equal keys the leftmost child is pushed last, so it is searched first).
inline void SortDescending(WideEntry* kids, int k) {
  for (int i = 1; i < k; ++i)
    for (int j = i; j > 0 && kids[j - 1].key <= kids[j].key; --j) std::swap(kids[j - 1], kids[j]);
}

// Asks the cache for what popping e will read (a hint only: no effect on any result).
inline void Prefetch(const WideEntry& e, const BvhWideNode* wide, const glm::vec3* corners) {
#if defined(__GNUC__) || defined(__clang__)
  if (e.count == 0) {
    __builtin_prefetch(wide + e.index);  // one cache line
  } else {
    __builtin_prefetch(corners + 3 * static_cast<std::size_t>(e.index));
  }
#else
  (void)e, (void)wide, (void)corners;
#endif
}

inline void Corners(const TriMesh& mesh, uint32_t t, DVec3* a, DVec3* b, DVec3* c) {
  const std::size_t i = 3 * static_cast<std::size_t>(t);
  *a = ToD(mesh.positions[mesh.indices[i]]);
  *b = ToD(mesh.positions[mesh.indices[i + 1]]);
  *c = ToD(mesh.positions[mesh.indices[i + 2]]);
}

// Triangle t's corners from the mesh, as three consecutive floats triples (the layout of
// Bvh::corners()), so both paths feed the same floats to the same routine.
struct MeshCorners {
  glm::vec3 v[3];
  MeshCorners(const TriMesh& mesh, uint32_t t) {
    const std::size_t i = 3 * static_cast<std::size_t>(t);
    v[0] = mesh.positions[mesh.indices[i]];
    v[1] = mesh.positions[mesh.indices[i + 1]];
    v[2] = mesh.positions[mesh.indices[i + 2]];
  }
};

inline glm::vec3 ToF(const DVec3& v) {
  return glm::vec3(static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z));
}

// Squared max distance, or a negative value when nothing can be found (negative or NaN).
inline double MaxDistanceSquared(float max_distance) {
  if (!(max_distance >= 0.0f)) return -1.0;
  double d = max_distance;
  return d * d;
}

// Best-so-far of a closest-point search: smallest squared distance, ties to the lowest triangle.
struct ClosestState {
  explicit ClosestState(double max_d2) : best_d2(max_d2) {}
  double best_d2;
  uint32_t best_t = std::numeric_limits<uint32_t>::max();
  TrianglePoint best_point;
  bool found = false;

  // abc: the triangle's three corners, consecutive.
  void Test(const glm::vec3* abc, const DVec3& p, uint32_t t) {
    TrianglePoint q = ClosestPointOnTriangle(p, ToD(abc[0]), ToD(abc[1]), ToD(abc[2]));
    if (q.distance_squared < best_d2 || (q.distance_squared == best_d2 && t < best_t)) {
      best_d2 = q.distance_squared;
      best_t = t;
      best_point = q;
      found = true;
    }
  }
  ClosestHit Result() const {
    ClosestHit h;
    if (!found) return h;
    h.found = true;
    h.distance = static_cast<float>(std::sqrt(best_d2));
    h.point = ToF(best_point.point);
    h.triangle = best_t;
    h.barycentric = glm::vec3(static_cast<float>(best_point.u), static_cast<float>(best_point.v),
                              static_cast<float>(best_point.w));
    return h;
  }
};

// A ray prepared once per query: origin, unit direction (in double), and the inverse direction
// for the slab test. valid is false for a zero or non-finite direction.
struct PreparedRay {
  DVec3 origin, dir, inv;
  bool valid = false;
  bool oblique = false;  // no zero direction component: WideRayKeys' near/far path
};

inline PreparedRay PrepareRay(const glm::vec3& origin, const glm::vec3& dir, bool normalize) {
  PreparedRay r;
  r.origin = ToD(origin);
  r.dir = ToD(dir);
  if (normalize) {
    double len = std::sqrt(Dot(r.dir, r.dir));
    if (!(len > 0.0) || !std::isfinite(len)) return r;
    r.dir = Mul(r.dir, 1.0 / len);
  } else if (!(Dot(r.dir, r.dir) > 0.0) || !std::isfinite(Dot(r.dir, r.dir))) {
    return r;
  }
  if (!std::isfinite(r.origin.x) || !std::isfinite(r.origin.y) || !std::isfinite(r.origin.z))
    return r;
  r.inv = {1.0 / r.dir.x, 1.0 / r.dir.y, 1.0 / r.dir.z};  // ±inf on a zero component
  r.valid = true;
  r.oblique = r.dir.x != 0.0 && r.dir.y != 0.0 && r.dir.z != 0.0;
  return r;
}

// First hit so far: smallest t, ties to the lowest triangle.
struct RayState {
  explicit RayState(double max_t) : best_t(max_t) {}
  double best_t;
  uint32_t best_tri = std::numeric_limits<uint32_t>::max();
  double best_u = 0, best_v = 0;
  bool hit = false;

  void Test(const glm::vec3* abc, const PreparedRay& ray, uint32_t tri) {
    double t, u, v;
    if (!RayTriangle(ray.origin, ray.dir, ToD(abc[0]), ToD(abc[1]), ToD(abc[2]), 0.0, best_t, &t,
                     &u, &v))
      return;
    if (t < best_t || tri < best_tri) {  // t <= best_t here: ties go to the lower index
      best_t = t;
      best_tri = tri;
      best_u = u;
      best_v = v;
      hit = true;
    }
  }
  RayHit Result(const TriMesh& mesh, const PreparedRay& ray, bool normal = true) const {
    RayHit h;
    if (!hit) return h;
    h.hit = true;
    h.distance = static_cast<float>(best_t);
    h.point = ToF(Add(ray.origin, Mul(ray.dir, best_t)));
    h.triangle = best_tri;
    h.barycentric = glm::vec3(static_cast<float>(1.0 - best_u - best_v), static_cast<float>(best_u),
                              static_cast<float>(best_v));
    if (!normal) return h;
    DVec3 a, b, c;
    Corners(mesh, best_tri, &a, &b, &c);
    DVec3 n = Cross(Sub(b, a), Sub(c, a));
    double len = std::sqrt(Dot(n, n));
    if (len > 0.0) h.normal = ToF(Mul(n, 1.0 / len));
    return h;
  }
};

// Does the segment/ray origin + t dir, t in [0, 1] (unnormalized dir), touch triangle tri?
inline bool SegmentTriangle(const glm::vec3* abc, const PreparedRay& seg) {
  double t, u, v;
  return RayTriangle(seg.origin, seg.dir, ToD(abc[0]), ToD(abc[1]), ToD(abc[2]), 0.0, 1.0, &t, &u,
                     &v);
}

// Squared distance from p to box b (0 inside), in double.
inline double BoxDistanceSquared(const Bounds3& b, const DVec3& p) {
  double dx =
      std::max({static_cast<double>(b.min.x) - p.x, 0.0, p.x - static_cast<double>(b.max.x)});
  double dy =
      std::max({static_cast<double>(b.min.y) - p.y, 0.0, p.y - static_cast<double>(b.max.y)});
  double dz =
      std::max({static_cast<double>(b.min.z) - p.z, 0.0, p.z - static_cast<double>(b.max.z)});
  return dx * dx + dy * dy + dz * dz;
}

// BoxDistanceSquared of child slot k of a wide node.
inline double WideBoxDistanceSquared(const BvhWideNode& n, int k, const DVec3& p) {
  return BoxDistanceSquared(n.ChildBounds(k), p);
}

// Slab test: does origin + t dir meet box b for some t in [0, t_max]? Sets *t_near (entry, >= 0).
inline bool RayBox(const Bounds3& b, const PreparedRay& r, double t_max, double* t_near) {
  double lo = 0.0, hi = t_max;
  const double o[3] = {r.origin.x, r.origin.y, r.origin.z};
  const double d[3] = {r.dir.x, r.dir.y, r.dir.z};
  const double inv[3] = {r.inv.x, r.inv.y, r.inv.z};
  for (int k = 0; k < 3; ++k) {
    double bmin = b.min[k], bmax = b.max[k];
    if (d[k] == 0.0) {  // parallel to this slab: inside it or never
      if (o[k] < bmin || o[k] > bmax) return false;
      continue;
    }
    double t1 = (bmin - o[k]) * inv[k], t2 = (bmax - o[k]) * inv[k];
    if (t1 > t2) std::swap(t1, t2);
    lo = std::max(lo, t1);
    hi = std::min(hi, t2);
    if (lo > hi) return false;
  }
  *t_near = lo;
  return true;
}

// WideRayKeys for any ray (a zero direction component included): RayBox of each of a wide node's
// first `count` child boxes (ChildBounds) at once, the very IEEE
// operations of the scalar test lane by lane (math/simd4.h), so the keys are its bits: the boxes
// decoded in four float lanes, the slabs in two double lanes. Without NaNs (finite boxes, and a
// direction from floats, so a finite inverse) the scalar test's early outs only stop it sooner:
// lo never falls and hi never rises, so a box missed on one axis is missed after all three.
// Returns a bit per kept slot (empty slots too: the caller masks them); keys[k] its slab entry.
// Four children's box sides on axis a from their bytes q (lo or hi): BvhWideNode::Decode in four
// float lanes (a byte is exactly a float), shared by both slab tests below.
inline simd::Float4 DecodeWideSlabs(const BvhWideNode& n, int a, const uint8_t q[4]) {
  return simd::Splat4(n.origin[a]) +
         simd::BytesToFloat4(q) * simd::Splat4(BvhWideNode::Step(n.exponent[a]));
}

inline int WideRayKeysGeneral(const BvhWideNode& n, const PreparedRay& r, double t_max,
                              double keys[4]) {
  using simd::Double2;
  using simd::Float4;
  using simd::Long2;
  const double o[3] = {r.origin.x, r.origin.y, r.origin.z};
  const double d[3] = {r.dir.x, r.dir.y, r.dir.z};
  const double inv[3] = {r.inv.x, r.inv.y, r.inv.z};
  Double2 lo[2] = {simd::Splat2(0.0), simd::Splat2(0.0)};
  Double2 hi[2] = {simd::Splat2(t_max), simd::Splat2(t_max)};
  Long2 miss[2] = {Long2{0, 0}, Long2{0, 0}};
  for (int a = 0; a < 3; ++a) {
    const Float4 blo = DecodeWideSlabs(n, a, n.lo[a]), bhi = DecodeWideSlabs(n, a, n.hi[a]);
    const Double2 oa = simd::Splat2(o[a]), ia = simd::Splat2(inv[a]);
    for (int h = 0; h < 2; ++h) {
      const Double2 bmin{static_cast<double>(blo[2 * h]), static_cast<double>(blo[2 * h + 1])};
      const Double2 bmax{static_cast<double>(bhi[2 * h]), static_cast<double>(bhi[2 * h + 1])};
      if (d[a] == 0.0) {  // parallel to this slab: inside it or never
        miss[h] |= (oa < bmin) | (oa > bmax);
        continue;
      }
      const Double2 t1 = (bmin - oa) * ia, t2 = (bmax - oa) * ia;
      const Long2 swap = t1 > t2;
      const Double2 t_in = simd::Select(swap, t2, t1), t_out = simd::Select(swap, t1, t2);
      lo[h] = simd::Select(lo[h] < t_in, t_in, lo[h]);    // std::max(lo, t1)
      hi[h] = simd::Select(t_out < hi[h], t_out, hi[h]);  // std::min(hi, t2)
    }
  }
  int kept = 0;
  for (int h = 0; h < 2; ++h) {
    const Long2 out = miss[h] | (lo[h] > hi[h]);
    for (int j = 0; j < 2; ++j) {
      const int k = 2 * h + j;
      if (out[j] == 0) {
        keys[k] = lo[h][j];
        kept |= 1 << k;
      }
    }
  }
  return kept;
}

// RayBox of each of a wide node's child boxes (ChildBounds) at once, with RayBox's keys, bit for
// bit. An oblique ray (no zero direction component; PrepareRay) takes the near/far form: on an axis
// with dir > 0 RayBox's (t1, t2) are never swapped (t1 <= t2 when bmin <= bmax and the inverse is
// finite and positive), with dir < 0 they are, or are equal; so the entry is the near side's t and
// the exit the far side's, chosen once per axis, and std::max/std::min become their lane-wise twins
// (simd::Max, simd::Min). The boxes are decoded as ChildBounds does (float lanes),
// then widened to double. Any other ray goes through WideRayKeysGeneral. Returns a bit per kept
// slot (empty slots too: the caller masks them); keys[k] its slab entry.
inline int WideRayKeys(const BvhWideNode& n, const PreparedRay& r, double t_max, double keys[4]) {
  if (!r.oblique) return WideRayKeysGeneral(n, r, t_max, keys);
  using simd::Double2;
  using simd::Float4;
  using simd::Long2;
  const double o[3] = {r.origin.x, r.origin.y, r.origin.z};
  const double d[3] = {r.dir.x, r.dir.y, r.dir.z};
  const double inv[3] = {r.inv.x, r.inv.y, r.inv.z};
  Double2 lo0 = simd::Splat2(0.0), lo1 = lo0;
  Double2 hi0 = simd::Splat2(t_max), hi1 = hi0;
  for (int a = 0; a < 3; ++a) {
    const bool forward = d[a] > 0.0;
    const Float4 b_near = DecodeWideSlabs(n, a, forward ? n.lo[a] : n.hi[a]);
    const Float4 b_far = DecodeWideSlabs(n, a, forward ? n.hi[a] : n.lo[a]);
    const Double2 oa = simd::Splat2(o[a]), ia = simd::Splat2(inv[a]);
    const Double2 t_in0 = (simd::LowToDouble2(b_near) - oa) * ia;
    const Double2 t_in1 = (simd::HighToDouble2(b_near) - oa) * ia;
    const Double2 t_out0 = (simd::LowToDouble2(b_far) - oa) * ia;
    const Double2 t_out1 = (simd::HighToDouble2(b_far) - oa) * ia;
    lo0 = simd::Max(lo0, t_in0);  // std::max(lo, t1)
    lo1 = simd::Max(lo1, t_in1);
    hi0 = simd::Min(hi0, t_out0);  // std::min(hi, t2)
    hi1 = simd::Min(hi1, t_out1);
  }
  const Long2 out0 = lo0 > hi0, out1 = lo1 > hi1;
  int kept = 0;
  if (out0[0] == 0) keys[0] = lo0[0], kept |= 1;
  if (out0[1] == 0) keys[1] = lo0[1], kept |= 2;
  if (out1[0] == 0) keys[2] = lo1[0], kept |= 4;
  if (out1[1] == 0) keys[3] = lo1[1], kept |= 8;
  return kept;
}

// A ray for the float slab test below (WideRayKeysConservative): its origin (floats: the caller's,
// exactly) and the double inverse direction rounded to float. usable is false (the caller keeps
// WideRayKeys) unless the ray is oblique, each |inverse| is at most 2^40 and each |origin| and
// |root box side| at most 2^40: then no float product below overflows (|box side − origin| < 2^43
// for the wide boxes, which lie within a few of their parent's extents of the root box, times 2^40)
// and none underflows (|inverse| >= 1 for a unit direction).
struct FloatSlabRay {
  // Each in all four lanes; set only when usable (not zeroed first: FirstHit builds one a ray,
  // and the zeroing was a 112-byte store per ray).
  simd::Float4 origin[3], inv[3];
  bool usable = false;
};

inline FloatSlabRay PrepareFloatSlabRay(const PreparedRay& r, const glm::vec3& origin,
                                        const Bounds3& root) {
  FloatSlabRay f;
  if (!r.valid || !r.oblique) return f;
  constexpr double kLimit = 1099511627776.0;  // 2^40
  const double inv[3] = {r.inv.x, r.inv.y, r.inv.z};
  for (int a = 0; a < 3; ++a) {
    if (!(std::fabs(inv[a]) <= kLimit) || !(std::fabs(origin[a]) <= kLimit) ||
        !(std::fabs(root.min[a]) <= kLimit) || !(std::fabs(root.max[a]) <= kLimit))
      return f;
    f.origin[a] = simd::Splat4(origin[a]);
    f.inv[a] = simd::Splat4(static_cast<float>(inv[a]));
  }
  f.usable = true;
  return f;
}

// The first float >= t (t >= 0, or +inf), for the float test's upper limit.
inline float FloatAtLeast(double t) {
  if (!(t < 3.0e38)) return std::numeric_limits<float>::infinity();
  const float f = static_cast<float>(t);
  return static_cast<double>(f) >= t ? f : f + f * 0x1p-22f;
}

// The conservative slab test's last step, shared by WideRayKeysConservative and its decoded-box
// twin (so both widen alike): lo >= 0 lowered by a relative 2^-20 and 2^-120; hi raised the same
// way when >= 0 (a negative exit means WideRayKeys' exit is negative too, below its entry >= 0: a
// miss either way, so how it is widened does not matter). Returns the kept lanes' bits, keys[k] =
// the widened entry of lane k.
inline int WidenedLaneKeys(simd::Float4 lo, simd::Float4 hi, double keys[4]) {
  const simd::Float4 tiny = simd::Splat4(0x1p-120f);
  lo = lo * simd::Splat4(1.0f - 0x1p-20f) - tiny;
  hi = hi * simd::Splat4(1.0f + 0x1p-20f) + tiny;
  const int kept = simd::LaneBits(lo <= hi);
  for (int k = 0; k < 4; ++k) keys[k] = static_cast<double>(lo[k]);
  return kept;
}

// A conservative twin of WideRayKeys in float lanes: all four child boxes at once, four lanes a
// step instead of two doubles, and no widening to double. It keeps every child WideRayKeys keeps
// (perhaps more) and keys it at most at WideRayKeys' key, so a walk with it tests every triangle
// the exact walk tests (perhaps more, never pruned wrongly) and finds the same first hit: the
// answer is the lowest (t, triangle) among the triangles the slab tests let through, and those
// always include the winner. Why the bounds hold: the boxes are decoded as ChildBounds does (the
// same floats); a slab distance (side − origin)·inverse is worked out here with three roundings
// to float (the difference, the inverse, the product) and by WideRayKeys with three to double, so
// the two lie within a relative 2^-22 of each other and have the same sign (the difference of two
// floats is zero only when they are equal, in either precision); the entries' largest and the
// exits' smallest are then widened by a relative 2^-20 and an absolute 2^-120 (the latter for
// subnormal products), outward: entry down, exit up. Returns a bit per kept slot (empty slots
// too: the caller masks them); keys[k] its (lowered) slab entry.
inline int WideRayKeysConservative(const BvhWideNode& n, const FloatSlabRay& r, double t_max,
                                   double keys[4]) {
  using simd::Float4;
  static_assert(offsetof(BvhWideNode, hi) == offsetof(BvhWideNode, lo) + 12, "lo, hi adjacent");
  Float4 q[6];  // lo[0..2], hi[0..2] as floats
  simd::Bytes24ToFloat4(&n.lo[0][0], q);
  // The node's origin (lanes 0-2) and steps 2^exponent (lanes 0-2; BvhWideNode::Step's bits).
  const Float4 origin = simd::LoadFloat4(n.origin);
  const Float4 step = simd::ExponentBytesToPowers(n.exponent);
  Float4 lo = simd::Splat4(0.0f);
  Float4 hi = simd::Splat4(FloatAtLeast(t_max));
  const Float4 origins[3] = {simd::LaneSplat<0>(origin), simd::LaneSplat<1>(origin),
                             simd::LaneSplat<2>(origin)};
  const Float4 steps[3] = {simd::LaneSplat<0>(step), simd::LaneSplat<1>(step),
                           simd::LaneSplat<2>(step)};
  for (int a = 0; a < 3; ++a) {
    // ChildBounds' decode (origin + q·step, the same floats), then the slab distances; the entry
    // is the nearer side's (forward: lo; else hi): min and max of the two give the same lanes.
    const Float4 t_lo = ((origins[a] + q[a] * steps[a]) - r.origin[a]) * r.inv[a];
    const Float4 t_hi = ((origins[a] + q[3 + a] * steps[a]) - r.origin[a]) * r.inv[a];
    lo = simd::MaxNoNaN(lo, simd::MinNoNaN(t_lo, t_hi));
    hi = simd::MinNoNaN(hi, simd::MaxNoNaN(t_lo, t_hi));
  }
  return WidenedLaneKeys(lo, hi, keys);
}

// WideRayKeysConservative from a node's decoded boxes (Bvh::wide_boxes(): the floats its decode
// gives, stored), so the same lanes, keys and kept bits, without the bytes' decode at each visit.
inline int WideRayKeysConservativeDecoded(const BvhWideBoxes& b, const FloatSlabRay& r,
                                          double t_max, double keys[4]) {
  using simd::Float4;
  Float4 lo = simd::Splat4(0.0f);
  Float4 hi = simd::Splat4(FloatAtLeast(t_max));
  for (int a = 0; a < 3; ++a) {
    const Float4 t_lo = (simd::LoadFloat4(b.lo[a]) - r.origin[a]) * r.inv[a];
    const Float4 t_hi = (simd::LoadFloat4(b.hi[a]) - r.origin[a]) * r.inv[a];
    lo = simd::MaxNoNaN(lo, simd::MinNoNaN(t_lo, t_hi));
    hi = simd::MinNoNaN(hi, simd::MaxNoNaN(t_lo, t_hi));
  }
  return WidenedLaneKeys(lo, hi, keys);
}

// A wide node's used slots (they fill from 0; an unused one's count is kEmpty, 0xff), without a
// loop: the lowest byte of ~count that is zero, by the has-zero-byte trick (exact for the lowest
// zero byte, the only one read), else 4.
inline int UsedSlots(const BvhWideNode& n) {
  uint32_t c;
  std::memcpy(&c, n.count, sizeof c);
  const uint32_t x = ~c;  // byte k: 0 where slot k is unused
  const uint32_t zero = (x - 0x01010101u) & ~x & 0x80808080u;
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
  return zero == 0 ? 4 : __builtin_ctz(zero) >> 3;
#else
  int slots = 0;
  while (slots < 4 && n.count[slots] != BvhWideNode::kEmpty) ++slots;
  return slots;
#endif
}

// The index of the lowest set bit of bits (bits != 0).
inline int LowestBit(unsigned bits) { return __builtin_ctz(bits); }

// The nearest-first depth-first walk that ClosestPoint and FirstHit share. From the root (pushed
// with root_key), it pops an entry, skips it when its key is beyond query.Bound() (the best got
// closer since it was pushed; ties kept), tests a leaf's triangles with
// query.Test(corners of slot i, order()[i]), and for a wide node keys each child with
// query.Key(box, &key) (false: pruned), pushes the kept ones farthest first (so the nearest, or
// the leftmost on equal keys, is searched first) and prefetches them. query.Keys(node, slots, keys)
// keys a node's first `slots` children at once (a bit per kept one). Counts into *visited (boxes
// tested, the root's included) and *tested (triangles).
template <typename Query>
void NearestFirstWalk(const Bvh& bvh, double root_key, Query& query, uint64_t* visited,
                      uint64_t* tested) {
  const BvhWideNode* wide = bvh.wide_nodes().data();
  const uint32_t* order = bvh.order().data();
  const glm::vec3* corners = bvh.corners().data();
  WideEntry stack[kMaxStack];
  int top = 0;
  stack[top++] = {0, 0, root_key};
  while (top > 0) {
    const WideEntry e = stack[--top];
    if (e.key > query.Bound()) continue;
    if (e.count > 0) {  // a leaf
      for (uint32_t i = e.index; i < e.index + e.count; ++i)
        query.Test(&corners[3 * static_cast<std::size_t>(i)], order[i]);
      *tested += e.count;
      continue;
    }
    const BvhWideNode& n = wide[e.index];
    WideEntry kids[4];
    int k = 0;
    const int slots = UsedSlots(n);
    *visited += static_cast<uint64_t>(slots);
    double keys[4];
    // The kept used slots, lowest first (as a loop over the slots would take them).
    for (unsigned bits = static_cast<unsigned>(query.Keys(n, slots, keys)) & ((1u << slots) - 1u);
         bits != 0; bits &= bits - 1) {
      const int i = LowestBit(bits);
      kids[k++] = {n.child[i], n.count[i], keys[i]};
    }
    SortDescending(kids, k);
    for (int i = 0; i < k; ++i) {
      Prefetch(kids[i], wide, corners);
      stack[top++] = kids[i];
    }
  }
}

}  // namespace niwa::geom::detail
