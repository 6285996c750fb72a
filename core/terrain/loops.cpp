// Loop removal, §4.4 methods 1 and 2 (see loops.h).
#include "terrain/loops.h"

#include <algorithm>
#include <map>

#include "terrain/polygon.h"

namespace niwa::terrain {
namespace {

// Index of the first plain item of a run of ≥ min_run plain items (else of the longest run).
std::size_t StartIndex(const std::vector<SeqItem>& seq, int min_run) {
  const std::size_t n = seq.size();
  std::size_t first_label = n;
  for (std::size_t i = 0; i < n; ++i)
    if (seq[i].label >= 0) {
      first_label = i;
      break;
    }
  if (first_label == n) return 0;
  std::size_t best = 0, best_len = 0;
  // Runs start right after a label; walk once around from first_label.
  std::size_t run_start = 0, run_len = 0;
  for (std::size_t k = 1; k <= n; ++k) {
    const std::size_t i = (first_label + k) % n;
    if (seq[i].label < 0) {
      if (run_len == 0) run_start = i;
      ++run_len;
      if (static_cast<int>(run_len) >= min_run) return run_start;
    } else {
      if (run_len > best_len) {
        best_len = run_len;
        best = run_start;
      }
      run_len = 0;
    }
  }
  return best_len > 0 ? best : (first_label + 1) % n;
}

std::vector<SeqItem> Rotate(const std::vector<SeqItem>& seq, std::size_t start) {
  std::vector<SeqItem> out;
  out.reserve(seq.size());
  for (std::size_t k = 0; k < seq.size(); ++k) out.push_back(seq[(start + k) % seq.size()]);
  return out;
}

}  // namespace

std::vector<SeqItem> RemoveLoopsMethod2(const std::vector<SeqItem>& seq, int min_run,
                                        int* removed) {
  if (seq.empty()) return {};
  const std::vector<SeqItem> s = Rotate(seq, StartIndex(seq, min_run));
  std::map<int, std::vector<std::size_t>> where;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s[i].label >= 0) where[s[i].label].push_back(i);
  std::vector<SeqItem> out;
  for (std::size_t i = 0; i < s.size();) {
    if (s[i].label >= 0) {
      const std::vector<std::size_t>& w = where[s[i].label];
      if (w.size() == 2 && w[0] == i) {
        // Delete from X up to just before its other occurrence; keep that one as a plain point.
        if (removed) ++*removed;
        SeqItem x = s[w[1]];
        x.label = -1;
        out.push_back(x);
        i = w[1] + 1;
        continue;
      }
    }
    out.push_back(s[i]);
    ++i;
  }
  return out;
}

std::vector<SeqItem> RemoveLoopsMethod1(const std::vector<SeqItem>& seq, int min_segments,
                                        int* removed, SweepWork* work) {
  if (seq.empty()) return {};
  std::vector<SeqItem> s = Rotate(seq, StartIndex(seq, min_segments));
  while (true) {
    if (SweepOver(work, kSweepWorkPerTry * static_cast<double>(s.size()))) return s;
    // An innermost loop: two occurrences of X with no other live label between them.
    bool changed = false;
    std::map<int, std::size_t> last;
    for (std::size_t i = 0; i < s.size() && !changed; ++i) {
      if (s[i].label < 0) continue;
      auto it = last.find(s[i].label);
      if (it != last.end()) {
        const std::size_t a = it->second;
        bool inner = true;
        for (std::size_t k = a + 1; k < i; ++k)
          if (s[k].label >= 0) inner = false;
        if (inner) {
          const int segments = static_cast<int>(i - a);  // X..X has i − a segments
          SeqItem x = s[i];
          x.label = -1;
          if (segments < min_segments) {
            s.erase(s.begin() + static_cast<std::ptrdiff_t>(a) + 1,
                    s.begin() + static_cast<std::ptrdiff_t>(i) + 1);
            s[a] = x;
            if (removed) ++*removed;
          } else {
            // A large face: the twist stays; X is no longer a candidate.
            s[a].label = -1;
            s[i] = x;
          }
          changed = true;
        }
      } else {
        last[s[i].label] = i;
      }
    }
    if (!changed) break;
  }
  return s;
}

Ring UntwistRing(const Ring& ring, int method, int threshold, int* removed, SweepWork* work) {
  const IRing g = ToGrid(ring);
  const std::size_t n = g.size();
  const std::vector<std::pair<int, int>> pairs = SelfIntersections(g, 1 << 30, work);
  if (pairs.empty() || (work != nullptr && work->stopped)) return ring;
  // Crossing points per edge, ordered along the edge.
  struct Hit {
    double t;
    int label;
    Vec2 p;
  };
  std::vector<std::vector<Hit>> hits(n);
  int label = 0;
  for (const auto& [i, j] : pairs) {
    const Vec2 a = ring[static_cast<std::size_t>(i)],
               b = ring[(static_cast<std::size_t>(i) + 1) % n];
    const Vec2 c = ring[static_cast<std::size_t>(j)],
               d = ring[(static_cast<std::size_t>(j) + 1) % n];
    const double rx = b.x - a.x, ry = b.y - a.y, sx = d.x - c.x, sy = d.y - c.y;
    const double den = rx * sy - ry * sx;
    if (den == 0) continue;  // collinear overlap: left to the union fallback
    const double t = ((c.x - a.x) * sy - (c.y - a.y) * sx) / den;
    const double u = ((c.x - a.x) * ry - (c.y - a.y) * rx) / den;
    const Vec2 p{a.x + t * rx, a.y + t * ry};
    hits[static_cast<std::size_t>(i)].push_back({t, label, p});
    hits[static_cast<std::size_t>(j)].push_back({u, label, p});
    ++label;
  }
  std::vector<SeqItem> seq;
  std::vector<Vec2> where;
  for (std::size_t i = 0; i < n; ++i) {
    seq.push_back({-1, static_cast<int>(where.size())});
    where.push_back(ring[i]);
    std::sort(hits[i].begin(), hits[i].end(), [](const Hit& x, const Hit& y) {
      return x.t < y.t || (x.t == y.t && x.label < y.label);
    });
    for (const Hit& h : hits[i]) {
      seq.push_back({h.label, static_cast<int>(where.size())});
      where.push_back(h.p);
    }
  }
  const std::vector<SeqItem> out = method == 1 ? RemoveLoopsMethod1(seq, threshold, removed, work)
                                               : RemoveLoopsMethod2(seq, threshold, removed);
  Ring result;
  for (const SeqItem& it : out) result.push_back(where[static_cast<std::size_t>(it.id)]);
  return result;
}

}  // namespace niwa::terrain
