// The bark maps: plates rasterised on the torus, a wrapped chamfer distance for the bevel, the
// height, normal, colour and ORM images.
#include "bark/bark_maps.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace niwa::bark {
namespace {

int WrapIndex(int v, int n) {
  const int r = v % n;
  return r < 0 ? r + n : r;
}

uint32_t MixBits(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

float Hash01(uint32_t a, uint32_t b) {
  return static_cast<float>(MixBits(a * 0x9e3779b9u ^ MixBits(b + 0x632be5abu)) >> 8) *
         (1.0f / 16777216.0f);
}

// Periodic value noise on a gx × gy cell grid over the image (bilinear, wraps both ways).
float BarkGrain(int x, int y, int width, int height, int gx, int gy, uint32_t salt) {
  const float fx =
      (static_cast<float>(x) + 0.5f) * static_cast<float>(gx) / static_cast<float>(width);
  const float fy =
      (static_cast<float>(y) + 0.5f) * static_cast<float>(gy) / static_cast<float>(height);
  const int x0 = static_cast<int>(std::floor(fx)), y0 = static_cast<int>(std::floor(fy));
  const float tx = fx - static_cast<float>(x0), ty = fy - static_cast<float>(y0);
  auto at = [&](int cx, int cy) {
    return Hash01(static_cast<uint32_t>(WrapIndex(cx, gx)) + salt,
                  static_cast<uint32_t>(WrapIndex(cy, gy)));
  };
  const float a = at(x0, y0) + (at(x0 + 1, y0) - at(x0, y0)) * tx;
  const float b = at(x0, y0 + 1) + (at(x0 + 1, y0 + 1) - at(x0, y0 + 1)) * tx;
  return a + (b - a) * ty;
}

unsigned char Byte(double v) {
  const double c = std::min(1.0, std::max(0.0, v));
  return static_cast<unsigned char>(std::lround(c * 255.0));
}

// Rasterises the plates of a surface (its triangles with three intact springs) at their deformed
// positions: pixel centres inside a triangle (edges inclusive, so neighbouring plates leave no
// hairline) get put(pixel index, triangle). px_x, px_y: pixels per cm; hf: the patch height (cm).
template <typename Put>
void RasterPlates(const Lattice& L, const Surface& s, double s_theta, double s_z, double px_x,
                  double px_y, double hf, int width, int height, Put put) {
  for (std::size_t t = 0; t < L.tri_nodes.size(); ++t) {
    const auto& sp = L.tri_springs[t];
    if (s.broken[sp[0]] || s.broken[sp[1]] || s.broken[sp[2]]) continue;
    const auto& nd = L.tri_nodes[t];
    const auto& of = L.tri_offsets[t];
    const int n0 = nd[0], i0 = n0 / L.n_h, j0 = n0 % L.n_h;
    const double x0 = L.x_of(i0) * s_theta + s.ux[n0], z0 = L.z_of(i0, j0) * s_z + s.uz[n0];
    double X[3], Y[3];
    X[0] = x0;
    Y[0] = z0;
    for (int k = 1; k < 3; ++k) {
      const int nk = nd[k];
      X[k] = x0 + of[2 * (k - 1)] * s_theta + (s.ux[nk] - s.ux[n0]);
      Y[k] = z0 + of[2 * (k - 1) + 1] * s_z + (s.uz[nk] - s.uz[n0]);
    }
    for (int k = 0; k < 3; ++k) {
      X[k] *= px_x;
      Y[k] = (hf - Y[k]) * px_y;  // image rows run down the trunk
    }
    const double area = (X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0]);
    if (area == 0) continue;
    const double sign = area > 0 ? 1.0 : -1.0, eps = -1e-9 * std::fabs(area);
    const int xa = static_cast<int>(std::floor(std::min({X[0], X[1], X[2]}) - 0.5));
    const int xb = static_cast<int>(std::ceil(std::max({X[0], X[1], X[2]}) - 0.5));
    const int ya = static_cast<int>(std::floor(std::min({Y[0], Y[1], Y[2]}) - 0.5));
    const int yb = static_cast<int>(std::ceil(std::max({Y[0], Y[1], Y[2]}) - 0.5));
    for (int iy = ya; iy <= yb; ++iy) {
      const double cy = iy + 0.5;
      for (int ix = xa; ix <= xb; ++ix) {
        const double cx = ix + 0.5;
        bool inside = true;
        for (int k = 0; k < 3 && inside; ++k) {
          const int k1 = (k + 1) % 3;
          const double e = ((X[k1] - X[k]) * (cy - Y[k]) - (Y[k1] - Y[k]) * (cx - X[k])) * sign;
          inside = e >= eps;
        }
        if (inside)
          put(static_cast<std::size_t>(WrapIndex(iy, height)) * width + WrapIndex(ix, width),
              static_cast<int>(t));
      }
    }
  }
}

// Chamfer (3-4, in thirds of a pixel) distances to the pixels holding 0, wrapped: two
// forward-backward sweeps carry distances across the seams.
void WrappedChamfer(int width, int height, std::vector<int>* dist_) {
  std::vector<int>& dist = *dist_;
  auto idx = [width, height](int x, int y) {
    return static_cast<std::size_t>(WrapIndex(y, height)) * width + WrapIndex(x, width);
  };
  for (int sweep = 0; sweep < 2; ++sweep) {
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        int& d = dist[idx(x, y)];
        d = std::min({d, dist[idx(x - 1, y)] + 3, dist[idx(x, y - 1)] + 3,
                      dist[idx(x - 1, y - 1)] + 4, dist[idx(x + 1, y - 1)] + 4});
      }
    for (int y = height - 1; y >= 0; --y)
      for (int x = width - 1; x >= 0; --x) {
        int& d = dist[idx(x, y)];
        d = std::min({d, dist[idx(x + 1, y)] + 3, dist[idx(x, y + 1)] + 3,
                      dist[idx(x + 1, y + 1)] + 4, dist[idx(x - 1, y + 1)] + 4});
      }
  }
}

constexpr int kFar = 1 << 20;
// The 2-layer model's plates: grey-brown.
constexpr double kPlateRgb[3] = {0.40, 0.34, 0.28};

// The four maps from a wrapped height field h (cm; `top` its highest level) and what covers each
// texel: colour(p, &rgb, &jitter) is true on a plate (rgb its layer's colour, jitter its per-plate
// factor) and false on the crack floor. The one texel loop of both models' maps.
template <typename PlateColour>
void FillMaps(int width, int height, const std::vector<double>& h, double top, PlateColour colour,
              BarkMaps* maps) {
  auto idx = [width, height](int x, int y) {
    return static_cast<std::size_t>(WrapIndex(y, height)) * width + WrapIndex(x, width);
  };
  maps->height = image::MakeGray16(width, height);
  maps->base_colour = image::MakeRgba8(width, height);
  maps->normal = image::MakeRgba8(width, height);
  maps->orm = image::MakeRgba8(width, height);
  const int gx = std::max(1, width / 4), gy = std::max(1, height / 32);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::size_t p = idx(x, y);
      const double hn = top > 0 ? h[p] / top : 0.0;
      maps->height.At(x, y) = static_cast<uint16_t>(std::lround(std::min(1.0, hn) * 65535.0));
      // Normal from central differences (wrapped); image rows run down, +y of the normal is up.
      const double dhdx = (h[idx(x + 1, y)] - h[idx(x - 1, y)]) / (2.0 * maps->texel_cm_x);
      const double dhdrow = (h[idx(x, y + 1)] - h[idx(x, y - 1)]) / (2.0 * maps->texel_cm_y);
      double nx = -dhdx, ny = dhdrow, nz = 1.0;
      const double len = std::sqrt(nx * nx + ny * ny + nz * nz);
      unsigned char* n = maps->normal.At(x, y);
      n[0] = Byte(0.5 + 0.5 * nx / len);
      n[1] = Byte(0.5 + 0.5 * ny / len);
      n[2] = Byte(0.5 + 0.5 * nz / len);
      n[3] = 255;
      // Colour: plates their layer's colour × a per-plate jitter × the grain; cracks the inner
      // layer's red-brown.
      const double grain = 0.8 + 0.25 * BarkGrain(x, y, width, height, gx, gy, 17u) +
                           0.15 * BarkGrain(x, y, width, height, gx * 2, gy * 2, 91u);
      unsigned char* c = maps->base_colour.At(x, y);
      const double* rgb = nullptr;
      double jitter = 1;
      const bool on_plate = colour(p, &rgb, &jitter);
      if (on_plate) {
        const double f = jitter * grain * (0.75 + 0.25 * hn);
        c[0] = Byte(rgb[0] * f);
        c[1] = Byte(rgb[1] * f);
        c[2] = Byte(rgb[2] * f);
      } else {
        const double f = 0.8 * grain;
        c[0] = Byte(0.42 * f);
        c[1] = Byte(0.20 * f);
        c[2] = Byte(0.11 * f);
      }
      c[3] = 255;
      unsigned char* o = maps->orm.At(x, y);
      o[0] = Byte(0.35 + 0.65 * hn);       // occlusion: crack depth
      o[1] = Byte(on_plate ? 0.8 : 0.95);  // roughness
      o[2] = 0;                            // metallic
      o[3] = 255;
    }
  }
}

}  // namespace

int MapHeightPx(int width, double circumference_cm, double height_cm) {
  const double want = width * height_cm / circumference_cm;
  int best = 256;
  double best_ratio = 1e300;
  for (int p = 256; p <= 4096; p *= 2) {
    const double r = std::max(p / want, want / p);
    if (r < best_ratio) {
      best_ratio = r;
      best = p;
    }
  }
  return best;
}

BarkMaps DrawBarkMaps(const Lattice& L, const Surface& s, const CrackMeasures& cracks,
                      double s_theta, double s_z, double D, int width) {
  const double cf = L.circumference() * s_theta, hf = L.height() * s_z;
  const int height = MapHeightPx(width, cf, hf);
  BarkMaps maps;
  maps.texel_cm_x = cf / width;
  maps.texel_cm_y = hf / height;
  const double px_x = width / cf, px_y = height / hf;
  // Plates: each intact triangle's pixels take its region's id + 1; 0 is crack.
  std::vector<int32_t> plate(static_cast<std::size_t>(width) * height, 0);
  RasterPlates(L, s, s_theta, s_z, px_x, px_y, hf, width, height,
               [&](std::size_t p, int t) { plate[p] = cracks.tri_region[t] + 1; });
  // Distance to the nearest crack pixel.
  const std::size_t npx = plate.size();
  std::vector<int> dist(npx);
  for (std::size_t p = 0; p < npx; ++p) dist[p] = plate[p] == 0 ? 0 : kFar;
  WrappedChamfer(width, height, &dist);
  // Height (cm): plate tops at D, bevelled by b = 0.3·D within w = 0.5·L_o of a crack; cracks at
  // the inner layer's top (0).
  const double texel = std::sqrt(maps.texel_cm_x * maps.texel_cm_y);
  const double bevel = 0.3 * D, reach = 0.5 * L.l_o;
  std::vector<double> h(npx);
  for (std::size_t p = 0; p < npx; ++p) {
    if (plate[p] == 0) {
      h[p] = 0;
      continue;
    }
    const double delta = dist[p] / 3.0 * texel;
    h[p] = D - bevel * std::max(0.0, 1.0 - delta / reach);
  }
  FillMaps(
      width, height, h, D,
      [&](std::size_t p, const double** rgb, double* jitter) {
        if (plate[p] == 0) return false;
        *rgb = kPlateRgb;
        *jitter = 0.85 + 0.3 * Hash01(static_cast<uint32_t>(plate[p]), 7u);
        return true;
      },
      &maps);
  return maps;
}

BarkMaps DrawLayeredMaps(const Lattice& L, const std::vector<MapLayer>& layers, double s_z,
                         int width) {
  const int nl = static_cast<int>(layers.size());
  const double cf = L.circumference() * layers.front().s_theta, hf = L.height() * s_z;
  const int height = MapHeightPx(width, cf, hf);
  BarkMaps maps;
  maps.texel_cm_x = cf / width;
  maps.texel_cm_y = hf / height;
  const double px_y = height / hf;
  // Levels: 0 the inner layer, nl the outermost; drawn from the innermost layer outward.
  const std::size_t npx = static_cast<std::size_t>(width) * height;
  std::vector<uint8_t> level(npx, 0);
  std::vector<int32_t> plate(npx, 0);
  for (int r = nl - 1; r >= 0; --r) {
    const MapLayer& m = layers[r];
    const double px_x = width / (L.circumference() * m.s_theta);
    const uint8_t lv = static_cast<uint8_t>(nl - r);
    RasterPlates(L, *m.surface, m.s_theta, s_z, px_x, px_y, hf, width, height,
                 [&](std::size_t p, int t) {
                   level[p] = lv;
                   plate[p] = (*m.tri_region)[t] + 1;
                 });
  }
  // Per level, the distance to the nearest pixel of a lower level (the bevel of its edges).
  std::vector<std::vector<int>> dist(nl + 1);
  for (int lv = 1; lv <= nl; ++lv) {
    dist[lv].resize(npx);
    for (std::size_t p = 0; p < npx; ++p) dist[lv][p] = level[p] < lv ? 0 : kFar;
    WrappedChamfer(width, height, &dist[lv]);
  }
  const double texel = std::sqrt(maps.texel_cm_x * maps.texel_cm_y);
  const double reach = 0.5 * L.l_o;
  const double top = layers.front().top;
  std::vector<double> h(npx);
  for (std::size_t p = 0; p < npx; ++p) {
    if (level[p] == 0) {
      h[p] = 0;
      continue;
    }
    const MapLayer& m = layers[nl - level[p]];
    const double delta = dist[level[p]][p] / 3.0 * texel;
    h[p] = m.top - 0.3 * m.thickness * std::max(0.0, 1.0 - delta / reach);
  }
  FillMaps(
      width, height, h, top,
      [&](std::size_t p, const double** rgb, double* jitter) {
        if (level[p] == 0) return false;
        *rgb = layers[nl - level[p]].colour;
        *jitter = 0.85 + 0.3 * Hash01(static_cast<uint32_t>(plate[p]), 7u + 131u * level[p]);
        return true;
      },
      &maps);
  return maps;
}

}  // namespace niwa::bark
