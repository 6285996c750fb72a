// Regions, intercepts and broken fractions of a cracked surface layer.
#include "bark/regions.h"

#include <algorithm>
#include <cmath>

namespace niwa::bark {

CrackMeasures MeasureCracks(const Lattice& L, const Surface& s, double s_theta, double s_z) {
  CrackMeasures m;
  for (int i = 0; i < L.springs(); ++i) {
    const int f = static_cast<int>(L.family(i));
    ++m.springs[f];
    m.broken[f] += s.broken[i];
  }
  for (int f = 0; f < 2; ++f)
    m.broken_fraction[f] = m.springs[f] ? static_cast<double>(m.broken[f]) / m.springs[f] : 0.0;
  const int all = m.broken[0] + m.broken[1];
  m.vertical_crack_share = all ? static_cast<double>(m.broken[1]) / all : 0.0;

  // Plates: intact triangles joined across their (intact) edges. Each triangle's nodes sit at
  // whole steps of columns and half-spacings from its node 0.
  const int nt = static_cast<int>(L.tri_nodes.size());
  const double pitch0 = L.pitch(), half0 = L.l_o / 2.0;
  auto step_of = [&](int t, int k, int* dc, int* dz) {
    if (k == 0) {
      *dc = *dz = 0;
      return;
    }
    *dc = static_cast<int>(std::lround(L.tri_offsets[t][2 * (k - 1)] / pitch0));
    *dz = static_cast<int>(std::lround(L.tri_offsets[t][2 * (k - 1) + 1] / half0));
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
    r.width = r.wraps_around ? L.circumference() * s_theta : (cmax - cmin) * pitch;
    r.height = r.wraps_along ? L.height() * s_z : (zmax - zmin) * half;
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
  return m;
}

}  // namespace niwa::bark
