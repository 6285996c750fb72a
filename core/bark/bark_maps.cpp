// The bark maps: plates rasterised on the torus, a signed distance to their outlines (exact to the
// outline's segments near them), a pillow and a crack-wall profile for the height, and the height,
// normal, colour and ORM images.
#include "bark/bark_maps.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
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

unsigned char Byte(float v) {
  const float c = std::min(1.0f, std::max(0.0f, v));
  return static_cast<unsigned char>(static_cast<int>(c * 255.0f + 0.5f));
}

float Smooth(float u) {
  const float c = std::min(1.0f, std::max(0.0f, u));
  return c * c * (3.0f - 2.0f * c);
}

// The deformed corners of triangle t of a surface, in pixels (x right, y down the image).
void TrianglePx(const Lattice& L, const Surface& s, int t, double s_theta, double s_z, double px_x,
                double px_y, double hf, double X[3], double Y[3]) {
  const auto& nd = L.tri_nodes[t];
  const auto& of = L.tri_offsets[t];
  const int n0 = nd[0], i0 = n0 / L.n_h, j0 = n0 % L.n_h;
  const double x0 = L.x_of(i0) * s_theta + s.ux[n0], z0 = L.z_of(i0, j0) * s_z + s.uz[n0];
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
}

bool Drawn(const Lattice& L, const Surface& s, int t) {
  const auto& sp = L.tri_springs[t];
  return !(s.broken[sp[0]] || s.broken[sp[1]] || s.broken[sp[2]]);
}

// Visits the pixel centres inside triangle (X, Y) (pixels of a wrapped width × height grid;
// edges inclusive, so neighbouring plates leave no hairline) as indices into the grid. Each row's
// run is found from its ends (the test at a pixel centre: every edge function ≥ −1e−9·|area|) and
// filled between them (a triangle's row is one run).
template <class Visit>
void RasteriseTriangle(const double X[3], const double Y[3], int width, int height, Visit visit) {
  const double area = (X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0]);
  if (area == 0) return;
  const double sign = area > 0 ? 1.0 : -1.0, eps = -1e-9 * std::fabs(area);
  const int xa = static_cast<int>(std::floor(std::min({X[0], X[1], X[2]}) - 0.5));
  const int xb = static_cast<int>(std::ceil(std::max({X[0], X[1], X[2]}) - 0.5));
  const int ya = static_cast<int>(std::floor(std::min({Y[0], Y[1], Y[2]}) - 0.5));
  const int yb = static_cast<int>(std::ceil(std::max({Y[0], Y[1], Y[2]}) - 0.5));
  for (int iy = ya; iy <= yb; ++iy) {
    const double cy = iy + 0.5;
    auto inside = [&](int ix) {
      const double cx = ix + 0.5;
      for (int k = 0; k < 3; ++k) {
        const int k1 = (k + 1) % 3;
        const double e = ((X[k1] - X[k]) * (cy - Y[k]) - (Y[k1] - Y[k]) * (cx - X[k])) * sign;
        if (!(e >= eps)) return false;
      }
      return true;
    };
    int lo = xa;
    while (lo <= xb && !inside(lo)) ++lo;
    if (lo > xb) continue;
    int hi = xb;
    while (hi > lo && !inside(hi)) --hi;
    const std::size_t row = static_cast<std::size_t>(WrapIndex(iy, height)) * width;
    int wx = WrapIndex(lo, width);
    for (int ix = lo; ix <= hi; ++ix) {
      visit(row + wx);
      if (++wx == width) wx = 0;
    }
  }
}

// Lowers d2 (squared cm) of a wrapped width × height grid to the squared distance to the segment
// (X0, Y0)-(X1, Y1) (pixels) over the segment's box grown by bx × by pixels; tx, ty are cm per
// pixel. In cm from the segment's first corner (small numbers: a turned surface gives the same
// distances); each row's run is split where it wraps, so the inner loop is contiguous (and
// vectorises; the same float operations in every lane).
void SegmentBand(double X0, double Y0, double X1, double Y1, double tx, double ty, int bx, int by,
                 int width, int height, float* d2) {
  const float dx = static_cast<float>((X1 - X0) * tx);
  const float dy = static_cast<float>((Y1 - Y0) * ty);
  const float l2 = dx * dx + dy * dy;
  const float inv = l2 > 0 ? 1.0f / l2 : 0.0f;
  const float ftx = static_cast<float>(tx);
  const int sxa = static_cast<int>(std::floor(std::min(X0, X1) - 0.5)) - bx;
  int sxb = static_cast<int>(std::ceil(std::max(X0, X1) - 0.5)) + bx;
  sxb = std::min(sxb, sxa + width - 1);
  const int sya = static_cast<int>(std::floor(std::min(Y0, Y1) - 0.5)) - by;
  const int syb = static_cast<int>(std::ceil(std::max(Y0, Y1) - 0.5)) + by;
  const float px0 = static_cast<float>((sxa + 0.5 - X0) * tx);
  const int wx0 = WrapIndex(sxa, width);
  const int run1 = std::min(sxb - sxa + 1, width - wx0);
  for (int iy = sya; iy <= syb; ++iy) {
    const float py = static_cast<float>((iy + 0.5 - Y0) * ty);
    float* row = d2 + static_cast<std::size_t>(WrapIndex(iy, height)) * width;
    const float pyd = py * dy;
    for (int part = 0; part < 2; ++part) {
      const int from = part == 0 ? 0 : run1, to = part == 0 ? run1 : sxb - sxa + 1;
      float* out = row + (part == 0 ? wx0 : 0) - from;
      for (int i = from; i < to; ++i) {
        const float px = px0 + static_cast<float>(i) * ftx;
        const float u = std::min(1.0f, std::max(0.0f, (px * dx + pyd) * inv));
        const float qx = px - u * dx, qy = py - u * dy;
        const float q2 = qx * qx + qy * qy;
        out[i] = std::min(out[i], q2);
      }
    }
  }
}

// The drawing of one layer: which plate covers each texel (0: none), at the map's resolution;
// and, on a grid `scale` (1 or 2) times coarser, whether a plate covers the texel and its signed
// distance (cm, + on a plate) to the plates' outline, exact within `band` of it and ±band beyond.
struct LayerField {
  std::vector<int32_t> plate;  // width × height
  int scale = 1;
  std::vector<uint8_t> cover;  // (width / scale) × (height / scale)
  std::vector<float> sd;       // the same
};

// Rasterises the plates of a surface (its triangles with three intact springs) at their deformed
// positions, then measures the distance to the outline (the edges of drawn triangles whose
// neighbour across is not drawn) as segments (so a crack's edge is a line, not the pixels'
// stairs), on the coarser grid (a triangle's corners there are its pixel coordinates halved, exact
// in binary; the coarse cover is read off the map's plates).
LayerField DrawLayer(const Lattice& L, const Surface& s, const std::vector<int>& tri_region,
                     double s_theta, double s_z, double px_x, double px_y, double hf, int width,
                     int height, int scale, double band_cm) {
  const std::size_t npx = static_cast<std::size_t>(width) * height;
  const int ws = width / scale, hs = height / scale;
  const std::size_t ns = static_cast<std::size_t>(ws) * hs;
  LayerField f;
  f.scale = scale;
  f.plate.assign(npx, 0);
  if (scale > 1) f.cover.assign(ns, 0);
  const int ntri = static_cast<int>(L.tri_nodes.size());
  std::vector<uint8_t> drawn(ntri);
  for (int t = 0; t < ntri; ++t) drawn[t] = Drawn(L, s, t);
  const double tx = scale / px_x, ty = scale / px_y;  // cm per texel of the coarser grid
  const double b2 = band_cm * band_cm;
  std::vector<float> d2(ns, static_cast<float>(b2));
  const int bx = static_cast<int>(std::ceil(band_cm * px_x / scale)) + 1;
  const int by = static_cast<int>(std::ceil(band_cm * px_y / scale)) + 1;
  const double inv_scale = 1.0 / scale;
  for (int t = 0; t < ntri; ++t) {
    if (!drawn[t]) continue;
    double X[3], Y[3];
    TrianglePx(L, s, t, s_theta, s_z, px_x, px_y, hf, X, Y);
    const int32_t id = tri_region[t] + 1;
    int32_t* plate = f.plate.data();
    RasteriseTriangle(X, Y, width, height, [plate, id](std::size_t p) { plate[p] = id; });
    if (scale > 1) {
      for (int k = 0; k < 3; ++k) {
        X[k] *= inv_scale;
        Y[k] *= inv_scale;
      }
    }
    // Outline edges: the neighbour across is not drawn.
    const auto& sp = L.tri_springs[t];
    for (int e = 0; e < 3; ++e) {
      const auto& side = L.spring_tris[sp[e]];
      const int other = side[0] == t ? side[1] : side[0];
      if (other >= 0 && drawn[other]) continue;
      const int k1 = (e + 1) % 3;
      SegmentBand(X[e], Y[e], X[k1], Y[k1], tx, ty, bx, by, ws, hs, d2.data());
    }
  }
  // The coarse grid's cover: a coarse texel's centre is the corner of four texels of the map; it
  // is on a plate when two or more of them are.
  if (scale > 1) {
    for (int y = 0; y < hs; ++y) {
      const int32_t* r0 = f.plate.data() + static_cast<std::size_t>(2 * y) * width;
      const int32_t* r1 = r0 + width;
      uint8_t* c = f.cover.data() + static_cast<std::size_t>(y) * ws;
      for (int x = 0; x < ws; ++x)
        c[x] = ((r0[2 * x] != 0) + (r0[2 * x + 1] != 0) + (r1[2 * x] != 0) +
                (r1[2 * x + 1] != 0)) >= 2;
    }
  }
  f.sd.resize(ns);
  for (std::size_t p = 0; p < ns; ++p) {
    const float d = std::sqrt(d2[p]);
    const bool on = scale > 1 ? f.cover[p] != 0 : f.plate[p] != 0;
    f.sd[p] = on ? d : -d;
  }
  return f;
}

// Doubles a wrapped w × h grid of integers bilinearly (texel centres: each output texel is 9:3:3:1
// of its four nearest inputs), handing emit(index, 16 × value) for the 2w × 2h grid. Integers, so
// exact: a grid shifted by a whole texel doubles to the doubled grid shifted by two.
template <class Emit>
void Upsample2(const std::vector<int32_t>& in, int w, int h, Emit emit) {
  std::vector<int64_t> col(static_cast<std::size_t>(w));
  const int w2 = 2 * w;
  for (int y = 0; y < 2 * h; ++y) {
    const int yn = y >> 1;
    const int other = (y & 1) ? (yn + 1 == h ? 0 : yn + 1) : (yn == 0 ? h - 1 : yn - 1);
    const int32_t* near = in.data() + static_cast<std::size_t>(yn) * w;
    const int32_t* far = in.data() + static_cast<std::size_t>(other) * w;
    for (int x = 0; x < w; ++x) col[x] = 3 * static_cast<int64_t>(near[x]) + far[x];
    const std::size_t row = static_cast<std::size_t>(y) * w2;
    for (int x = 0; x < w; ++x) {
      const int64_t c = col[x];
      const int64_t left = col[x == 0 ? w - 1 : x - 1], right = col[x + 1 == w ? 0 : x + 1];
      emit(row + 2 * x, 3 * c + left);
      emit(row + 2 * x + 1, 3 * c + right);
    }
  }
}

// A wrapped box blur of integers over (2·rx + 1) × (2·ry + 1) texels, as sums (exact: the
// result does not depend on where a row starts, so a turned surface blurs to the turned map).
void BoxSumRows(const std::vector<int32_t>& in, int width, int height, int r,
                std::vector<int32_t>* out) {
  out->resize(in.size());
  for (int y = 0; y < height; ++y) {
    const int32_t* a = in.data() + static_cast<std::size_t>(y) * width;
    int32_t* o = out->data() + static_cast<std::size_t>(y) * width;
    int32_t sum = 0;
    for (int k = -r; k <= r; ++k) sum += a[WrapIndex(k, width)];
    int lo = WrapIndex(-r, width), hi = WrapIndex(r + 1, width);
    for (int x = 0; x < width; ++x) {
      o[x] = sum;
      sum += a[hi] - a[lo];
      if (++hi == width) hi = 0;
      if (++lo == width) lo = 0;
    }
  }
}

void BoxSumColumns(const std::vector<int32_t>& in, int width, int height, int r,
                   std::vector<int32_t>* out) {
  out->resize(in.size());
  std::vector<int32_t> sum(width, 0);
  for (int k = -r; k <= r; ++k) {
    const int32_t* a = in.data() + static_cast<std::size_t>(WrapIndex(k, height)) * width;
    for (int x = 0; x < width; ++x) sum[x] += a[x];
  }
  int lo = WrapIndex(-r, height), hi = WrapIndex(r + 1, height);
  for (int y = 0; y < height; ++y) {
    int32_t* o = out->data() + static_cast<std::size_t>(y) * width;
    const int32_t* ah = in.data() + static_cast<std::size_t>(hi) * width;
    const int32_t* al = in.data() + static_cast<std::size_t>(lo) * width;
    for (int x = 0; x < width; ++x) {
      o[x] = sum[x];
      sum[x] += ah[x] - al[x];
    }
    if (++hi == height) hi = 0;
    if (++lo == height) lo = 0;
  }
}

// Sums v (in place, |v| ≤ vmax) over a box rx × ry twice (a tent), in integers: a value c
// everywhere comes out c·n²/k, n = (2rx+1)(2ry+1), k the returned divisor: 1, or n when n²·vmax
// would overflow (then the first pass's sums are divided by n).
int64_t TentSum(std::vector<int32_t>* v, int width, int height, int rx, int ry, int64_t vmax) {
  const int64_t n = static_cast<int64_t>(2 * rx + 1) * (2 * ry + 1);
  const bool divide = n * n * vmax >= (int64_t{1} << 31);
  std::vector<int32_t> tmp;
  BoxSumRows(*v, width, height, rx, &tmp);
  BoxSumColumns(tmp, width, height, ry, v);
  if (divide)
    for (int32_t& x : *v) x = static_cast<int32_t>(x / n);
  BoxSumRows(*v, width, height, rx, &tmp);
  BoxSumColumns(tmp, width, height, ry, v);
  return divide ? n : 1;
}

// Periodic value noise over the image (gx × gy cells, bilinear, wraps both ways), as a table.
std::vector<float> PeriodicNoise(int width, int height, int gx, int gy, uint32_t salt) {
  std::vector<float> lattice(static_cast<std::size_t>(gx) * gy);
  for (int j = 0; j < gy; ++j)
    for (int i = 0; i < gx; ++i)
      lattice[static_cast<std::size_t>(j) * gx + i] =
          Hash01(static_cast<uint32_t>(i) + salt, static_cast<uint32_t>(j));
  std::vector<int> cx(width);
  std::vector<float> fx(width);
  for (int x = 0; x < width; ++x) {
    const float f =
        (static_cast<float>(x) + 0.5f) * static_cast<float>(gx) / static_cast<float>(width);
    cx[x] = static_cast<int>(f);
    fx[x] = f - static_cast<float>(cx[x]);
  }
  std::vector<float> out(static_cast<std::size_t>(width) * height);
  std::vector<float> blend(static_cast<std::size_t>(gx) + 1);
  for (int y = 0; y < height; ++y) {
    const float f =
        (static_cast<float>(y) + 0.5f) * static_cast<float>(gy) / static_cast<float>(height);
    const int cy = static_cast<int>(f);
    const float ty = f - static_cast<float>(cy);
    const float* r0 = lattice.data() + static_cast<std::size_t>(cy % gy) * gx;
    const float* r1 = lattice.data() + static_cast<std::size_t>((cy + 1) % gy) * gx;
    // The row's lattice values blended along y once, then along x per texel.
    for (int i = 0; i < gx; ++i) blend[i] = r0[i] + (r1[i] - r0[i]) * ty;
    blend[gx] = blend[0];
    float* o = out.data() + static_cast<std::size_t>(y) * width;
    for (int x = 0; x < width; ++x) {
      const int c0 = cx[x];
      o[x] = blend[c0] + (blend[c0 + 1] - blend[c0]) * fx[x];
    }
  }
  return out;
}

// One layer as the maps draw it: its field, its top above the inner layer (cm), its palette and
// its plates' jitter salt.
struct DrawnLayer {
  std::vector<int32_t> plate;   // plate id + 1 of each texel, 0: none
  std::vector<float> sd;        // blurred signed distance to the outline (cm)
  std::vector<int32_t> pillow;  // tent-summed plate cover, 0..pillow_full
  double top = 0;
  const double* colour = nullptr;
  uint32_t salt = 7u;
};

// The shape of a plate's top (a fraction of its layer's top) from its signed distance to the
// outline (cm) and its pillow (0..1): a crack wall over w_wall (the crack widens into the plate,
// so its width and depth follow the broken springs), the plate's bulge (its middle stands highest)
// and the curl of its edges (a lip just inside the wall).
struct Relief {
  float wall = 0;  // the wall's width (cm)
  float lip = 0;   // the lip's half-width (cm)
  float bulge = 0.45f, curl = 0.15f;
  float Of(float sd, float pillow) const {
    const float u = Smooth((sd + 0.1f * wall) / wall);
    float h = u * (1.0f - bulge * (1.0f - pillow));
    const float v = (sd - wall) / lip;
    if (v > -1.0f && v < 1.0f) h += curl * u * (1.0f - v * v) * (1.0f - v * v);
    return std::min(1.0f, h);
  }
};

// The stylised palette: a dark red-brown crack floor, warm fresh cork in the walls, grey-brown
// plates weathering to grey.
constexpr BarkPalette kStylised = {
    {0.40, 0.34, 0.28}, {0.46, 0.29, 0.18}, {0.30, 0.16, 0.09}, {0.56, 0.54, 0.50}};

// The four maps from the drawn layers (outermost first): height = the highest layer's relief
// (each layer a solid from the inner layer up to its top, so a crack shows what lies beneath);
// normal from the height plus a fibre grain along the trunk (the grain is in the normal and the
// colour, not the height map); colour by layer, plate (age jitter), depth and weathering; ORM.
void FillMaps(int width, int height, const std::vector<DrawnLayer>& layers, const Relief& relief,
              int32_t pillow_full, const BarkPalette& palette, BarkMaps* maps) {
  float floor_rgb[3], wall_rgb[3], weathered_rgb[3];
  for (int k = 0; k < 3; ++k) {
    floor_rgb[k] = static_cast<float>(palette.floor[k]);
    wall_rgb[k] = static_cast<float>(palette.wall[k]);
    weathered_rgb[k] = static_cast<float>(palette.weathered[k]);
  }
  const std::size_t npx = static_cast<std::size_t>(width) * height;
  const double top = layers.front().top;
  const float inv_top = top > 0 ? static_cast<float>(1.0 / top) : 0.0f;
  const float inv_full = 1.0f / static_cast<float>(pillow_full);
  std::vector<float> hn(npx);          // height / top
  std::vector<uint8_t> level(npx);     // 0 the inner layer, else layer index + 1
  std::vector<float> face(npx, 0.0f);  // 0 at a wall's foot .. 1 on the plate's top
  const int nl = static_cast<int>(layers.size());
  for (std::size_t p = 0; p < npx; ++p) {
    float best = 0;
    int lv = 0;
    float fc = 0;
    for (int r = 0; r < nl; ++r) {
      const DrawnLayer& d = layers[r];
      const float sd = d.sd[p];
      if (sd <= -0.1f * relief.wall) continue;
      const float rel = relief.Of(sd, static_cast<float>(d.pillow[p]) * inv_full);
      const float h = rel * static_cast<float>(d.top) * inv_top;
      if (h > best) {
        best = h;
        lv = r + 1;
        fc = Smooth((sd + 0.1f * relief.wall) / relief.wall);
      }
    }
    hn[p] = best;
    level[p] = static_cast<uint8_t>(lv);
    face[p] = fc;
  }
  // Fibres: fine cells across the trunk, long along it; a coarser mottling.
  const std::vector<float> fibre =
      PeriodicNoise(width, height, std::max(4, width / 3), std::max(2, height / 24), 17u);
  const std::vector<float> mottle =
      PeriodicNoise(width, height, std::max(2, width / 48), std::max(2, height / 64), 91u);
  // Each plate's age and jitter, looked up by plate id.
  std::vector<std::vector<float>> age(nl), jitter(nl);
  for (int r = 0; r < nl; ++r) {
    const DrawnLayer& d = layers[r];
    const int32_t top_id = *std::max_element(d.plate.begin(), d.plate.end());
    age[r].resize(static_cast<std::size_t>(top_id) + 1);
    jitter[r].resize(age[r].size());
    for (int32_t id = 0; id <= top_id; ++id) {
      age[r][id] = Hash01(static_cast<uint32_t>(id), d.salt);
      jitter[r][id] = 0.75f + 0.45f * Hash01(static_cast<uint32_t>(id), d.salt + 1u);
    }
  }
  // Every texel is written below: the images are sized, not filled.
  maps->height.width = maps->base_colour.width = maps->normal.width = maps->orm.width = width;
  maps->height.height = maps->base_colour.height = maps->normal.height = maps->orm.height = height;
  maps->height.pixels.resize(npx);
  maps->base_colour.pixels.resize(4 * npx);
  maps->normal.pixels.resize(4 * npx);
  maps->orm.pixels.resize(4 * npx);
  // Slopes per unit of hn and of the grain, per texel across (x) and along (row).
  const float sx = static_cast<float>(top / (2.0 * maps->texel_cm_x));
  const float sy = static_cast<float>(top / (2.0 * maps->texel_cm_y));
  const float grain_cm = 0.012f;  // the fibres' relief
  const float gsx = static_cast<float>(grain_cm / (2.0 * maps->texel_cm_x));
  const float gsy = static_cast<float>(grain_cm / (2.0 * maps->texel_cm_y));
  for (int y = 0; y < height; ++y) {
    const std::size_t row = static_cast<std::size_t>(y) * width;
    const std::size_t up = static_cast<std::size_t>(y == 0 ? height - 1 : y - 1) * width;
    const std::size_t down = static_cast<std::size_t>(y == height - 1 ? 0 : y + 1) * width;
    uint16_t* hrow = &maps->height.At(0, y);
    for (int x = 0; x < width; ++x) {
      const std::size_t p = row + x;
      const int xl = x == 0 ? width - 1 : x - 1, xr = x == width - 1 ? 0 : x + 1;
      const float h = hn[p];
      hrow[x] = static_cast<uint16_t>(static_cast<int>(std::min(1.0f, h) * 65535.0f + 0.5f));
      // The grain shows on plates' tops, fading down the walls.
      const float on = level[p] ? face[p] : 0.4f;
      const float g = fibre[p];
      const float dgx = (fibre[row + xr] - fibre[row + xl]) * gsx * on;
      const float dgy = (fibre[down + x] - fibre[up + x]) * gsy * on;
      const float dhdx = (hn[row + xr] - hn[row + xl]) * sx + dgx;
      const float dhdrow = (hn[down + x] - hn[up + x]) * sy + dgy;
      // Image rows run down, +y of the normal is up.
      const float nx = -dhdx, ny = dhdrow;
      const float inv = 1.0f / std::sqrt(nx * nx + ny * ny + 1.0f);
      unsigned char* n = maps->normal.At(x, y);
      n[0] = Byte(0.5f + 0.5f * nx * inv);
      n[1] = Byte(0.5f + 0.5f * ny * inv);
      n[2] = Byte(0.5f + 0.5f * inv);
      n[3] = 255;
      const float m = mottle[p];
      const float grain = 0.86f + 0.22f * g;
      float rgb[3];
      float rough;
      if (level[p]) {
        const int r = level[p] - 1;
        const DrawnLayer& d = layers[r];
        const int32_t id = d.plate[p];
        // A plate's age: older plates (and a plate's high middle) weather to grey.
        const float age_p = age[r][id];
        const float jit = jitter[r][id];
        const float pil = static_cast<float>(d.pillow[p]) * inv_full;
        const float weather = std::min(1.0f, (0.15f + 0.5f * age_p) * pil * (0.6f + 0.8f * m));
        const float fc = face[p];
        for (int k = 0; k < 3; ++k) {
          const float plate = static_cast<float>(d.colour[k]) * jit;
          const float topc = plate + (weathered_rgb[k] - plate) * weather;
          rgb[k] = (wall_rgb[k] + (topc - wall_rgb[k]) * fc) * grain * (0.8f + 0.2f * pil);
        }
        rough = 0.78f + 0.14f * (1.0f - fc) + 0.06f * g;
      } else {
        for (int k = 0; k < 3; ++k) rgb[k] = floor_rgb[k] * (0.85f + 0.3f * m);
        rough = 0.95f;
      }
      // Cavity: deep texels darker.
      const float cav = 0.68f + 0.32f * std::min(1.0f, h * 1.6f);
      unsigned char* c = maps->base_colour.At(x, y);
      c[0] = Byte(rgb[0] * cav);
      c[1] = Byte(rgb[1] * cav);
      c[2] = Byte(rgb[2] * cav);
      c[3] = 255;
      unsigned char* o = maps->orm.At(x, y);
      o[0] = Byte(0.3f + 0.7f * std::min(1.0f, h * 1.25f));  // occlusion: crack depth
      o[1] = Byte(rough);
      o[2] = 0;  // metallic
      o[3] = 255;
    }
  }
}

// Draws layers (outermost first; each its surface, regions, anchor scale, top, colour) at the
// axial growth factor s_z into maps spanning the outermost layer's circumference.
BarkMaps DrawLayers(const Lattice& L, const std::vector<MapLayer>& layers, double s_z, int width,
                    const BarkPalette& palette) {
  const double cf = L.circumference() * layers.front().s_theta, hf = L.height() * s_z;
  const int height = MapHeightPx(width, cf, hf);
  BarkMaps maps;
  maps.texel_cm_x = cf / width;
  maps.texel_cm_y = hf / height;
  const double px_y = height / hf;
  Relief relief;
  relief.wall = static_cast<float>(0.6 * L.l_o);
  relief.lip = static_cast<float>(0.3 * L.l_o);
  const double band = relief.wall + relief.lip + 0.45 * L.l_o;
  // The distance field and the pillow are smooth: when a texel is under 0.15·L_o, they are
  // measured on a grid twice as coarse and doubled bilinearly (a quarter of the texels; the plate
  // ids stay at the map's resolution).
  const int scale = 2.0 * std::max(maps.texel_cm_x, maps.texel_cm_y) <= 0.3 * L.l_o &&
                            width % 2 == 0 && height % 2 == 0
                        ? 2
                        : 1;
  const int ws = width / scale, hs = height / scale;
  const double tex_x = maps.texel_cm_x * scale, tex_y = maps.texel_cm_y * scale;
  // The pillow: plate cover blurred over about one spring length.
  const int rx = std::max(1, static_cast<int>(std::lround(0.5 * L.l_o / tex_x)));
  const int ry = std::max(1, static_cast<int>(std::lround(0.5 * L.l_o / tex_y)));
  const int64_t n = static_cast<int64_t>(2 * rx + 1) * (2 * ry + 1);
  int64_t pillow_div = 1;
  const int sx = std::max(1, static_cast<int>(std::lround(0.4 * L.l_o / tex_x)));
  const int sy = std::max(1, static_cast<int>(std::lround(0.4 * L.l_o / tex_y)));
  const int64_t ns = static_cast<int64_t>(2 * sx + 1) * (2 * sy + 1);
  const int64_t up = scale == 2 ? 16 : 1;  // Upsample2's weights
  std::vector<DrawnLayer> drawn(layers.size());
  for (std::size_t r = 0; r < layers.size(); ++r) {
    const MapLayer& m = layers[r];
    const double px_x = width / (L.circumference() * m.s_theta);
    DrawnLayer& d = drawn[r];
    LayerField field = DrawLayer(L, *m.surface, *m.tri_region, m.s_theta, s_z, px_x, px_y, hf,
                                 width, height, scale, band);
    d.plate = std::move(field.plate);
    // The outline's lattice zigzag rounded: the distance tent-blurred over about 0.4·L_o (in
    // integers of 1/1024 cm, so the blur is exact and a turned surface gives the turned map).
    std::vector<int32_t> q(field.sd.size());
    for (std::size_t p = 0; p < q.size(); ++p)
      q[p] = static_cast<int32_t>(std::lround(field.sd[p] * 1024.0f));
    std::vector<float>().swap(field.sd);
    const int64_t qmax = static_cast<int64_t>(std::ceil(band * 1024.0)) + 1;
    const int64_t k = TentSum(&q, ws, hs, sx, sy, qmax);
    const float per =
        static_cast<float>(static_cast<double>(k) / (1024.0 * static_cast<double>(ns * ns * up)));
    d.sd.resize(d.plate.size());
    // The pillow from the same grid's cover.
    std::vector<int32_t> cover(q.size());
    for (std::size_t p = 0; p < cover.size(); ++p)
      cover[p] = (scale > 1 ? field.cover[p] != 0 : d.plate[p] != 0) ? 1 : 0;
    std::vector<uint8_t>().swap(field.cover);
    pillow_div = TentSum(&cover, ws, hs, rx, ry, 1);
    if (scale == 2) {
      float* sd = d.sd.data();
      Upsample2(q, ws, hs,
                [sd, per](std::size_t p, int64_t v) { sd[p] = static_cast<float>(v) * per; });
      std::vector<int32_t>().swap(q);
      d.pillow.resize(d.plate.size());
      int32_t* pillow = d.pillow.data();
      Upsample2(cover, ws, hs,
                [pillow](std::size_t p, int64_t v) { pillow[p] = static_cast<int32_t>(v); });
    } else {
      for (std::size_t p = 0; p < q.size(); ++p) d.sd[p] = static_cast<float>(q[p]) * per;
      d.pillow = std::move(cover);
    }
    d.top = m.top;
    d.colour = m.colour;
    d.salt = 7u + 131u * static_cast<uint32_t>(layers.size() - r);
  }
  FillMaps(width, height, drawn, relief, static_cast<int32_t>(n * n / pillow_div * up), palette,
           &maps);
  return maps;
}

}  // namespace

int NearestPowerOfTwo(double want, int lo, int hi) {
  int best = lo;
  double best_ratio = 1e300;
  for (int p = lo; p <= hi; p *= 2) {
    const double r = std::max(p / want, want / p);
    if (r < best_ratio) {
      best_ratio = r;
      best = p;
    }
  }
  return best;
}

int MapHeightPx(int width, double circumference_cm, double height_cm) {
  return NearestPowerOfTwo(width * height_cm / circumference_cm, 256, 4096);
}

BarkPalette SpeciesPalette(const std::string& species) {
  if (species == "camphor")  // Cinnamomum camphora: grey-brown plates, dark brown furrows
    return {{0.45, 0.39, 0.33}, {0.36, 0.26, 0.19}, {0.17, 0.12, 0.09}, {0.53, 0.50, 0.46}};
  if (species == "tallow")  // Triadica sebifera: light grey plates, grey-brown fissures
    return {{0.52, 0.49, 0.44}, {0.42, 0.34, 0.26}, {0.23, 0.18, 0.14}, {0.63, 0.61, 0.58}};
  if (species == "pine")  // Pinus (red and black pine): red-brown plates, orange cork beneath
    return {{0.47, 0.32, 0.24}, {0.64, 0.37, 0.22}, {0.21, 0.12, 0.08}, {0.49, 0.45, 0.42}};
  return kStylised;
}

BarkMaps DrawBarkMaps(const Lattice& L, const Surface& s, const CrackMeasures& cracks,
                      double s_theta, double s_z, double D, int width) {
  return DrawBarkMaps(L, s, cracks, s_theta, s_z, D, width, kStylised);
}

BarkMaps DrawBarkMaps(const Lattice& L, const Surface& s, const CrackMeasures& cracks,
                      double s_theta, double s_z, double D, int width, const BarkPalette& palette) {
  MapLayer m;
  m.surface = &s;
  m.tri_region = &cracks.tri_region;
  m.s_theta = s_theta;
  m.top = D;
  m.thickness = D;
  for (int k = 0; k < 3; ++k) m.colour[k] = palette.plate[k];
  return DrawLayers(L, {m}, s_z, width, palette);
}

BarkMaps DrawLayeredMaps(const Lattice& L, const std::vector<MapLayer>& layers, double s_z,
                         int width) {
  return DrawLayers(L, layers, s_z, width, kStylised);
}

BarkMaps DrawLayeredMaps(const Lattice& L, const std::vector<MapLayer>& layers, double s_z,
                         int width, const BarkPalette& palette) {
  return DrawLayers(L, layers, s_z, width, palette);
}

}  // namespace niwa::bark
