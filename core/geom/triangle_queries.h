// The per-triangle routines every geometry query shares, BVH and brute force alike, so both give
// the same triangle and the same distance bits: closest point on a triangle (Ericson, "Real-Time
// Collision Detection", 5.1.5) and ray/triangle (Möller–Trumbore 1997). Does not: loop over
// triangles or know the BVH.
//
// Precision: both work in double on float inputs (exact products of floats are not needed; double
// only keeps rounding far below float spacing), and are plain +−×÷ and sqrt, so they give the
// same bits natively and in WASM (no FMA contraction: CMake's -ffp-contract=off).
//
// Epsilon policy (Möller–Trumbore): a hit needs u >= -kEdgeEpsilon, v >= -kEdgeEpsilon and
// u + v <= 1 + kEdgeEpsilon (barycentrics are scale-free, so one relative epsilon fits metres and
// pixels). The slack makes the test watertight: a ray or segment through an edge or a vertex
// shared by two triangles hits at least one of them (usually both), never neither. A ray parallel
// to the plane (|det| <= kParallelEpsilon · |e1||e2||dir|) misses; so does a triangle of zero area.
#pragma once

#include <glm/vec3.hpp>

namespace niwa::geom {

constexpr double kEdgeEpsilon = 1e-9;
constexpr double kParallelEpsilon = 1e-12;

struct DVec3 {
  double x = 0, y = 0, z = 0;
};
inline DVec3 ToD(const glm::vec3& v) { return {v.x, v.y, v.z}; }
inline DVec3 Sub(const DVec3& a, const DVec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline DVec3 Add(const DVec3& a, const DVec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline DVec3 Mul(const DVec3& a, double s) { return {a.x * s, a.y * s, a.z * s}; }
inline double Dot(const DVec3& a, const DVec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline DVec3 Cross(const DVec3& a, const DVec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// Closest point of triangle abc to p, and its barycentrics (weights of a, b, c; they sum to 1).
struct TrianglePoint {
  DVec3 point;
  double u = 0, v = 0, w = 0;  // point = u a + v b + w c
  double distance_squared = 0;
};

// Ericson 5.1.5 ClosestPtPointTriangle: Voronoi regions of the vertices, then of the edges, else
// the face. For a degenerate triangle it still returns a point of the triangle (a vertex or edge
// point).
inline TrianglePoint ClosestPointOnTriangle(const DVec3& p, const DVec3& a, const DVec3& b,
                                            const DVec3& c) {
  TrianglePoint r;
  DVec3 ab = Sub(b, a), ac = Sub(c, a), ap = Sub(p, a);
  double d1 = Dot(ab, ap), d2 = Dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) {  // vertex region a
    r.point = a;
    r.u = 1;
  } else {
    DVec3 bp = Sub(p, b);
    double d3 = Dot(ab, bp), d4 = Dot(ac, bp);
    double vc, vb, va;
    DVec3 cp;
    double d5 = 0, d6 = 0;
    if (d3 >= 0.0 && d4 <= d3) {  // vertex region b
      r.point = b;
      r.v = 1;
    } else if ((vc = d1 * d4 - d3 * d2) <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {  // edge ab
      double t = d1 / (d1 - d3);
      r.point = Add(a, Mul(ab, t));
      r.u = 1 - t;
      r.v = t;
    } else if (cp = Sub(p, c), d5 = Dot(ab, cp), d6 = Dot(ac, cp); d6 >= 0.0 && d5 <= d6) {
      r.point = c;  // vertex region c
      r.w = 1;
    } else if ((vb = d5 * d2 - d1 * d6) <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {  // edge ac
      double t = d2 / (d2 - d6);
      r.point = Add(a, Mul(ac, t));
      r.u = 1 - t;
      r.w = t;
    } else if ((va = d3 * d6 - d5 * d4) <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
      double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));  // edge bc
      r.point = Add(b, Mul(Sub(c, b), t));
      r.v = 1 - t;
      r.w = t;
    } else {  // face region
      double sum = va + vb + vc;
      if (!(sum > 0.0)) {  // only reachable for degenerate input: fall back to vertex a
        r.point = a;
        r.u = 1;
      } else {
        double denom = 1.0 / sum;
        double v = vb * denom, w = vc * denom;
        r.point = Add(a, Add(Mul(ab, v), Mul(ac, w)));
        r.u = 1.0 - v - w;
        r.v = v;
        r.w = w;
      }
    }
  }
  DVec3 d = Sub(p, r.point);
  r.distance_squared = Dot(d, d);
  return r;
}

// Möller–Trumbore: origin + t·dir crosses triangle abc with t in [t_min, t_max]? On a hit sets
// *t and the barycentrics (u of b, v of c; a's weight is 1 - u - v). Both faces count.
inline bool RayTriangle(const DVec3& origin, const DVec3& dir, const DVec3& a, const DVec3& b,
                        const DVec3& c, double t_min, double t_max, double* t, double* u,
                        double* v) {
  DVec3 e1 = Sub(b, a), e2 = Sub(c, a);
  DVec3 pvec = Cross(dir, e2);
  double det = Dot(e1, pvec);
  double scale = Dot(e1, e1) * Dot(e2, e2) * Dot(dir, dir);  // (|e1||e2||dir|)²
  if (!(det * det > kParallelEpsilon * kParallelEpsilon * scale)) return false;
  double inv_det = 1.0 / det;
  DVec3 tvec = Sub(origin, a);
  double uu = Dot(tvec, pvec) * inv_det;
  if (uu < -kEdgeEpsilon || uu > 1.0 + kEdgeEpsilon) return false;
  DVec3 qvec = Cross(tvec, e1);
  double vv = Dot(dir, qvec) * inv_det;
  if (vv < -kEdgeEpsilon || uu + vv > 1.0 + kEdgeEpsilon) return false;
  double tt = Dot(e2, qvec) * inv_det;
  if (!(tt >= t_min && tt <= t_max)) return false;
  *t = tt;
  *u = uu;
  *v = vv;
  return true;
}

}  // namespace niwa::geom
