// The polygon shrinking algorithm traced step by step for the method figures (shrink_trace.h).
#include "terrain/shrink_trace.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "math/det_math.h"
#include "params/param_text.h"
#include "random/pcg32.h"
#include "terrain/fourier.h"
#include "terrain/generate.h"
#include "terrain/polygon.h"

namespace niwa::terrain {
namespace {

constexpr std::size_t kMaxStepPoints = 200000;

Vec2 TraceSub(const Vec2& a, const Vec2& b) { return {a.x - b.x, a.y - b.y}; }
double Cross(const Vec2& a, const Vec2& b) { return a.x * b.y - a.y * b.x; }

// The unit normal of edge a -> b on the offset side: left (inside a CCW ring) when shrinking.
Vec2 OffsetNormal(const Vec2& a, const Vec2& b, bool outward) {
  const Vec2 e = TraceSub(b, a);
  const double l = std::sqrt(e.x * e.x + e.y * e.y);
  if (l == 0) return {0, 0};
  return outward ? Vec2{e.y / l, -e.x / l} : Vec2{-e.y / l, e.x / l};
}

// Fig 2: every edge of the ring moved by d; at each vertex the two moved edges either cross (a
// ridge when shrinking, if its edges are long enough) or leave a gap (every valley).
void NaiveOffsets(const Ring& r, double d, bool outward, ShrinkTraceStep* step) {
  const std::size_t n = r.size();
  std::vector<EdgeOffset> edges(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& a = r[i];
    const Vec2& b = r[(i + 1) % n];
    const Vec2 nn = OffsetNormal(a, b, outward);
    edges[i] = {{a.x + d * nn.x, a.y + d * nn.y}, {b.x + d * nn.x, b.y + d * nn.y}};
  }
  for (std::size_t i = 0; i < n; ++i) {  // vertex i + 1 joins edge i and edge i + 1
    const std::size_t j = (i + 1) % n;
    const Vec2 e1 = TraceSub(r[j], r[i]), e2 = TraceSub(r[(j + 1) % n], r[j]);
    const bool left_turn = Cross(e1, e2) > 0;
    const bool convex = left_turn != outward;  // toward the offset side's inside
    (convex ? step->convex : step->reflex) += 1;
    const bool cross = SegmentsIntersect(ToGrid(edges[i].a), ToGrid(edges[i].b), ToGrid(edges[j].a),
                                         ToGrid(edges[j].b));
    if (cross && convex) ++step->crossings;
    if (!cross) ++step->gaps;
  }
  step->naive.push_back(std::move(edges));
}

Status CheckOptions(const ShrinkTraceOptions& o) {
  const ShrinkOptions& s = o.shrink;
  if (!(s.d > 0 && s.d <= 1e6)) return Status::Error("d", "must be a number in (0, 1e6] m");
  if (!(s.c >= 1 && s.c <= 100)) return Status::Error("c", "must be a number in [1, 100]");
  if (o.steps < 0 || o.steps > kMaxTraceSteps)
    return Status::Error("steps",
                         "must be a whole number in [0, " + std::to_string(kMaxTraceSteps) + "]");
  if (!(s.clean_len >= 0 && s.clean_len <= 1e6))
    return Status::Error("clean_len", "must be a number in [0, 1e6] m");
  if (!(s.clean_angle_deg >= 0 && s.clean_angle_deg <= 180))
    return Status::Error("clean_angle", "must be a number in [0, 180] degrees");
  if (o.displace) {
    if (!(o.d0 > 0 && o.d0 <= 1e6)) return Status::Error("d0", "must be a number in (0, 1e6] m");
    if (!(o.d2 >= 0 && o.d2 <= 1e6)) return Status::Error("d2", "must be a number in [0, 1e6] m");
    if (!(o.theta_min_deg >= 0 && o.theta_max_deg <= 89 && o.theta_min_deg <= o.theta_max_deg))
      return Status::Error("theta", "must be two numbers 0 <= min <= max <= 89 degrees");
  }
  if (o.fourier) {
    if (o.fd_n < 16 || o.fd_n > 65536)
      return Status::Error("fd_n", "must be a whole number in [16, 65536]");
    if (o.fd_f0 < 1 || o.fd_f0 > o.fd_n / 2)
      return Status::Error("fd_f0", "must be a whole number in [1, " + std::to_string(o.fd_n / 2) +
                                        "] (half the FFT's samples)");
    if (!(o.fd_amp >= 0 && o.fd_amp <= det::kPi))
      return Status::Error("fd_amp", "must be a number in [0, pi]");
  }
  return Status::Ok();
}

}  // namespace

double MinInteriorAngleDeg(const Ring& r) {
  double best = 360;
  const std::size_t n = r.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 e1 = TraceSub(r[i], r[(i + n - 1) % n]), e2 = TraceSub(r[(i + 1) % n], r[i]);
    const double turn = det::Atan2(Cross(e1, e2), e1.x * e2.x + e1.y * e2.y);  // left turn > 0
    best = std::min(best, (det::kPi - turn) * 180 / det::kPi);
  }
  return best;
}

Result<ShrinkTrace> TraceShrink(const Ring& seed, const ShrinkTraceOptions& o) {
  Status ok = CheckOptions(o);
  if (!ok.ok()) return ok;
  if (seed.size() > kMaxTracePoints)
    return Status::Error("contour", std::to_string(seed.size()) + " points; a figure takes 3.." +
                                        std::to_string(kMaxTracePoints));
  Result<Ring> checked = CheckSeed(seed);
  if (!checked.ok()) return checked.status();
  ShrinkTrace trace;
  trace.seed = *checked;
  std::vector<Ring> input{trace.seed};
  Pcg32 rng(o.rng_seed);
  if (o.displace) {  // paper §4.1, Fig 12
    // A figure's displaced seed holds at most what a figure takes (kMaxTracePoints).
    std::optional<Ring> displaced = MidpointDisplace(trace.seed, o.d0, o.d2, o.theta_min_deg,
                                                     o.theta_max_deg, &rng, kMaxTracePoints);
    if (!displaced) {
      const Status s = MidpointOverflow(
          o.d0, o.d2, o.theta_max_deg, static_cast<double>(kMaxTracePoints), "what a figure takes");
      return Status::Error("theta", s.message());
    }
    trace.displaced = Normalise(*displaced);
    for (const Vec2& p : trace.displaced)
      trace.max_displacement = std::max(trace.max_displacement, RingDistance(trace.seed, p));
    if (!IsSimple(ToGrid(trace.displaced)))
      return Status::Error("d2", "the displaced seed crosses itself; lower d2 or theta");
    input = {trace.displaced};
  }
  for (int s = 0; s < o.steps && !input.empty(); ++s) {
    ShrinkTraceStep step;
    std::size_t total = 0;
    for (const Ring& ring : input) {
      // What Shrink does first (Fig 8 pre-clean, normalise), kept so the raw path can be drawn.
      int cleaned = 0;
      const Ring r =
          Normalise(PreClean(ring, o.shrink.clean_len, o.shrink.clean_angle_deg, &cleaned));
      if (r.size() < 3) continue;
      step.input.push_back(r);
      NaiveOffsets(r, o.shrink.d, o.shrink.outward, &step);
      Ring raw = RawOffsetPath(r, o.shrink);
      step.raw_self_intersections += static_cast<int>(SelfIntersections(ToGrid(raw)).size());
      step.raw.push_back(std::move(raw));
      for (Ring& q : Shrink(ring, o.shrink, &step.counts)) {
        step.points += static_cast<int>(q.size());
        step.min_angle_deg = std::min(step.min_angle_deg, MinInteriorAngleDeg(q));
        total += q.size();
        step.rings.push_back(std::move(q));
      }
    }
    if (total > kMaxStepPoints)
      return Status::Error("steps", "step " + std::to_string(s + 1) + " holds " +
                                        std::to_string(total) + " points; a figure takes at most " +
                                        std::to_string(kMaxStepPoints));
    if (o.fourier) {  // paper §4.2, Fig 14: each ring on its own, nothing fed back
      for (const Ring& r : step.rings) {
        Ring z = FourierPerturb(r, o.fd_n, o.fd_f0, o.fd_amp, &rng);
        for (const Vec2& p : z)
          step.fourier_max_shift = std::max(step.fourier_max_shift, RingDistance(r, p));
        if (!IsSimple(ToGrid(z))) ++step.fourier_not_simple;
        step.fourier.push_back(std::move(z));
      }
    }
    input = step.rings;
    trace.steps.push_back(std::move(step));
  }
  return trace;
}

std::string ShrinkTraceToSvg(const ShrinkTrace& t) {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  const auto grow = [&](const Vec2& p) {
    x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
  };
  for (const Vec2& p : t.seed) grow(p);
  for (const Vec2& p : t.displaced) grow(p);
  for (const ShrinkTraceStep& s : t.steps) {
    for (const auto& edges : s.naive)
      for (const EdgeOffset& e : edges) grow(e.a), grow(e.b);
    for (const Ring& r : s.raw)
      for (const Vec2& p : r) grow(p);
    for (const Ring& r : s.fourier)
      for (const Vec2& p : r) grow(p);
  }
  const double span = std::max({x1 - x0, y1 - y0, 1e-9});
  const double margin = span * 0.04;
  const double scale = 600 / (span + 2 * margin);
  const double w = std::round((x1 - x0 + 2 * margin) * scale);
  const double h = std::round((y1 - y0 + 2 * margin) * scale);
  const auto X = [&](double x) {
    return FormatNumber(std::round((x - x0 + margin) * scale * 100) / 100);
  };
  const auto Y = [&](double y) {
    return FormatNumber(std::round((y1 + margin - y) * scale * 100) / 100);
  };
  const auto path = [&](const Ring& r, bool closed) {
    std::string d;
    for (std::size_t k = 0; k < r.size(); ++k)
      d += (k == 0 ? "M" : "L") + X(r[k].x) + " " + Y(r[k].y);
    return closed ? d + "Z" : d;
  };
  std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + FormatNumber(w) +
                    "\" height=\"" + FormatNumber(h) + "\" viewBox=\"0 0 " + FormatNumber(w) + " " +
                    FormatNumber(h) +
                    "\">\n<rect width=\"100%\" height=\"100%\" fill=\"#fbf8f1\"/>\n";
  svg += "<path class=\"seed\" d=\"" + path(t.seed, true) +
         "\" fill=\"none\" stroke=\"#222\" stroke-width=\"1.5\"/>\n";
  if (!t.displaced.empty())
    svg += "<path class=\"displaced\" d=\"" + path(t.displaced, true) +
           "\" fill=\"none\" stroke=\"#2a8a3a\" stroke-width=\"1.5\"/>\n";
  const int n = static_cast<int>(t.steps.size());
  for (int s = 0; s < n; ++s) {
    const ShrinkTraceStep& step = t.steps[static_cast<std::size_t>(s)];
    const std::string tag = " data-step=\"" + std::to_string(s + 1) + "\"";
    if (n <= 2) {  // the construction of one or two steps; many steps show only the kept rings
      for (const auto& edges : step.naive)
        for (const EdgeOffset& e : edges)
          svg += "<path class=\"naive\"" + tag + " d=\"M" + X(e.a.x) + " " + Y(e.a.y) + "L" +
                 X(e.b.x) + " " + Y(e.b.y) + "\" stroke=\"#e08a1e\" stroke-width=\"1\"/>\n";
      for (const Ring& r : step.raw)
        svg += "<path class=\"raw\"" + tag + " d=\"" + path(r, true) +
               "\" fill=\"none\" stroke=\"#c22\" stroke-width=\"1\" stroke-dasharray=\"4 3\"/>\n";
    }
    const int shade = n > 1 ? 200 - 140 * s / (n - 1) : 140;
    char colour[16];
    std::snprintf(colour, sizeof colour, "#%02x%02x%02x", shade / 4, shade / 2, 255 - shade / 3);
    for (const Ring& r : step.rings)
      svg += "<path class=\"ring\"" + tag + " d=\"" + path(r, true) + "\" fill=\"none\" stroke=\"" +
             colour + "\" stroke-width=\"1.5\"/>\n";
    for (const Ring& r : step.fourier)
      svg += "<path class=\"fourier\"" + tag + " d=\"" + path(r, true) +
             "\" fill=\"none\" stroke=\"#2a8a3a\" stroke-width=\"1\"/>\n";
  }
  return svg + "</svg>\n";
}

}  // namespace niwa::terrain
