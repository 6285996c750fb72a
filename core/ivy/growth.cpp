// Ivy growth: rules p0-p3 and the nutrient ledger (spec E1-E5), the position search (E6-E10) and
// the lateral frame (E11). Every choice the paper leaves open is argued in docs/ivy-model.md.
#include "ivy/growth.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <glm/geometric.hpp>
#include <string>

#include "geom/closest_point.h"
#include "geom/linear_queries.h"
#include "geom/ray_cast.h"
#include "ivy/ivy_budget.h"
#include "ivy/segment_grid.h"
#include "math/det_math.h"
#include "params/param_text.h"
#include "random/pcg32.h"
#include "run/study_run.h"

namespace niwa::ivy {

char BudSymbol(BudKind kind) {
  return kind == BudKind::kApical ? 'A' : kind == BudKind::kDormant ? 'D' : 'Z';
}

const char* RejectName(int reason) {
  static const char* names[] = {"gravitropism", "bend",     "far", "near",
                                "collision",    "crowding", "body"};
  return reason >= 0 && reason < kRejectCount ? names[reason] : "";
}

glm::dvec3 TriangleNormal(const geom::TriMesh& mesh, uint32_t triangle) {
  const glm::dvec3 a(mesh.positions[mesh.indices[3 * triangle]]);
  const glm::dvec3 b(mesh.positions[mesh.indices[3 * triangle + 1]]);
  const glm::dvec3 c(mesh.positions[mesh.indices[3 * triangle + 2]]);
  glm::dvec3 n = glm::cross(b - a, c - a);
  double len = std::sqrt(glm::dot(n, n));
  return len > 0 ? n / len : glm::dvec3(0, 0, 1);
}

double SegmentSegmentDistance(const glm::dvec3& p1, const glm::dvec3& q1, const glm::dvec3& p2,
                              const glm::dvec3& q2) {
  const glm::dvec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const double a = glm::dot(d1, d1), e = glm::dot(d2, d2), f = glm::dot(d2, r);
  double s = 0, t = 0;
  const double kTiny = 1e-30;
  if (a <= kTiny && e <= kTiny) {
    s = t = 0;
  } else if (a <= kTiny) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = glm::dot(d1, r);
    if (e <= kTiny) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = glm::dot(d1, d2), denom = a * e - b * b;
      s = denom > kTiny ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0) {
        t = 0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1) {
        t = 1;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  const glm::dvec3 diff = (p1 + d1 * s) - (p2 + d2 * t);
  return std::sqrt(glm::dot(diff, diff));
}

namespace {

constexpr double kTol = 1e-9;  // threshold comparison tolerance (spec §4 item 3)
constexpr double kDeg = det::kPi / 180.0;

glm::dvec3 Unit(const glm::dvec3& v) {
  double len = std::sqrt(glm::dot(v, v));
  return len > 0 ? v / len : v;
}
double Length(const glm::dvec3& v) { return std::sqrt(glm::dot(v, v)); }
glm::vec3 F(const glm::dvec3& v) { return glm::vec3(v); }

double AngleBetween(const glm::dvec3& a, const glm::dvec3& b) {
  return det::Acos(std::clamp(glm::dot(a, b), -1.0, 1.0));
}

// SplitMix64 over the key (seed, bud, step, attempt): the candidates' stream (E6).
uint64_t Mix(uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}
uint64_t Key(uint64_t seed, int bud, int step, int attempt) {
  uint64_t h = Mix(seed);
  h = Mix(h ^ static_cast<uint64_t>(bud));
  h = Mix(h ^ static_cast<uint64_t>(step));
  return Mix(h ^ static_cast<uint64_t>(attempt));
}

struct Placement {
  glm::dvec3 q{0.0}, u{0.0};
  geom::ClosestHit anchor;
};

// The lowest-scoring valid candidate so far (on equal scores the first stays): the random walk's
// and the tangent fan's choice.
struct BestPlacement {
  bool found = false;
  double score = 0;
  Placement place;
  void Offer(const Placement& candidate, double candidate_score) {
    if (!found || candidate_score < score) {
      found = true;
      score = candidate_score;
      place = candidate;
    }
  }
};

}  // namespace

// Outside the anonymous namespace: IvyGrowth::Impl holds one.
namespace growth_detail {

class Grower {
 public:
  Grower(const Support& support, const IvyParams& p, uint64_t seed, GrowLog* log)
      : s_(support), p_(p), seed_(seed), log_(log) {
    L_ = p.Get(IvyParam::kL);
    d_ = p.Get(IvyParam::kD);
    eps_ = p.Get(IvyParam::kEps);
    up_ = Unit(glm::dvec3(p.Get(IvyParam::kUpX), p.Get(IvyParam::kUpY), p.Get(IvyParam::kUpZ)));
    // Cells at least as large as the avoidance radius: a query touches at most 4^3 cells.
    grid_ = SegmentGrid(std::max(L_, p.Get(IvyParam::kAvoid)));
  }

  bool free() const { return s_.mesh == nullptr; }

  // IvyGrowth::SetSupport: the new support; buds anchored at or past `kept` re-anchored on it.
  void SetSupport(const Support& support, uint32_t kept) {
    s_ = support;
    if (free()) return;
    for (Bud& b : m_.buds) {
      if (b.anchor_tri < 0 || static_cast<uint32_t>(b.anchor_tri) < kept) continue;
      const geom::ClosestHit hit = Closest(b.pos, std::numeric_limits<double>::infinity());
      if (!hit.found) continue;
      b.anchor = glm::dvec3(hit.point);
      b.anchor_tri = static_cast<int>(hit.triangle);
      b.clearance = static_cast<double>(hit.distance);
    }
  }

  geom::ClosestHit Closest(const glm::dvec3& q, double max_distance) {
    if (s_.attach_mesh != nullptr) {
      if (s_.accel == Accel::kLinear)
        return geom::ClosestPointLinear(*s_.attach_mesh, F(q), static_cast<float>(max_distance),
                                        &log_->closest);
      return geom::ClosestPoint(*s_.attach_mesh, *s_.attach_bvh, F(q),
                                static_cast<float>(max_distance), &log_->closest);
    }
    if (s_.accel == Accel::kLinear)
      return geom::ClosestPointLinear(*s_.mesh, F(q), static_cast<float>(max_distance),
                                      &log_->closest);
    return geom::ClosestPoint(*s_.mesh, *s_.bvh, F(q), static_cast<float>(max_distance),
                              &log_->closest);
  }
  bool SegmentHits(const glm::dvec3& a, const glm::dvec3& b) {
    if (s_.accel == Accel::kLinear)
      return geom::SegmentHitsLinear(*s_.mesh, F(a), F(b), &log_->segment);
    return geom::SegmentHits(*s_.mesh, *s_.bvh, F(a), F(b), &log_->segment);
  }
  geom::RayHit FirstHit(const glm::dvec3& a, const glm::dvec3& dir, double len) {
    if (s_.accel == Accel::kLinear)
      return geom::FirstHitLinear(*s_.mesh, F(a), F(dir), static_cast<float>(len), &log_->segment);
    return geom::FirstHit(*s_.mesh, *s_.bvh, F(a), F(dir), static_cast<float>(len), &log_->segment);
  }

  Status PlaceSeeds(const std::vector<glm::dvec3>& seeds) {
    for (std::size_t i = 0; i < seeds.size(); ++i) {
      Bud b;
      b.id = static_cast<int>(m_.buds.size());
      b.kind = BudKind::kApical;
      b.N = p_.Get(IvyParam::kN0);
      b.plant = static_cast<int>(i);
      b.axis = static_cast<int>(m_.axes.size());
      b.pos = seeds[i];
      if (free()) {
        b.dir = up_;
        b.anchor = b.pos - glm::dvec3(0, 0, 1) * (d_ / 2);
        b.clearance = d_ / 2;
      } else {
        geom::ClosestHit hit = Closest(seeds[i], std::numeric_limits<double>::infinity());
        if (!hit.found || static_cast<double>(hit.distance) > d_) {
          std::string dist = hit.found ? FormatNumber(static_cast<double>(hit.distance)) : "inf";
          return Status::Error(
              "seed_points", "point " + std::to_string(i + 1) + ": (" + FormatNumber(seeds[i].x) +
                                 ", " + FormatNumber(seeds[i].y) + ", " + FormatNumber(seeds[i].z) +
                                 ") is " + dist +
                                 " from the nearest face; must be within d = " + FormatNumber(d_));
        }
        const glm::dvec3 cp(hit.point);
        glm::dvec3 n = seeds[i] - cp;
        n = Length(n) > 1e-9 * L_
                ? Unit(n)
                : TriangleNormal(s_.attach_mesh ? *s_.attach_mesh : *s_.mesh, hit.triangle);
        // §4 item 13: snapped to anchor + N·d/2; initial direction = up in the face's plane.
        b.pos = cp + n * (d_ / 2);
        glm::dvec3 t = up_ - glm::dot(up_, n) * n;
        if (Length(t) < 1e-6) {
          glm::dvec3 x(1, 0, 0);
          t = x - glm::dot(x, n) * n;
          if (Length(t) < 1e-6) t = glm::dvec3(0, 0, 1) - n.z * n;
        }
        b.dir = Unit(t);
        geom::ClosestHit a = Closest(b.pos, std::numeric_limits<double>::infinity());
        b.anchor = glm::dvec3(a.point);
        b.anchor_tri = static_cast<int>(a.triangle);
        b.clearance = static_cast<double>(a.distance);
      }
      b.outward = Unit(b.pos - b.anchor);
      m_.roots.push_back(b.id);
      m_.axes.push_back({b.axis, 0, -1, b.id, 0, -1, {0, 0, 0}});
      m_.buds.push_back(b);
    }
    return Status::Ok();
  }

  // E11: the preferred direction of the lateral from dormant bud b.
  glm::dvec3 LateralDirection(const Bud& b) const {
    const glm::dvec3 H = b.dir;
    const glm::dvec3 n = b.outward;
    glm::dvec3 B = glm::cross(n, H);
    if (Length(B) < 1e-6) {
      glm::dvec3 axis(0.0);
      int k = std::fabs(H.x) <= std::fabs(H.y) && std::fabs(H.x) <= std::fabs(H.z) ? 0
              : std::fabs(H.y) <= std::fabs(H.z)                                   ? 1
                                                                                   : 2;
      axis[k] = 1;
      B = glm::cross(axis, H);
    }
    B = Unit(B);
    const glm::dvec3 Np = glm::cross(H, B);
    double tz = p_.Get(IvyParam::kThetaZ);
    if (p_.GetBool(IvyParam::kAlternate) && b.index_on_axis % 2 == 1) tz = -tz;
    const double ty = p_.Get(IvyParam::kThetaY) * kDeg;
    double sy, cy, sz, cz;
    det::SinCos(ty, &sy, &cy);
    det::SinCos(tz * kDeg, &sz, &cz);
    // [H B N']·Rz(θz)·Ry(θy)·Rx(θx)·x̂; Rx leaves x̂ unchanged.
    return Unit(cy * cz * H + cy * sz * B - sy * Np);
  }
  double LateralThetaZ(const Bud& b) const {
    double tz = p_.Get(IvyParam::kThetaZ);
    if (p_.GetBool(IvyParam::kAlternate) && b.index_on_axis % 2 == 1) tz = -tz;
    return tz;
  }

  // Crowding (improved preset): is segment p-q closer than r_avoid to an internode not touching
  // bud `from`?
  // The internodes near p-q come from the grid (segment_grid.h); the answer is the loop's over
  // every internode (tests/ivy/segment_grid_test.cpp checks the two against each other).
  bool Crowded(int from, const glm::dvec3& p, const glm::dvec3& q, double r_avoid) const {
    return grid_.Any(p, q, r_avoid, [&](int i) {
      const Internode& in = m_.internodes[static_cast<std::size_t>(i)];
      if (in.from_bud == from || in.to_bud == from) return false;
      const Bud& a = m_.buds[static_cast<std::size_t>(in.from_bud)];
      const Bud& b = m_.buds[static_cast<std::size_t>(in.to_bud)];
      return SegmentSegmentDistance(p, q, a.pos, b.pos) < r_avoid;
    });
  }

  // The search's parameters, read once per search.
  struct SearchParams {
    double g_min, max_bend, r_avoid, wd, wa, wg;
    double body;  // the body's largest distance to a face (body · d); 0: not checked
  };
  SearchParams ReadSearchParams() const {
    return {p_.Get(IvyParam::kGMin),     p_.Get(IvyParam::kMaxBend) * kDeg,
            p_.Get(IvyParam::kAvoid),    p_.Get(IvyParam::kWDist),
            p_.Get(IvyParam::kWAngle),   p_.Get(IvyParam::kWGrav),
            p_.Get(IvyParam::kBody) * d_};
  }

  // Is a point of the body p→q farther than `reach` from every face? Its quarter points and
  // midpoint (issue 31 item 6: the nodes alone let bodies reach 1.35 d over a convex edge).
  bool BodyAway(const glm::dvec3& p, const glm::dvec3& q, double reach) {
    for (double t : {0.5, 0.25, 0.75}) {
      if (!Closest(p + t * (q - p), reach).found) return true;
    }
    return false;
  }

  // E8-E9 on the candidate q = p + L·u of bud `from`: the rejection reason (counted in the log),
  // or -1 with the candidate's closest hit and its score (E9: near the face, small angle to the
  // preferred direction v0, following gravitropism; lower is better).
  int Evaluate(int from, const glm::dvec3& p, const glm::dvec3& u, const glm::dvec3& v0,
               const SearchParams& sp, std::array<int, kRejectCount>* rejects, Placement* place,
               double* score) {
    ++log_->candidates;
    const glm::dvec3 q = p + L_ * u;
    int reason = -1;
    geom::ClosestHit hit;
    if (glm::dot(u, up_) < sp.g_min) {
      reason = kGravitropism;
    } else if (sp.max_bend < det::kPi - 1e-12 && AngleBetween(u, v0) > sp.max_bend) {
      reason = kBend;
    } else {
      hit = Closest(q, d_);
      if (!hit.found) {
        reason = kFar;
      } else if (static_cast<double>(hit.distance) < eps_) {
        reason = kNear;
      } else if (SegmentHits(p, q)) {
        reason = kCollision;
      } else if (sp.r_avoid > 0 && Crowded(from, p, q, sp.r_avoid)) {
        reason = kCrowding;
      } else if (sp.body > 0 && BodyAway(p, q, sp.body)) {
        reason = kBody;
      }
    }
    if (reason >= 0) {
      ++(*rejects)[static_cast<std::size_t>(reason)];
      ++log_->rejected[static_cast<std::size_t>(reason)];
      return reason;
    }
    *score = sp.wd * static_cast<double>(hit.distance) / d_ +
             sp.wa * AngleBetween(u, v0) / det::kPi + sp.wg * (1.0 - glm::dot(u, up_)) / 2.0;
    *place = {q, u, hit};
    return -1;
  }

  // E6-E10: a new node for bud `from` with preferred direction v0; false when every attempt failed
  // (and, with tangent_retry, the tangent fan too).
  bool Search(int from, const glm::dvec3& v0, int step, Placement* out) {
    const glm::dvec3 p = m_.buds[static_cast<std::size_t>(from)].pos;
    if (free()) {
      out->q = p + L_ * v0;
      out->u = v0;
      return true;
    }
    const int n_c = p_.GetInt(IvyParam::kCandidates);
    const int r_max = p_.GetInt(IvyParam::kRetries);
    const double phi = p_.Get(IvyParam::kPhi), dphi = p_.Get(IvyParam::kPhiStep);
    const SearchParams sp = ReadSearchParams();
    glm::dvec3 v = v0;
    for (int r = 0; r <= r_max; ++r) {
      ++log_->attempts;
      if (r > 0) ++log_->retries;
      const double phi_r = std::min(90.0, phi + r * dphi) * kDeg;
      const double cos_phi = det::Cos(phi_r);
      const glm::dvec3 a = std::fabs(v.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
      const glm::dvec3 e1 = Unit(glm::cross(v, a));
      const glm::dvec3 e2 = glm::cross(v, e1);
      Pcg32 rng(Key(seed_, from, step, r));
      std::array<int, kRejectCount> rejects{};
      BestPlacement best;
      for (int k = 0; k < n_c; ++k) {
        const double xi1 = rng.Uniform(), xi2 = rng.Uniform();
        const double cos_t = 1.0 - xi1 * (1.0 - cos_phi);
        const double sin_t = std::sqrt(std::max(0.0, 1.0 - cos_t * cos_t));
        double s_psi, c_psi;
        det::SinCos(2.0 * det::kPi * xi2, &s_psi, &c_psi);
        const glm::dvec3 u = Unit(cos_t * v + sin_t * (c_psi * e1 + s_psi * e2));
        Placement place;
        double score = 0;
        if (Evaluate(from, p, u, v0, sp, &rejects, &place, &score) >= 0) continue;
        best.Offer(place, score);
      }
      if (best.found) {
        *out = best.place;
        return true;
      }
      // E10: correct the direction by the dominant reason (ties: collision > far > near >
      // gravitropism > bend > crowding > body), then widen the cone; body turns toward the
      // surface as far does.
      static const int kPriority[] = {kCollision, kFar,      kNear, kGravitropism,
                                      kBend,      kCrowding, kBody};
      int dominant = kPriority[0];
      for (int reason : kPriority)
        if (rejects[static_cast<std::size_t>(reason)] > rejects[static_cast<std::size_t>(dominant)])
          dominant = reason;
      glm::dvec3 nv = v;
      if (dominant == kFar || dominant == kBody) {
        geom::ClosestHit c = Closest(p, std::numeric_limits<double>::infinity());
        if (c.found) nv = Unit(v + Unit(glm::dvec3(c.point) - p));
      } else if (dominant == kCollision || dominant == kNear) {
        glm::dvec3 n(0.0);
        if (dominant == kCollision) {
          geom::RayHit h = FirstHit(p, v, L_);
          if (h.hit) n = glm::dvec3(h.normal);
        }
        if (Length(n) == 0) {
          geom::ClosestHit c = Closest(p, std::numeric_limits<double>::infinity());
          if (c.found) n = Unit(p - glm::dvec3(c.point));
        }
        glm::dvec3 t = v - glm::dot(v, n) * n;
        if (Length(t) < 1e-6) t = up_ - glm::dot(up_, n) * n;
        if (Length(t) >= 1e-6) nv = Unit(t);
      } else if (dominant == kGravitropism) {
        nv = Unit(v - std::min(0.0, glm::dot(v, up_)) * up_ + 0.1 * up_);
      } else if (dominant == kBend) {
        nv = Unit(v + v0);
      }
      v = nv;
    }
    if (p_.GetBool(IvyParam::kTangentRetry) && TangentRetry(from, p, v0, sp, out)) return true;
    ++log_->failures;
    return false;
  }

  // The tangent fan (docs/ivy-model.md "Convex edges"): after E10's last retry, fixed directions
  // (no random draw, so a search that never gets here is unchanged) around p's closest face: in
  // its tangent plane every 22.5° from ĝ's projection (v0's on a face normal to ĝ), so that ±90°
  // runs along a horizontal edge, each at the tilts 0°, 10°, 20° toward the face; then the
  // projection of ĝ turned about the in-plane horizontal, an edge's line, toward the face by 30° to
  // 90° (at a convex edge: over it, onto the next face). Each is tested and scored as a walk's
  // candidate (E8-E9); the best valid one is taken (ties: the first in this order).
  static constexpr int kFanPsi = 16;
  static constexpr std::array<double, 3> kFanTilt = {0, 10, 20};  // degrees toward the face
  static constexpr std::array<double, 5> kEdgeTilt = {30, 45, 60, 75, 90};
  static_assert(kFanPsi * kFanTilt.size() + kEdgeTilt.size() == kTangentFanCandidates);
  bool TangentRetry(int from, const glm::dvec3& p, const glm::dvec3& v0, const SearchParams& sp,
                    Placement* out) {
    ++log_->tangent_retries;
    const geom::ClosestHit c = Closest(p, std::numeric_limits<double>::infinity());
    if (!c.found) return false;
    glm::dvec3 n = TriangleNormal(s_.attach_mesh ? *s_.attach_mesh : *s_.mesh, c.triangle);
    if (glm::dot(p - glm::dvec3(c.point), n) < 0) n = -n;  // the face's side p is on
    glm::dvec3 t1 = up_ - glm::dot(up_, n) * n;
    if (Length(t1) < 1e-6) t1 = v0 - glm::dot(v0, n) * n;
    if (Length(t1) < 1e-6) {
      const glm::dvec3 x = std::fabs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
      t1 = x - glm::dot(x, n) * n;
    }
    t1 = Unit(t1);
    const glm::dvec3 t2 = glm::cross(n, t1);
    std::array<int, kRejectCount> rejects{};
    BestPlacement best;
    auto consider = [&](const glm::dvec3& w, double tilt_deg) {
      double s_tilt, c_tilt;
      det::SinCos(tilt_deg * kDeg, &s_tilt, &c_tilt);
      const glm::dvec3 u = Unit(c_tilt * w - s_tilt * n);
      Placement place;
      double score = 0;
      if (Evaluate(from, p, u, v0, sp, &rejects, &place, &score) >= 0) return;
      best.Offer(place, score);
    };
    for (double tilt_deg : kFanTilt) {
      for (int k = 0; k < kFanPsi; ++k) {
        // ψ = 0, +22.5°, -22.5°, +45°, ..., 180°
        const int j = (k + 1) / 2 * (k % 2 == 1 ? 1 : -1);
        double s_psi, c_psi;
        det::SinCos(j * (2.0 * det::kPi / kFanPsi), &s_psi, &c_psi);
        consider(c_psi * t1 + s_psi * t2, tilt_deg);
      }
    }
    for (double tilt_deg : kEdgeTilt) consider(t1, tilt_deg);
    if (!best.found) return false;
    ++log_->tangent_saves;
    *out = best.place;
    return true;
  }

  // A hanging tendril's next internode (the row "hang", beyond §3.2; docs/ivy-model.md "The
  // artist preset"): from bud `from`, its direction `dir` turned toward the ground by 30° (or
  // β_max when smaller; straight down once within that), as Luft's Ivy Generator lets a shoot
  // that lost the surface fall. Taken when it crosses no face and, with r_avoid, no other
  // internode; the anchor is the closest support point at any distance.
  bool Hang(int from, const glm::dvec3& dir, Placement* out) {
    const Bud& b = m_.buds[static_cast<std::size_t>(from)];
    const glm::dvec3 p = b.pos, down = -up_;
    const double turn = std::min(30.0 * kDeg, p_.Get(IvyParam::kMaxBend) * kDeg);
    glm::dvec3 u = down;
    if (AngleBetween(dir, down) > turn) {
      glm::dvec3 w = down - glm::dot(down, dir) * dir;
      if (Length(w) < 1e-9) w = b.outward - glm::dot(b.outward, dir) * dir;
      if (Length(w) < 1e-9)
        w = glm::cross(dir, std::fabs(dir.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0));
      double st, ct;
      det::SinCos(turn, &st, &ct);
      u = Unit(ct * dir + st * Unit(w));
    }
    const glm::dvec3 q = p + L_ * u;
    ++log_->candidates;
    int reason = -1;
    const double r_avoid = p_.Get(IvyParam::kAvoid);
    if (SegmentHits(p, q)) {
      reason = kCollision;
    } else if (r_avoid > 0 && Crowded(from, p, q, r_avoid)) {
      reason = kCrowding;
    }
    if (reason >= 0) {
      ++log_->rejected[static_cast<std::size_t>(reason)];
      return false;
    }
    out->q = q;
    out->u = u;
    out->anchor = Closest(q, std::numeric_limits<double>::infinity());
    return true;
  }

  int AddBud(const Bud& from, const Placement& pl, int step, BudKind kind, double N, int axis,
             int order, int index_on_axis, int hang = 0) {
    Bud b;
    b.id = static_cast<int>(m_.buds.size());
    b.kind = kind;
    b.pos = pl.q;
    b.dir = pl.u;
    b.N = N;
    b.plant = from.plant;
    b.axis = axis;
    b.order = order;
    b.index_on_axis = index_on_axis;
    b.parent = from.id;
    b.born_step = step;
    b.hang = hang;
    if (hang > 0) ++log_->hang_internodes;
    if (free()) {
      b.anchor = b.pos - from.outward * (d_ / 2);
      b.clearance = d_ / 2;
      b.outward = from.outward;
    } else {
      b.anchor = glm::dvec3(pl.anchor.point);
      b.anchor_tri = static_cast<int>(pl.anchor.triangle);
      b.clearance = static_cast<double>(pl.anchor.distance);
      b.outward = Unit(b.pos - b.anchor);
    }
    grid_.Insert(static_cast<int>(m_.internodes.size()), from.pos, b.pos);
    m_.internodes.push_back({from.id, b.id, step, axis});
    m_.buds.push_back(b);
    return b.id;
  }

  // Pre-order, lateral subtree before the axis continuation (the L-string's order).
  std::vector<int> PreOrder() const {
    std::vector<int> order, stack;
    for (auto it = m_.roots.rbegin(); it != m_.roots.rend(); ++it) stack.push_back(*it);
    while (!stack.empty()) {
      int b = stack.back();
      stack.pop_back();
      order.push_back(b);
      const Bud& bud = m_.buds[static_cast<std::size_t>(b)];
      if (bud.child[0] >= 0) stack.push_back(bud.child[0]);
      if (bud.child[1] >= 0) stack.push_back(bud.child[1]);
    }
    return order;
  }

  double NutrientTotal() const {
    double sum = 0;
    for (const Bud& b : m_.buds) sum += b.N;
    return sum;
  }

  void Step(int s) {
    using Clock = std::chrono::steady_clock;
    StepLog st;
    const double t1 = p_.Get(IvyParam::kT1), t2 = p_.Get(IvyParam::kT2);
    const double kappa = p_.Get(IvyParam::kKappa), alpha = p_.Get(IvyParam::kAlpha);
    const double lambda = p_.Get(IvyParam::kLambda);
    const double da = p_.Get(IvyParam::kDeltaA), dd = p_.Get(IvyParam::kDeltaD);
    const int hang_max = free() ? 0 : p_.GetInt(IvyParam::kHang);
    // Parallel rule choice from the state at the start of the step.
    enum Rule { kNone, kP0, kP1, kP2 };
    std::vector<int> order = PreOrder();
    std::vector<Rule> rule(order.size(), kNone);
    for (std::size_t i = 0; i < order.size(); ++i) {
      const Bud& b = m_.buds[static_cast<std::size_t>(order[i])];
      if (b.kind == BudKind::kApical) rule[i] = b.N >= t1 - kTol ? kP0 : kP2;
      if (b.kind == BudKind::kDormant) rule[i] = (b.N >= t2 - kTol || b.released) ? kP1 : kP2;
    }
    // Sequential geometry in L-string order.
    for (std::size_t i = 0; i < order.size(); ++i) {
      const int id = order[i];
      Bud* b = &m_.buds[static_cast<std::size_t>(id)];
      if (rule[i] == kP2) {
        double inc = b->kind == BudKind::kApical ? da : dd;
        for (int k = 0; k < b->order; ++k) inc *= lambda;  // λ^k without pow
        b->N += inc;
        st.accumulated += inc;
        ++st.p2;
      } else if (rule[i] == kP0) {
        Placement pl;
        auto t0 = Clock::now();
        // A tendril hangs on until it is `hang` internodes long (then p3, its nutrient lost); an
        // apex on the support searches (E6-E10) and, when that fails, starts a tendril.
        bool ok = false, hanging = false;
        if (b->hang > 0) {
          ok = hanging = b->hang < hang_max && Hang(id, b->dir, &pl);
        } else {
          ok = Search(id, b->dir, s, &pl);
          if (!ok && hang_max > 0 && Hang(id, m_.buds[static_cast<std::size_t>(id)].dir, &pl)) {
            ok = hanging = true;
            ++log_->tendrils;
          }
        }
        log_->ms_search += std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
        b = &m_.buds[static_cast<std::size_t>(id)];
        if (ok) {
          const double spent = kappa * t1;
          const double rem = b->N - spent;
          b->kind = BudKind::kDormant;
          b->N = (1.0 - alpha) * rem;
          st.spent += spent;
          const Bud from = *b;
          int nb = AddBud(from, pl, s, BudKind::kApical, alpha * rem, from.axis, from.order,
                          from.index_on_axis + 1, hanging ? from.hang + 1 : 0);
          m_.buds[static_cast<std::size_t>(id)].child[0] = nb;
          ++st.p0;
        } else {
          EndApex(id, s, &st);
        }
      } else if (rule[i] == kP1) {
        if (b->released) ++st.released_breaks;
        const glm::dvec3 v0 = LateralDirection(*b);
        Placement pl;
        auto t0 = Clock::now();
        // With `hang`: a tendril does not branch (its D fails, p3), and a lateral born on a face
        // looking down (under an overhang: outward·ĝ < -1/2) hangs from its first internode.
        bool ok = false, hanging = false;
        if (b->hang > 0) {
          ok = false;
        } else if (hang_max > 0 && glm::dot(b->outward, up_) < -0.5) {
          ok = hanging = Hang(id, v0, &pl);
          if (ok) ++log_->tendrils;
        } else {
          ok = Search(id, v0, s, &pl);
        }
        log_->ms_search += std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
        b = &m_.buds[static_cast<std::size_t>(id)];
        if (ok) {
          const double spent = std::min(b->N, kappa * t2);
          const double rem = std::max(0.0, b->N - kappa * t2);
          st.spent += spent;
          b->kind = BudKind::kEnding;
          b->N = 0;
          b->died_step = s;
          b->released = false;
          const Bud from = *b;
          const int axis = static_cast<int>(m_.axes.size());
          m_.axes.push_back(
              {axis,
               from.order + 1,
               from.axis,
               from.id,
               s,
               -1,
               {p_.Get(IvyParam::kThetaX), p_.Get(IvyParam::kThetaY), LateralThetaZ(from)}});
          int nb =
              AddBud(from, pl, s, BudKind::kApical, rem, axis, from.order + 1, 1, hanging ? 1 : 0);
          m_.buds[static_cast<std::size_t>(id)].child[1] = nb;
          if (log_->first_break_step < 0) log_->first_break_step = s;
          ++st.p1;
        } else {
          // p3 on a D: its nutrient is lost.
          st.lost += b->N;
          b->N = 0;
          b->kind = BudKind::kEnding;
          b->died_step = s;
          b->released = false;
          ++st.p3_d;
        }
      }
    }
    st.nutrient_total = NutrientTotal();
    log_->steps.push_back(st);
  }

  // p3 on an apex (E4): the nearest dormant bud parent-ward gets its nutrient and breaks next step.
  void EndApex(int id, int s, StepLog* st) {
    Bud& b = m_.buds[static_cast<std::size_t>(id)];
    b.kind = BudKind::kEnding;
    b.died_step = s;
    m_.axes[static_cast<std::size_t>(b.axis)].death_step = s;
    ++st->p3_a;
    const double n = b.N;
    b.N = 0;
    // A tendril's end (it hung its `hang` internodes, or hit something) wakes no bud.
    if (p_.GetBool(IvyParam::kObstacleBreak) && b.hang == 0) {
      for (int w = m_.buds[static_cast<std::size_t>(id)].parent; w >= 0;
           w = m_.buds[static_cast<std::size_t>(w)].parent) {
        Bud& d = m_.buds[static_cast<std::size_t>(w)];
        if (d.kind == BudKind::kDormant) {
          d.N += n;
          d.released = true;
          return;
        }
      }
    }
    st->lost += n;
  }

  bool Alive() const {
    for (const Bud& b : m_.buds)
      if (b.kind != BudKind::kEnding) return true;
    return false;
  }

  IvyModel& model() { return m_; }

 private:
  Support s_;
  const IvyParams& p_;
  uint64_t seed_;
  GrowLog* log_;
  SegmentGrid grid_{1.0};  // the internodes, cell L (set in the constructor)
  double L_ = 0, d_ = 0, eps_ = 0;
  glm::dvec3 up_{0, 1, 0};
  IvyModel m_;
};

}  // namespace growth_detail

using growth_detail::Grower;

struct IvyGrowth::Impl {
  IvyParams params;
  GrowLog log;
  std::unique_ptr<Grower> grower;
  int steps = 0;
  bool finished = false;
  double ms_total = 0;
};

IvyGrowth::IvyGrowth(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
IvyGrowth::IvyGrowth(IvyGrowth&&) noexcept = default;
IvyGrowth& IvyGrowth::operator=(IvyGrowth&&) noexcept = default;
IvyGrowth::~IvyGrowth() = default;

Result<IvyGrowth> IvyGrowth::Start(const Support& support, const std::vector<glm::dvec3>& seeds,
                                   const IvyParams& params, int steps, uint64_t seed) {
  NIWA_RETURN_IF_ERROR(ValidateIvyParams(params));
  if (steps < 0 || steps > kMaxSteps) {
    return Status::Error(
        "steps", std::to_string(steps) + " is out of range; must be a whole number in [0, 10000]");
  }
  if (seeds.empty() || seeds.size() > static_cast<std::size_t>(kMaxSeedPoints)) {
    return Status::Error("seed_points",
                         std::to_string(seeds.size()) + " seed points; must be between 1 and 64");
  }
  for (const glm::dvec3& s : seeds) {
    if (!std::isfinite(s.x) || !std::isfinite(s.y) || !std::isfinite(s.z)) {
      return Status::Error("seed_points", "not finite; must be three finite numbers X,Y,Z");
    }
  }
  if (support.mesh != nullptr && support.mesh->triangle_count() == 0) {
    return Status::Error("mesh", "has no triangles; the support needs at least 1");
  }
  if (support.attach_mesh != nullptr && support.attach_mesh->triangle_count() == 0) {
    return Status::Error("mesh",
                         "has only obstacle triangles (noivy materials); ivy needs at "
                         "least 1 support triangle");
  }
  auto impl = std::make_unique<Impl>();
  impl->params = params;
  impl->steps = steps;
  impl->grower = std::make_unique<Grower>(support, impl->params, seed, &impl->log);
  NIWA_RETURN_IF_ERROR(impl->grower->PlaceSeeds(seeds));
  impl->log.nutrient_start = impl->grower->NutrientTotal();
  impl->finished = steps == 0;
  return IvyGrowth(std::move(impl));
}

void IvyGrowth::SetSupport(const Support& support, uint32_t kept_triangles) {
  impl_->grower->SetSupport(support, kept_triangles);
}

Status IvyGrowth::GrowTo(int to, const IvyGrowLimits* limits, const StepObserver& on_step) {
  Impl& m = *impl_;
  GrowLog* log = &m.log;
  Grower& g = *m.grower;
  const auto t0 = std::chrono::steady_clock::now();
  for (int s = log->steps_run + 1; !m.finished && s <= std::min(to, m.steps); ++s) {
    if (limits != nullptr) {
      log->truncated_by = CheckIvyStep(g.model(), *log, *limits, s, m.steps);
      if (!log->truncated_by.empty()) {
        m.finished = true;
        break;
      }
    }
    log->bud_steps += static_cast<double>(g.model().buds.size());
    g.Step(s);
    log->steps_run = s;
    if (on_step && !on_step(s, m.steps, g.model(), *log)) return run::CancelledStatus();
    if (!g.Alive()) {
      log->extinct_step = s;
      m.finished = true;
    }
    if (s == m.steps) m.finished = true;
  }
  m.ms_total +=
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return Status::Ok();
}

bool IvyGrowth::finished() const { return impl_->finished; }
int IvyGrowth::steps() const { return impl_->steps; }
const IvyModel& IvyGrowth::model() const { return impl_->grower->model(); }
const GrowLog& IvyGrowth::log() const { return impl_->log; }

IvyModel IvyGrowth::TakeModel() { return std::move(impl_->grower->model()); }

GrowLog IvyGrowth::TakeLog() {
  impl_->log.ms_rules = std::max(0.0, impl_->ms_total - impl_->log.ms_search);
  return std::move(impl_->log);
}

Result<IvyModel> Grow(const Support& support, const std::vector<glm::dvec3>& seeds,
                      const IvyParams& params, int steps, uint64_t seed, GrowLog* log,
                      const IvyGrowLimits* limits, const StepObserver& on_step) {
  GrowLog local;
  if (log == nullptr) log = &local;
  *log = GrowLog();
  Result<IvyGrowth> growth = IvyGrowth::Start(support, seeds, params, steps, seed);
  if (!growth.ok()) return growth.status();
  const Status grown = growth->GrowTo(steps, limits, on_step);
  *log = growth->TakeLog();
  if (!grown.ok()) return grown;
  return growth->TakeModel();
}

}  // namespace niwa::ivy
