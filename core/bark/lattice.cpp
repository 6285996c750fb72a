// The triangular torus lattice of the 2-layer model: springs and triangles by fixed rules.
#include "bark/lattice.h"

#include <cmath>
#include <map>
#include <utility>

#include "math/det_math.h"

namespace niwa::bark {

double Lattice::pitch() const { return std::sqrt(3.0) / 2.0 * l_o; }
double Lattice::circumference() const { return n_r * pitch(); }
double Lattice::height() const { return n_h * l_o; }
double Lattice::radius() const { return std::sqrt(3.0) * l_o * n_r / (4.0 * det::kPi); }
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
  return L;
}

}  // namespace niwa::bark
