// The page's flat buffers of a grown mountain (see terrain_surface.h).
#include "terrain/terrain_surface.h"

#include <algorithm>
#include <cmath>

#include "terrain/terrain_output.h"

namespace niwa::terrain {

void BuildSurfaceBuffers(const Terrain& t, const Heightfield& hf, SurfaceBuffers* out) {
  const int w = hf.width, h = hf.height;
  const std::size_t cells = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  out->positions.resize(cells * 3);
  out->normals.resize(cells * 3);
  out->colours.resize(cells * 3);
  double lo = 0, hi = 0;
  if (cells > 0) {
    const auto [a, b] = std::minmax_element(hf.h.begin(), hf.h.end());
    lo = *a;
    hi = *b;
  }
  const double span = hi > lo ? hi - lo : 1.0;
  float* pos = out->positions.data();
  float* nrm = out->normals.data();
  float* col = out->colours.data();
  for (int j = 0; j < h; ++j) {
    const int jn = std::max(j - 1, 0), js = std::min(j + 1, h - 1);
    const double* row = hf.h.data() + static_cast<std::size_t>(j) * static_cast<std::size_t>(w);
    const double* north = hf.h.data() + static_cast<std::size_t>(jn) * static_cast<std::size_t>(w);
    const double* south = hf.h.data() + static_cast<std::size_t>(js) * static_cast<std::size_t>(w);
    const double y = hf.y1 - (j + 0.5) * hf.cell;
    for (int i = 0; i < w; ++i) {
      const std::size_t k = 3 * (static_cast<std::size_t>(j) * static_cast<std::size_t>(w) +
                                 static_cast<std::size_t>(i));
      pos[k] = static_cast<float>(hf.x0 + (i + 0.5) * hf.cell);
      pos[k + 1] = static_cast<float>(row[i]);
      pos[k + 2] = static_cast<float>(-y);
      // Central differences (one-sided at the border): dh/dx east, dh/dy north (row j−1); the
      // surface (x, h(x, y), −y) has the normal ∝ (−∂h/∂x, 1, ∂h/∂y), as the .glb's.
      const int il = std::max(i - 1, 0), ir = std::min(i + 1, w - 1);
      const double gx = ir > il ? (row[ir] - row[il]) / ((ir - il) * hf.cell) : 0;
      const double gy = js > jn ? (north[i] - south[i]) / ((js - jn) * hf.cell) : 0;
      const double len = std::sqrt(gx * gx + 1.0 + gy * gy);
      nrm[k] = static_cast<float>(-gx / len);
      nrm[k + 1] = static_cast<float>(1.0 / len);
      nrm[k + 2] = static_cast<float>(gy / len);
      HypsometricColour((row[i] - lo) / span, col + k);
    }
  }
  if (out->indices_width != w || out->indices_height != h) {
    out->indices.clear();
    if (w >= 2 && h >= 2) {
      out->indices.resize(static_cast<std::size_t>(w - 1) * static_cast<std::size_t>(h - 1) * 6);
      uint32_t* q = out->indices.data();
      for (int j = 0; j + 1 < h; ++j) {
        for (int i = 0; i + 1 < w; ++i) {
          const auto a = static_cast<uint32_t>(j * w + i), b = a + 1,
                     c = static_cast<uint32_t>((j + 1) * w + i), d = c + 1;
          // Counter-clockwise seen from above (+y up, row j+1 is south = +z).
          *q++ = a;
          *q++ = c;
          *q++ = b;
          *q++ = b;
          *q++ = c;
          *q++ = d;
        }
      }
    }
    out->indices_width = w;
    out->indices_height = h;
  }
  out->line_positions.clear();
  out->line_height.clear();
  out->line_level.clear();
  for (const ContourNode& node : t.contours) {
    const std::size_t n = node.ring.size();
    const auto e = static_cast<float>(node.elevation);
    const auto level = static_cast<float>(node.level);
    for (std::size_t p = 0; p < n; ++p) {
      const Vec2& u = node.ring[p];
      const Vec2& v = node.ring[(p + 1) % n];
      out->line_positions.insert(out->line_positions.end(),
                                 {static_cast<float>(u.x), e, static_cast<float>(-u.y),
                                  static_cast<float>(v.x), e, static_cast<float>(-v.y)});
      out->line_height.insert(out->line_height.end(), {e, e});
      out->line_level.insert(out->line_level.end(), {level, level});
    }
  }
  out->summit_positions.clear();
  out->summit_radius.clear();
  for (const Summit& s : t.summits) {
    out->summit_positions.insert(out->summit_positions.end(),
                                 {static_cast<float>(s.position.x), static_cast<float>(s.elevation),
                                  static_cast<float>(-s.position.y)});
    out->summit_radius.push_back(static_cast<float>(s.radius));
  }
}

}  // namespace niwa::terrain
