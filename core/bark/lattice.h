// The 2-layer model's lattice (paper 003 §3.1, Fig. 3; ../shared/specs/bark.md §1.2): a triangular
// lattice of N_R columns around the trunk and N_H nodes along it, wrapped into a torus (around and
// along), whose lattice lines run along the trunk axis. Column i sits at arc position
// x_i = i·(√3/2)·L_o, node j of it at z_ij = j·L_o + (i mod 2)·L_o/2; node index i·N_H + j. Each
// node owns three forward springs: one axial (family 1, to (i, j+1)) and two diagonals at ±30° from
// the circumferential direction (family 2: even i to (i+1, j) and (i+1, j−1), odd i to (i+1, j+1)
// and (i+1, j)); all axial springs come first, then the diagonals, each in node order. Every
// spring keeps its reference vector (a to b, unwrapped), so a seam spring is an interior one.
// Also the lattice's triangles (two per node, each one axial and two diagonal edges) for the maps
// and the region measure. Does not: hold any state of a run (springs.h) or know the materials.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace niwa::bark {

enum class Family : uint8_t { kAxial = 0, kDiagonal = 1 };

struct Lattice {
  int n_r = 0, n_h = 0;
  double l_o = 0;  // reference spring length (cm)
  // Springs, structure of arrays: node a, node b, the reference vector a -> b (cm, unwrapped).
  std::vector<int32_t> a, b;
  std::vector<float> ox, oz;
  int axial_count = 0;  // springs [0, axial_count) are axial, the rest diagonal
  // Triangles: three nodes (counter-clockwise in (x, z)), the springs of edges (0,1), (1,2),
  // (2,0), and the reference vectors of nodes 1 and 2 from node 0.
  std::vector<std::array<int32_t, 3>> tri_nodes, tri_springs;
  std::vector<std::array<float, 4>> tri_offsets;  // x1, z1, x2, z2
  // The same in whole steps: columns and half-spacings (lround(x/pitch), lround(z/(L_o/2))).
  std::vector<std::array<int8_t, 4>> tri_steps;
  // The two triangles on either side of each spring (every spring has two on the torus).
  std::vector<std::array<int32_t, 2>> spring_tris;
  // The spring pass's layout (springs.cpp). A spring's force slot: axial s -> s, diagonal
  // s = N + 2n + k -> N + k·N + n (N nodes), so each of the three sub-families (axial, first and
  // second diagonal of a node) lists its springs in node order, node a = n. slot_b: node b of each
  // slot. inc_slot / inc_a: each node's six springs in ascending spring index (the order the
  // forces were summed in, spring by spring), as slot and 1 when the node is the spring's a.
  // slot_run4: slots n..n+3 of a sub-family have consecutive b. node_run4: nodes n..n+3 have, entry
  // by entry, consecutive slots and the same ends (so four nodes sum as lanes). slot_run8 and
  // node_run8: the same for eight (the AVX2 batches, springs.h BatchLanes).
  std::vector<int32_t> slot_b, inc_slot;
  // Scan lines (the crack-spacing measure, regions.h), one triangle a half of a strip or row.
  // line_around: N_H lines around the trunk at z = (j + 1/4)·L_o, each of 2·N_R halves, half h
  // at x ∈ [h, h + 1]·pitch/2 (no line runs through a node, each triangle there is pitch/2 wide);
  // line_along: N_R lines along the trunk half-way between columns i and i + 1, each of 2·N_H
  // halves, half h at z ∈ [L_o/4 + h·L_o/2, L_o/4 + (h + 1)·L_o/2]. Every triangle is on one line
  // of each.
  std::vector<int32_t> line_around, line_along;
  std::vector<uint8_t> inc_a, slot_run4, node_run4, slot_run8, node_run8;

  int nodes() const { return n_r * n_h; }
  int springs() const { return static_cast<int>(a.size()); }
  Family family(int s) const { return s < axial_count ? Family::kAxial : Family::kDiagonal; }
  int node(int i, int j) const { return i * n_h + j; }
  // The force slot of spring s (see slot_b), and the spring of a slot.
  int slot(int s) const {
    return s < axial_count
               ? s
               : axial_count + ((s - axial_count) & 1) * nodes() + (s - axial_count) / 2;
  }
  int spring_of_slot(int q) const {
    if (q < axial_count) return q;
    const int k = (q - axial_count) / nodes(), n = (q - axial_count) % nodes();
    return axial_count + 2 * n + k;
  }
  double pitch() const;          // (√3/2)·L_o: the column spacing around the trunk
  double circumference() const;  // N_R·pitch = 2π·R_o
  double height() const;         // H_o = L_o·N_H
  double radius() const;         // R_o = √3·L_o·N_R/(4π)
  // Reference position of node (i, j) in the unrolled patch (cm).
  double x_of(int i) const;
  double z_of(int i, int j) const;
};

// The lattice of n_r (even, ≥ 4) columns and n_h (≥ 3) rows at spacing l_o.
Lattice BuildLattice(int n_r, int n_h, double l_o);

// A lattice's column pitch and radius from its rows without building it (Lattice::pitch and
// radius are these): (√3/2)·L_o, and R_o = √3·L_o·N_R/(4π).
double LatticePitch(double l_o);
double LatticeRadius(int n_r, double l_o);

}  // namespace niwa::bark
