// The triangular torus lattice of the 2-layer model: springs and triangles by fixed rules.
#include "bark/lattice.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "math/det_math.h"

namespace niwa::bark {

double LatticePitch(double l_o) { return std::sqrt(3.0) / 2.0 * l_o; }
double LatticeRadius(int n_r, double l_o) { return std::sqrt(3.0) * l_o * n_r / (4.0 * det::kPi); }

double Lattice::pitch() const { return LatticePitch(l_o); }
double Lattice::circumference() const { return n_r * pitch(); }
double Lattice::height() const { return n_h * l_o; }
double Lattice::radius() const { return LatticeRadius(n_r, l_o); }
double Lattice::x_of(int i) const { return i * pitch(); }
double Lattice::z_of(int i, int j) const { return j * l_o + (i % 2) * l_o / 2.0; }

Lattice BuildLattice(int n_r, int n_h, double l_o) {
  Lattice L;
  L.n_r = n_r;
  L.n_h = n_h;
  L.l_o = l_o;
  const int n = n_r * n_h;
  const float pitch = static_cast<float>(L.pitch());
  const float lo = static_cast<float>(l_o), half = static_cast<float>(l_o / 2.0);
  L.a.reserve(3 * n);
  L.b.reserve(3 * n);
  L.ox.reserve(3 * n);
  L.oz.reserve(3 * n);
  auto add = [&L](int a, int b, float ox, float oz) {
    L.a.push_back(a);
    L.b.push_back(b);
    L.ox.push_back(ox);
    L.oz.push_back(oz);
  };
  // Family 1: axial, (i, j) -> (i, j+1).
  for (int i = 0; i < n_r; ++i)
    for (int j = 0; j < n_h; ++j) add(L.node(i, j), L.node(i, (j + 1) % n_h), 0.0f, lo);
  L.axial_count = static_cast<int>(L.a.size());
  // Family 2: diagonals to the next column, up and down by half a spacing.
  for (int i = 0; i < n_r; ++i) {
    const int next = (i + 1) % n_r;
    for (int j = 0; j < n_h; ++j) {
      if (i % 2 == 0) {
        add(L.node(i, j), L.node(next, j), pitch, half);
        add(L.node(i, j), L.node(next, (j + n_h - 1) % n_h), pitch, -half);
      } else {
        add(L.node(i, j), L.node(next, (j + 1) % n_h), pitch, half);
        add(L.node(i, j), L.node(next, j), pitch, -half);
      }
    }
  }
  // Triangles, with their edges' springs found from the node pairs.
  std::map<std::pair<int, int>, int> spring_of;
  for (int s = 0; s < L.springs(); ++s) {
    spring_of[{L.a[s], L.b[s]}] = s;
    spring_of[{L.b[s], L.a[s]}] = s;
  }
  auto tri = [&](int n0, int n1, int n2, float x1, float z1, float x2, float z2) {
    L.tri_nodes.push_back({n0, n1, n2});
    L.tri_springs.push_back(
        {spring_of.at({n0, n1}), spring_of.at({n1, n2}), spring_of.at({n2, n0})});
    L.tri_offsets.push_back({x1, z1, x2, z2});
  };
  for (int i = 0; i < n_r; ++i) {
    const int next = (i + 1) % n_r;
    for (int j = 0; j < n_h; ++j) {
      const int up = (j + 1) % n_h;
      if (i % 2 == 0) {
        // (i,j), (i+1,j), (i,j+1) and (i,j+1), (i+1,j), (i+1,j+1): counter-clockwise in (x, z).
        tri(L.node(i, j), L.node(next, j), L.node(i, up), pitch, half, 0.0f, lo);
        tri(L.node(i, up), L.node(next, j), L.node(next, up), pitch, -half, pitch, half);
      } else {
        tri(L.node(i, j), L.node(next, up), L.node(i, up), pitch, half, 0.0f, lo);
        tri(L.node(i, j), L.node(next, j), L.node(next, up), pitch, -half, pitch, half);
      }
    }
  }
  L.spring_tris.assign(L.a.size(), {-1, -1});
  for (std::size_t t = 0; t < L.tri_springs.size(); ++t) {
    for (int e = 0; e < 3; ++e) {
      std::array<int32_t, 2>& side = L.spring_tris[L.tri_springs[t][e]];
      side[side[0] < 0 ? 0 : 1] = static_cast<int32_t>(t);
    }
  }
  // The triangles' steps (regions.cpp walks plates by them), as the region measure computed them.
  const double pitch0 = L.pitch(), half0 = L.l_o / 2.0;
  for (const auto& o : L.tri_offsets) {
    std::array<int8_t, 4> st;
    for (int k = 0; k < 2; ++k) {
      st[2 * k] = static_cast<int8_t>(std::lround(o[2 * k] / pitch0));
      st[2 * k + 1] = static_cast<int8_t>(std::lround(o[2 * k + 1] / half0));
    }
    L.tri_steps.push_back(st);
  }
  // The spring pass's layout: slots, each node's springs in index order, the runs of four.
  const int springs = L.springs();
  L.slot_b.assign(springs, 0);
  for (int s = 0; s < springs; ++s) L.slot_b[L.slot(s)] = L.b[s];
  std::vector<int> count(n, 0);
  L.inc_slot.assign(6 * static_cast<std::size_t>(n), 0);
  L.inc_a.assign(6 * static_cast<std::size_t>(n), 0);
  for (int s = 0; s < springs; ++s) {
    for (int end = 0; end < 2; ++end) {
      const int v = end == 0 ? L.a[s] : L.b[s];
      const std::size_t e = 6 * static_cast<std::size_t>(v) + count[v]++;
      L.inc_slot[e] = L.slot(s);
      L.inc_a[e] = end == 0;
    }
  }
  // Runs of w slots (consecutive b within one sub-family) and of w nodes (entry by entry
  // consecutive slots, the same ends).
  auto slot_runs = [&](int w, std::vector<uint8_t>* out) {
    out->assign(springs, 0);
    for (int q = 0; q + w - 1 < springs; ++q) {
      bool run = (q % n) + w - 1 < n;  // within one sub-family
      for (int k = 1; k < w && run; ++k) run = L.slot_b[q + k] == L.slot_b[q] + k;
      (*out)[q] = run;
    }
  };
  auto node_runs = [&](int w, std::vector<uint8_t>* out) {
    out->assign(n, 0);
    for (int v = 0; v + w - 1 < n; ++v) {
      bool run = true;
      for (int k = 1; k < w && run; ++k) {
        for (int e = 0; e < 6 && run; ++e) {
          const std::size_t p = 6 * static_cast<std::size_t>(v) + e, q = p + 6 * k;
          run = L.inc_slot[q] == L.inc_slot[p] + k && L.inc_a[q] == L.inc_a[p];
        }
      }
      (*out)[v] = run;
    }
  };
  slot_runs(4, &L.slot_run4);
  slot_runs(8, &L.slot_run8);
  node_runs(4, &L.node_run4);
  node_runs(8, &L.node_run8);
  // Scan lines: a triangle's axial edge (its two nodes in one column) and its apex fix its strip,
  // its half (beside the axial edge) and the lines through it. Heights in quarters of L_o.
  L.line_around.assign(static_cast<std::size_t>(n_h) * 2 * n_r, -1);
  L.line_along.assign(static_cast<std::size_t>(n_r) * 2 * n_h, -1);
  auto pmod = [](int v, int m) { return ((v % m) + m) % m; };
  for (std::size_t t = 0; t < L.tri_nodes.size(); ++t) {
    const int n0 = L.tri_nodes[t][0], c0 = n0 / n_h;
    const auto& o = L.tri_offsets[t];
    int col[3], z4[3];
    col[0] = c0;
    z4[0] = 4 * (n0 % n_h) + 2 * (c0 % 2);
    for (int k = 1; k < 3; ++k) {
      col[k] = c0 + static_cast<int>(std::lround(o[2 * (k - 1)] / pitch));
      z4[k] = z4[0] + static_cast<int>(std::lround(o[2 * (k - 1) + 1] / (lo / 4.0f)));
    }
    int apex = 0;
    for (int k = 0; k < 3; ++k)
      if (col[k] != col[(k + 1) % 3] && col[k] != col[(k + 2) % 3]) apex = k;
    const int e0 = (apex + 1) % 3, e1 = (apex + 2) % 3;
    const int za = std::min(z4[e0], z4[e1]);  // the axial edge spans [za, za + 4]
    const bool right = col[apex] > col[e0];   // the apex right of the axial edge
    const int strip = pmod(std::min(col[apex], col[e0]), n_r);
    const int line = pmod((za + pmod(1 - za, 4) - 1) / 4, n_h);
    const int side = 2 * strip + (right ? 0 : 1);
    L.line_around[static_cast<std::size_t>(line) * 2 * n_r + side] = static_cast<int32_t>(t);
    L.line_along[static_cast<std::size_t>(strip) * 2 * n_h + pmod(za / 2, 2 * n_h)] =
        static_cast<int32_t>(t);
  }
  return L;
}

}  // namespace niwa::bark
