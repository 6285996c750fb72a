// The torus lattice: counts, the R_o and H_o formulas, each spring's reference vector against the
// torus metric, and every node's six neighbours against a brute-force neighbour list.
#include "bark/lattice.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <utility>
#include <vector>

namespace niwa::bark {
namespace {

TEST(Lattice, CountsAndThePapersFormulas) {
  const Lattice L = BuildLattice(128, 64, 0.33);
  EXPECT_EQ(L.nodes(), 8192);
  EXPECT_EQ(L.axial_count, 8192);
  EXPECT_EQ(L.springs(), 24576);
  EXPECT_EQ(L.tri_nodes.size(), 16384u);
  EXPECT_NEAR(L.radius(), 5.822, 5e-4);         // R_o = √3·L_o·N_R/4π
  EXPECT_NEAR(L.height(), 21.12, 1e-9);         // H_o = L_o·N_H
  EXPECT_NEAR(L.circumference(), 36.58, 5e-3);  // 2π·R_o
  EXPECT_NEAR(L.circumference(), 2 * 3.14159265358979 * L.radius(), 1e-9);
}

// The shortest torus vector from p to q.
void TorusDelta(const Lattice& L, int p, int q, double* dx, double* dz) {
  const double C = L.circumference(), H = L.height();
  *dx = L.x_of(q / L.n_h) - L.x_of(p / L.n_h);
  *dz = L.z_of(q / L.n_h, q % L.n_h) - L.z_of(p / L.n_h, p % L.n_h);
  *dx -= C * std::round(*dx / C);
  *dz -= H * std::round(*dz / H);
}

TEST(Lattice, SpringsAreTheTorusNeighboursOfABruteForceSearch) {
  for (const auto& [n_r, n_h] : {std::pair{8, 4}, std::pair{12, 7}, std::pair{16, 10}}) {
    const Lattice L = BuildLattice(n_r, n_h, 0.33);
    // Each spring's stored vector is the torus vector between its nodes, of length L_o.
    for (int s = 0; s < L.springs(); ++s) {
      double dx, dz;
      TorusDelta(L, L.a[s], L.b[s], &dx, &dz);
      EXPECT_NEAR(dx, L.ox[s], 1e-6) << s;
      EXPECT_NEAR(dz, L.oz[s], 1e-6) << s;
      EXPECT_NEAR(std::hypot(dx, dz), 0.33, 1e-6);
      EXPECT_EQ(L.family(s) == Family::kAxial, std::fabs(dx) < 1e-9) << s;
    }
    // Brute force: the nodes within 1.01·L_o of each node (torus metric) are its springs' ends.
    std::vector<std::set<int>> by_springs(L.nodes());
    for (int s = 0; s < L.springs(); ++s) {
      by_springs[L.a[s]].insert(L.b[s]);
      by_springs[L.b[s]].insert(L.a[s]);
    }
    for (int p = 0; p < L.nodes(); ++p) {
      std::set<int> near;
      for (int q = 0; q < L.nodes(); ++q) {
        if (q == p) continue;
        double dx, dz;
        TorusDelta(L, p, q, &dx, &dz);
        if (std::hypot(dx, dz) < 1.01 * 0.33) near.insert(q);
      }
      EXPECT_EQ(near.size(), 6u) << n_r << "x" << n_h << " node " << p;
      EXPECT_EQ(near, by_springs[p]) << n_r << "x" << n_h << " node " << p;
    }
  }
}

TEST(Lattice, TrianglesTileThePatch) {
  const Lattice L = BuildLattice(12, 6, 0.33);
  double area = 0;
  for (std::size_t t = 0; t < L.tri_nodes.size(); ++t) {
    int axial = 0;
    for (int e = 0; e < 3; ++e) {
      const int s = L.tri_springs[t][e];
      const int u = L.tri_nodes[t][e], v = L.tri_nodes[t][(e + 1) % 3];
      EXPECT_TRUE((L.a[s] == u && L.b[s] == v) || (L.a[s] == v && L.b[s] == u)) << t;
      axial += L.family(s) == Family::kAxial;
    }
    EXPECT_EQ(axial, 1) << t;
    const auto& o = L.tri_offsets[t];
    const double a = 0.5 * (o[0] * o[3] - o[2] * o[1]);
    EXPECT_GT(a, 0) << t;  // counter-clockwise
    area += a;
  }
  EXPECT_NEAR(area, L.circumference() * L.height(), 1e-4);
}

// The spring pass's layout: slots a bijection onto the springs, each sub-family in node order
// with node a = n, each node's six springs in ascending index with its end, and the runs of four.
TEST(Lattice, SlotsAndEachNodesSpringsInIndexOrder) {
  for (const auto& [n_r, n_h] : {std::pair{8, 4}, std::pair{12, 7}, std::pair{16, 10}}) {
    const Lattice L = BuildLattice(n_r, n_h, 0.33);
    const int n = L.nodes();
    std::vector<int> seen(L.springs(), 0);
    for (int s = 0; s < L.springs(); ++s) {
      const int q = L.slot(s);
      ++seen[q];
      EXPECT_EQ(L.spring_of_slot(q), s);
      EXPECT_EQ(L.a[s], q % n) << s;  // node a of slot q is q mod N
      EXPECT_EQ(L.slot_b[q], L.b[s]) << s;
      // A sub-family's reference vector is one.
      EXPECT_EQ(L.ox[s], L.ox[L.spring_of_slot(q - q % n)]) << s;
      EXPECT_EQ(L.oz[s], L.oz[L.spring_of_slot(q - q % n)]) << s;
    }
    for (int v : seen) EXPECT_EQ(v, 1);
    for (int v = 0; v < n; ++v) {
      int last = -1;
      for (int e = 0; e < 6; ++e) {
        const std::size_t k = 6 * static_cast<std::size_t>(v) + e;
        const int s = L.spring_of_slot(L.inc_slot[k]);
        EXPECT_GT(s, last) << v;
        last = s;
        EXPECT_EQ(L.inc_a[k] ? L.a[s] : L.b[s], v) << v;
      }
      if (v + 3 < n && L.node_run4[v]) {
        for (int q = 1; q < 4; ++q)
          for (int e = 0; e < 6; ++e)
            EXPECT_EQ(L.inc_slot[6 * (v + q) + e], L.inc_slot[6 * v + e] + q);
      }
    }
    for (int q = 0; q + 3 < L.springs(); ++q) {
      if (!L.slot_run4[q]) continue;
      EXPECT_EQ(q / n, (q + 3) / n);
      for (int k = 1; k < 4; ++k) EXPECT_EQ(L.slot_b[q + k], L.slot_b[q] + k);
    }
  }
}

// Whether the reference triangle t holds the point (x, z) on the torus (strictly inside).
bool TriangleHolds(const Lattice& L, int t, double x, double z) {
  const int n0 = L.tri_nodes[t][0];
  const double x0 = L.x_of(n0 / L.n_h), z0 = L.z_of(n0 / L.n_h, n0 % L.n_h);
  const auto& o = L.tri_offsets[t];
  const double C = L.circumference(), H = L.height();
  for (int wx = -1; wx <= 1; ++wx) {
    for (int wz = -1; wz <= 1; ++wz) {
      const double px = x + wx * C - x0, pz = z + wz * H - z0;
      const double p[3][2] = {{0, 0}, {o[0], o[1]}, {o[2], o[3]}};
      bool in = true;
      for (int e = 0; e < 3 && in; ++e) {
        const double* a = p[e];
        const double* b = p[(e + 1) % 3];
        in = (b[0] - a[0]) * (pz - a[1]) - (b[1] - a[1]) * (px - a[0]) > 1e-9;  // left of a->b
      }
      if (in) return true;
    }
  }
  return false;
}

// The scan lines: every triangle once on each family of lines, and each half's middle inside it.
TEST(Lattice, ScanLinesCrossEveryTriangleOnce) {
  for (const auto& [n_r, n_h] : {std::pair{8, 4}, std::pair{12, 7}, std::pair{16, 10}}) {
    const Lattice L = BuildLattice(n_r, n_h, 0.33);
    const std::size_t nt = L.tri_nodes.size();
    std::vector<int> around(nt, 0), along(nt, 0);
    const double pitch = L.pitch(), lo = L.l_o;
    for (int j = 0; j < n_h; ++j) {
      for (int h = 0; h < 2 * n_r; ++h) {
        const int t = L.line_around[static_cast<std::size_t>(j) * 2 * n_r + h];
        ASSERT_GE(t, 0);
        ++around[t];
        EXPECT_TRUE(TriangleHolds(L, t, (h + 0.5) * pitch / 2, (j + 0.25) * lo)) << j << " " << h;
      }
    }
    for (int i = 0; i < n_r; ++i) {
      for (int h = 0; h < 2 * n_h; ++h) {
        const int t = L.line_along[static_cast<std::size_t>(i) * 2 * n_h + h];
        ASSERT_GE(t, 0);
        ++along[t];
        EXPECT_TRUE(TriangleHolds(L, t, (i + 0.5) * pitch, lo / 4 + (h + 0.5) * lo / 2))
            << i << " " << h;
      }
    }
    for (std::size_t t = 0; t < nt; ++t) {
      EXPECT_EQ(around[t], 1) << t;
      EXPECT_EQ(along[t], 1) << t;
    }
  }
}

}  // namespace
}  // namespace niwa::bark
