// The torus lattice: counts, the R_o and H_o formulas, each spring's reference vector against the
// torus metric, and every node's six neighbours against a brute-force neighbour list.
#include "bark/lattice.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

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

}  // namespace
}  // namespace niwa::bark
