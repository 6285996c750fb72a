// The union sweep's grid of windings (core/terrain/ray_windings) against its brute-force twin:
// random edge soups with shared endpoints, collinear and horizontal edges and points on edges,
// a comb's and a spiral's edges; and the work limit that stops before the lists are made.
#include "terrain/ray_windings.h"

#include <gtest/gtest.h>

#include "random/pcg32.h"

namespace niwa::terrain {
namespace {

std::vector<RayEdge> Edges(const std::vector<IPoint>& ring) {
  std::vector<RayEdge> e;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const IPoint a{2 * ring[i].x, 2 * ring[i].y};
    const IPoint& n = ring[(i + 1) % ring.size()];
    const IPoint b{2 * n.x, 2 * n.y};
    if (a.y < b.y) e.push_back({a, b, 1});
    if (a.y > b.y) e.push_back({b, a, -1});
  }
  return e;
}

std::vector<IPoint> Midpoints(const std::vector<IPoint>& ring) {
  std::vector<IPoint> m;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const IPoint& n = ring[(i + 1) % ring.size()];
    m.push_back({ring[i].x + n.x, ring[i].y + n.y});
  }
  return m;
}

TEST(RayWindings, EqualsTheBruteForceOnRandomSoups) {
  Pcg32 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    const int span = trial % 3 == 0 ? 4 : (trial % 3 == 1 ? 40 : 4000);  // small: many ties
    const int n = 1 + static_cast<int>(rng.NextU32() % 300);
    std::vector<IPoint> pts;
    for (int k = 0; k < n; ++k)
      pts.push_back({static_cast<int64_t>(rng.NextU32() % span) * 2,
                     static_cast<int64_t>(rng.NextU32() % span) * 2});
    std::vector<RayEdge> edges;
    for (int k = 0; k < n; ++k) {
      IPoint a = pts[static_cast<std::size_t>(k)];
      IPoint b = pts[rng.NextU32() % pts.size()];
      if (a.y == b.y) continue;
      const int w = 1 + static_cast<int>(rng.NextU32() % 3);
      edges.push_back(a.y < b.y ? RayEdge{a, b, w} : RayEdge{b, a, -w});
    }
    std::vector<IPoint> points;
    for (int k = 0; k < 300; ++k)  // grid points, edge endpoints and edge midpoints
      points.push_back({static_cast<int64_t>(rng.NextU32() % (2 * span + 4)) - 2,
                        static_cast<int64_t>(rng.NextU32() % (2 * span + 4)) - 2});
    for (const RayEdge& e : edges) {
      points.push_back(e.lo);
      points.push_back({(e.lo.x + e.hi.x) / 2, (e.lo.y + e.hi.y) / 2});  // even: on the edge
    }
    const std::vector<int> brute = RayWindingsBruteForce(edges, points);
    for (RayWindingsFill fill :
         {RayWindingsFill::kAuto, RayWindingsFill::kRows, RayWindingsFill::kColumns}) {
      std::vector<int> got;
      RayWindings(edges, points, -1, &got, fill);
      EXPECT_EQ(got, brute) << "trial " << trial << " fill " << static_cast<int>(fill);
    }
  }
}

TEST(RayWindings, EqualsTheBruteForceOnACombAndASpiral) {
  std::vector<IPoint> comb = {{0, 0}, {3 * 300 - 1, 0}};
  for (int i = 299; i >= 0; --i) {
    const int64_t x0 = 3 * i, x1 = x0 + 2;
    if (i < 299) comb.push_back({x1, 10});
    comb.push_back({x1, 60});
    comb.push_back({x0, 60});
    if (i > 0) comb.push_back({x0, 10});
  }
  std::vector<IPoint> spiral;
  for (int64_t k = 0; k < 80; ++k) {
    const int64_t a = 2 * k, b = a + 1;
    spiral.push_back({-b, -b});
    spiral.push_back({b + 1, -b});
    spiral.push_back({b + 1, b + 1});
    spiral.push_back({-b - 1, b + 1});
  }
  for (const std::vector<IPoint>* ring : {&comb, &spiral}) {
    const std::vector<RayEdge> edges = Edges(*ring);
    const std::vector<IPoint> points = Midpoints(*ring);
    const std::vector<int> brute = RayWindingsBruteForce(edges, points);
    const double work = RayWindings(edges, points, -1, nullptr);
    for (RayWindingsFill fill :
         {RayWindingsFill::kAuto, RayWindingsFill::kRows, RayWindingsFill::kColumns}) {
      std::vector<int> got;
      // Either fill returns the count pass's work: budgets do not depend on the choice.
      EXPECT_EQ(work, RayWindings(edges, points, -1, &got, fill));
      EXPECT_EQ(got, brute) << "fill " << static_cast<int>(fill);
    }
    // A limit below the work stops with the count, the sums unfilled.
    std::vector<int> none;
    EXPECT_GT(RayWindings(edges, points, work / 2, &none), work / 2);
    EXPECT_TRUE(none.empty());
  }
  // The comb's work is linear in its teeth (the brute force's is quadratic).
  EXPECT_LT(RayWindings(Edges(comb), Midpoints(comb), -1, nullptr),
            40.0 * static_cast<double>(comb.size()));
}

}  // namespace
}  // namespace niwa::terrain
