// Regions, intercepts and broken fractions of a cracked surface layer.
#include "bark/regions.h"

#include <algorithm>
#include <cmath>

namespace niwa::bark {
namespace {

// The spacing of the cracks on `lines` lines of `halves` halves each (cm a half), line l's half h
// the triangle table[l·halves + h]; counted[t]: triangle t is in a counted plate. With `crosses`,
// a crack run is a crossing only when one of its triangles has crosses[t] set; the line goes
// through any other run as through plate (see MeasureCracks: the horizontal cracks along).
Spacing ScanSpacing(const std::vector<int32_t>& table, int lines, int halves, double half_cm,
                    const std::vector<uint8_t>& counted, const std::vector<uint8_t>* crosses) {
  Spacing sp;
  double sum = 0, gaps = 0, gap_sum = 0;
  std::vector<double> middles;
  for (int l = 0; l < lines; ++l) {
    const int32_t* row = table.data() + static_cast<std::size_t>(l) * halves;
    int first_crack = -1, plates = 0;
    for (int h = 0; h < halves; ++h) {
      if (counted[row[h]])
        ++plates;
      else if (first_crack < 0)
        first_crack = h;
    }
    if (plates == 0) continue;
    ++sp.lines;
    const double length = halves * half_cm;
    if (first_crack < 0) {
      ++sp.open;
      sum += length;
      sp.max = std::max(sp.max, length);
      continue;
    }
    // Runs of crack from a plate half on, going round once: the middles of those that cross.
    int start = first_crack;
    while (!counted[row[start % halves]]) ++start;  // the first plate half after a crack
    middles.clear();
    for (int k = 0; k < halves;) {
      if (counted[row[(start + k) % halves]]) {
        ++k;
        continue;
      }
      const int run_start = k;
      bool crossing = crosses == nullptr;
      for (; k < halves && !counted[row[(start + k) % halves]]; ++k)
        crossing = crossing || (*crosses)[row[(start + k) % halves]];
      if (crossing) middles.push_back(start + (run_start + k) / 2.0);
    }
    const int cracks = static_cast<int>(middles.size());
    if (cracks == 0) {  // only runs that do not cross: the line is open
      ++sp.open;
      sum += length;
      sp.max = std::max(sp.max, length);
      continue;
    }
    const double spacing = length / cracks;
    sum += spacing;
    sp.max = std::max(sp.max, spacing);
    for (int c = 0; c < cracks; ++c) {
      const double next = c + 1 < cracks ? middles[c + 1] : middles[0] + halves;
      const double gap = (next - middles[c]) * half_cm;
      gap_sum += gap;
      gaps += 1;
      sp.gap_max = std::max(sp.gap_max, gap);
    }
  }
  if (sp.lines > 0) sp.mean = sum / sp.lines;
  if (gaps > 0) sp.gap_mean = gap_sum / gaps;
  return sp;
}

}  // namespace

CrackMeasures MeasurePlates(const Lattice& L, const Surface& s, double s_theta, double s_z) {
  CrackMeasures m;
  // Plates: intact triangles joined across their (intact) edges. Each triangle's nodes sit at
  // whole steps of columns and half-spacings from its node 0 (lattice.h tri_steps).
  const int nt = static_cast<int>(L.tri_nodes.size());
  const double pitch0 = L.pitch(), half0 = L.l_o / 2.0;
  auto step_of = [&](int t, int k, int* dc, int* dz) {
    if (k == 0) {
      *dc = *dz = 0;
      return;
    }
    *dc = L.tri_steps[t][2 * (k - 1)];
    *dz = L.tri_steps[t][2 * (k - 1) + 1];
  };
  std::vector<uint8_t> plate(nt, 0);
  for (int t = 0; t < nt; ++t) {
    const auto& sp = L.tri_springs[t];
    plate[t] = !(s.broken[sp[0]] || s.broken[sp[1]] || s.broken[sp[2]]);
  }
  m.tri_region.assign(nt, -1);
  std::vector<int> acol(nt), az(nt), queue;
  const double pitch = pitch0 * s_theta, half = half0 * s_z;
  double counted = 0, closed = 0, plates = 0, sum_w = 0, sum_h = 0;
  for (int start = 0; start < nt; ++start) {
    if (!plate[start] || m.tri_region[start] >= 0) continue;
    const int id = static_cast<int>(m.regions.size());
    Region r;
    queue.assign(1, start);
    m.tri_region[start] = id;
    const int n0 = L.tri_nodes[start][0];
    acol[start] = n0 / L.n_h;
    az[start] = 2 * (n0 % L.n_h) + (n0 / L.n_h) % 2;
    int cmin = acol[start], cmax = cmin, zmin = az[start], zmax = zmin;
    for (std::size_t q = 0; q < queue.size(); ++q) {
      const int t = queue[q];
      for (int k = 0; k < 3; ++k) {
        int dc, dz;
        step_of(t, k, &dc, &dz);
        cmin = std::min(cmin, acol[t] + dc);
        cmax = std::max(cmax, acol[t] + dc);
        zmin = std::min(zmin, az[t] + dz);
        zmax = std::max(zmax, az[t] + dz);
      }
      for (int e = 0; e < 3; ++e) {
        const int spring = L.tri_springs[t][e];
        const int other =
            L.spring_tris[spring][0] == t ? L.spring_tris[spring][1] : L.spring_tris[spring][0];
        if (!plate[other]) continue;
        // The shared node u (node e of t): where t puts it, less its step within the other.
        const int u = L.tri_nodes[t][e];
        int dc, dz;
        step_of(t, e, &dc, &dz);
        int k2 = 0;
        while (L.tri_nodes[other][k2] != u) ++k2;
        int dc2, dz2;
        step_of(other, k2, &dc2, &dz2);
        const int c = acol[t] + dc - dc2, z = az[t] + dz - dz2;
        if (m.tri_region[other] >= 0) {
          if (c != acol[other]) r.wraps_around = true;
          if (z != az[other]) r.wraps_along = true;
          continue;
        }
        m.tri_region[other] = id;
        acol[other] = c;
        az[other] = z;
        queue.push_back(other);
      }
    }
    r.triangles = static_cast<int>(queue.size());
    // On the torus no plate is wider or taller than the patch: a plate wrapping around the trunk
    // may wind up and down in its unwrapped walk (a wavy band) further than H without closing a
    // loop along it; it then covers every height, so its height is H (likewise the width).
    const double c_patch = L.circumference() * s_theta, h_patch = L.height() * s_z;
    r.width = r.wraps_around ? c_patch : std::min((cmax - cmin) * pitch, c_patch);
    r.height = r.wraps_along ? h_patch : std::min((zmax - zmin) * half, h_patch);
    m.regions.push_back(r);
    plates += r.triangles;
    if (r.triangles < 2) continue;
    ++m.count;
    if (!r.closed()) ++m.strips;
    counted += r.triangles;
    if (r.closed()) closed += r.triangles;
    sum_w += r.width;
    sum_h += r.height;
    m.max_width = std::max(m.max_width, r.width);
    m.max_height = std::max(m.max_height, r.height);
  }
  m.plate_fraction = nt ? plates / nt : 0.0;
  if (m.count > 0) {
    m.mean_width = sum_w / m.count;
    m.mean_height = sum_h / m.count;
    m.closed_fraction = closed / counted;
  }
  return m;
}

CrackMeasures MeasureCracks(const Lattice& L, const Surface& s, double s_theta, double s_z) {
  CrackMeasures m = MeasurePlates(L, s, s_theta, s_z);
  const int nt = static_cast<int>(L.tri_nodes.size());
  for (int i = 0; i < L.springs(); ++i) {
    const int f = static_cast<int>(L.family(i));
    ++m.springs[f];
    m.broken[f] += s.broken[i];
  }
  for (int f = 0; f < 2; ++f)
    m.broken_fraction[f] = m.springs[f] ? static_cast<double>(m.broken[f]) / m.springs[f] : 0.0;
  const int all = m.broken[0] + m.broken[1];
  m.vertical_crack_share = all ? static_cast<double>(m.broken[1]) / all : 0.0;
  // Intercepts. A row j crosses a crack between columns i and i+1 when a diagonal of (i, j) broke;
  // a column's cracks are its broken axial springs.
  double crossings = 0, axial_broken = 0;
  for (int i = L.axial_count; i < L.springs(); i += 2) {
    if (s.broken[i] || s.broken[i + 1]) ++crossings;
  }
  for (int i = 0; i < L.axial_count; ++i) axial_broken += s.broken[i];
  const double per_row = crossings / L.n_h, per_column = axial_broken / L.n_r;
  m.intercept_width = per_row > 0 ? L.circumference() * s_theta / per_row : 0.0;
  m.intercept_height = per_column > 0 ? L.height() * s_z / per_column : 0.0;
  // Crack spacing along the scan lines, over the counted plates.
  std::vector<uint8_t> in_counted(nt, 0);
  for (int t = 0; t < nt; ++t) {
    const int id = m.tri_region[t];
    in_counted[t] = id >= 0 && m.regions[id].triangles >= 2;
  }
  m.spacing_width =
      ScanSpacing(L.line_around, L.n_h, 2 * L.n_r, L.pitch() * s_theta / 2.0, in_counted, nullptr);
  // Along the trunk the paper measured the spacing of the *horizontal* cracks (「縦横のひびの間隔を
  // 計測した」, paper 003 §3.2 before Table 3: the spacing of the vertical and the horizontal
  // cracks; Table 3's height is the horizontal cracks' spacing). A horizontal crack cuts a column:
  // it breaks axial springs (spec §1.3: family 1 makes the horizontal cracks), and a crack can only
  // pass from one column gap to the next through a broken axial spring. A run of crack on a line
  // along, which lies half-way between two columns, whose triangles lost only diagonal edges is a
  // vertical crack lying on the line for a while (a furrow confined to that column gap, ending
  // there, its neighbour en échelon in the next gap): the line runs along it and crosses nothing
  // horizontal, so it is not a region boundary along the trunk. Only runs holding a triangle whose
  // axial edge broke count. Around the trunk every crack run counts (a horizontal crack breaks
  // diagonals as well, so the families do not tell its runs apart there). docs/bark-model.md
  // choice 10a; `spacing_height_all_runs` keeps the measure before (every run a crossing).
  std::vector<uint8_t> axial_cut(nt, 0);
  for (int t = 0; t < nt; ++t) {
    for (int e = 0; e < 3; ++e) {
      const int spring = L.tri_springs[t][e];
      if (L.family(spring) == Family::kAxial && s.broken[spring]) axial_cut[t] = 1;
    }
  }
  m.spacing_height =
      ScanSpacing(L.line_along, L.n_r, 2 * L.n_h, L.l_o * s_z / 2.0, in_counted, &axial_cut);
  m.spacing_height_all_runs =
      ScanSpacing(L.line_along, L.n_r, 2 * L.n_h, L.l_o * s_z / 2.0, in_counted, nullptr);
  return m;
}

}  // namespace niwa::bark
