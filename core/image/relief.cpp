// Bird's-eye pictures of a heightfield: a perspective z-buffer rasteriser with Gouraud-shaded
// hypsometric tint, and its brute-force ray-casting twin.
#include "image/relief.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>

#include "math/det_math.h"

namespace niwa::image {
namespace {

constexpr int kMaxGridSide = 4097;
constexpr int kMinPicture = 16, kMaxPicture = 4096;

struct V3 {
  double x = 0, y = 0, z = 0;
};
V3 Sub(const V3& a, const V3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V3 Add(const V3& a, const V3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V3 Scale(const V3& a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double Dot(const V3& a, const V3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 Cross(const V3& a, const V3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
V3 Unit(const V3& a) {
  const double l = std::sqrt(Dot(a, a));
  return l > 0 ? Scale(a, 1.0 / l) : V3{0, 1, 0};
}

// Compass bearing b (degrees) and elevation e: the unit vector from the origin towards them, in
// the world frame (x east, y up, z south).
V3 Towards(double bearing_deg, double elevation_deg) {
  double sb = 0, cb = 1, se = 0, ce = 1;
  det::SinCos(bearing_deg * det::kPi / 180.0, &sb, &cb);
  det::SinCos(elevation_deg * det::kPi / 180.0, &se, &ce);
  return {ce * sb, se, -ce * cb};
}

// The world, the camera and the screen mapping shared by the rasteriser and the ray caster.
struct Scene {
  int w = 0, h = 0;    // grid samples
  int pw = 0, ph = 0;  // picture pixels
  std::vector<V3> p;   // sample positions (world), w·h; y NaN for a hole
  V3 eye, right, up, forward;
  double focal = 1;       // pixels per unit of x/z at depth 1
  double lo = 0, hi = 1;  // tint range (m, before exaggeration)
  double exaggeration = 1;
};

Status CheckInputs(const ReliefGrid& g, const ReliefView& v) {
  if (g.width < 2 || g.height < 2 || g.width > kMaxGridSide || g.height > kMaxGridSide)
    return Status::Error("grid", "must be 2..4097 samples each way, got " +
                                     std::to_string(g.width) + " x " + std::to_string(g.height));
  if (!(std::isfinite(g.cell) && g.cell > 0) || !std::isfinite(g.x0) || !std::isfinite(g.y1))
    return Status::Error("grid", "cell must be finite and > 0, origin finite");
  if (g.heights.size() != static_cast<std::size_t>(g.width) * static_cast<std::size_t>(g.height))
    return Status::Error("grid", "heights must be width x height samples");
  if (std::none_of(g.heights.begin(), g.heights.end(), [](double z) { return std::isfinite(z); }))
    return Status::Error("grid", "has no finite height");
  if (v.width < kMinPicture || v.height < kMinPicture || v.width > kMaxPicture ||
      v.height > kMaxPicture)
    return Status::Error("view", "size must be 16..4096 pixels each way");
  if (!(v.elevation_deg >= 5 && v.elevation_deg <= 90))
    return Status::Error("view", "elevation must be in [5, 90] degrees");
  if (!(v.fov_deg >= 5 && v.fov_deg <= 120))
    return Status::Error("view", "field of view must be in [5, 120] degrees");
  if (!(v.exaggeration >= 0.1 && v.exaggeration <= 20))
    return Status::Error("view", "exaggeration must be in [0.1, 20]");
  if (!std::isfinite(v.view_from_deg) || !std::isfinite(v.sun_from_deg) ||
      !(v.sun_elevation_deg >= 0 && v.sun_elevation_deg <= 90))
    return Status::Error("view", "bearings must be finite, sun elevation in [0, 90] degrees");
  for (double f : v.frame)
    if (!std::isfinite(f)) return Status::Error("view", "frame must be finite");
  if (std::isnan(v.floor) || v.floor == INFINITY)
    return Status::Error("view", "floor must be a number or -inf");
  if (!std::isfinite(v.tint_min) || !std::isfinite(v.tint_max))
    return Status::Error("view", "tint range must be finite");
  return Status::Ok();
}

Scene MakeScene(const ReliefGrid& g, const ReliefView& v) {
  Scene s;
  s.w = g.width;
  s.h = g.height;
  s.pw = v.width;
  s.ph = v.height;
  s.exaggeration = v.exaggeration;
  const bool own = v.frame[0] == 0 && v.frame[1] == 0 && v.frame[2] == 0 && v.frame[3] == 0;
  const double x_min = own ? g.x0 : v.frame[0],
               x_max = own ? g.x0 + (g.width - 1) * g.cell : v.frame[2];
  const double y_min = own ? g.y1 - (g.height - 1) * g.cell : v.frame[1];
  const double y_max = own ? g.y1 : v.frame[3];
  const double slack = 0.5 * g.cell;
  const auto drawn = [&](int i, int j) {
    const double x = g.x0 + i * g.cell, y = g.y1 - j * g.cell;
    return own ||
           (x >= x_min - slack && x <= x_max + slack && y >= y_min - slack && y <= y_max + slack);
  };
  const auto height_at = [&](int i, int j) {
    const double z = g.heights[static_cast<std::size_t>(j) * g.width + i];
    return !std::isfinite(z) || !drawn(i, j) ? NAN : std::max(z, v.floor);
  };
  double lo = 0, hi = 0;
  bool any = false;
  for (int k = 0; k < g.width * g.height; ++k) {
    const double z = height_at(k % g.width, k / g.width);
    if (!std::isfinite(z)) continue;
    lo = any ? std::min(lo, z) : z;
    hi = any ? std::max(hi, z) : z;
    any = true;
  }
  s.lo = v.tint_min < v.tint_max ? v.tint_min : lo;
  s.hi = v.tint_min < v.tint_max ? v.tint_max : hi;
  if (!(s.hi > s.lo)) s.hi = s.lo + 1;
  s.p.resize(g.heights.size());
  for (int j = 0; j < g.height; ++j) {
    for (int i = 0; i < g.width; ++i) {
      const std::size_t k = static_cast<std::size_t>(j) * g.width + i;
      const double z = height_at(i, j);
      // World: x east, y up, z south (north of the grid's origin is -z).
      s.p[k] = {g.x0 + i * g.cell, std::isfinite(z) ? z * v.exaggeration : NAN,
                -(g.y1 - j * g.cell)};
    }
  }
  const V3 centre{0.5 * (x_min + x_max), 0.5 * (lo + hi) * v.exaggeration, -0.5 * (y_min + y_max)};
  const double dx = x_max - x_min, dy = y_max - y_min, dz = (hi - lo) * v.exaggeration;
  const double radius = 0.5 * std::sqrt(dx * dx + dy * dy + dz * dz);
  double s_half = 0, c_half = 1;
  det::SinCos(0.5 * v.fov_deg * det::kPi / 180.0, &s_half, &c_half);
  const V3 towards = Towards(v.view_from_deg, v.elevation_deg);
  s.forward = Scale(towards, -1.0);
  // Looking straight down, "up" on the screen is north.
  const V3 world_up = v.elevation_deg >= 89.999 ? Towards(v.view_from_deg + 180, 0) : V3{0, 1, 0};
  s.right = Unit(Cross(s.forward, world_up));
  s.up = Cross(s.right, s.forward);
  s.focal = 0.5 * v.height * c_half / s_half;
  // The nearest camera (along the same line) that shows the box's 8 corners within 95 % of the
  // picture: bisection between touching the bounding sphere's far side and the sphere fitting.
  const auto fits = [&](double distance) {
    const V3 eye = Add(centre, Scale(towards, distance));
    for (int corner = 0; corner < 8; ++corner) {
      const V3 p{(corner & 1) ? x_max : x_min,
                 (corner & 2) ? hi * v.exaggeration : lo * v.exaggeration,
                 -((corner & 4) ? y_max : y_min)};
      const V3 d = Sub(p, eye);
      const double z = Dot(d, s.forward);
      if (!(z > 1e-9)) return false;
      if (std::abs(Dot(d, s.right)) * s.focal / z > 0.95 * 0.5 * v.width ||
          std::abs(Dot(d, s.up)) * s.focal / z > 0.95 * 0.5 * v.height)
        return false;
    }
    return true;
  };
  double near = std::max(radius, 1e-9), far = near / s_half * 1.02;
  for (int k = 0; k < 30 && !fits(far); ++k) far *= 2;
  for (int k = 0; k < 40; ++k) {
    const double mid = 0.5 * (near + far);
    (fits(mid) ? far : near) = mid;
  }
  s.eye = Add(centre, Scale(towards, far));
  return s;
}

// A world point on the screen: pixel coordinates (x right, y down) and 1/depth; false behind the
// camera.
bool Project(const Scene& s, const V3& p, double* sx, double* sy, double* inv_z) {
  const V3 d = Sub(p, s.eye);
  const double z = Dot(d, s.forward);
  if (!(z > 1e-9)) return false;
  *inv_z = 1.0 / z;
  *sx = 0.5 * s.pw + Dot(d, s.right) * s.focal * *inv_z;
  *sy = 0.5 * s.ph - Dot(d, s.up) * s.focal * *inv_z;
  return true;
}

// The three sample indices of triangle t (cell (i, j): 2·(j·(w−1) + i) and +1).
void Corners(const Scene& s, int64_t t, std::size_t k[3]) {
  const int64_t cell = t / 2;
  const int i = static_cast<int>(cell % (s.w - 1)), j = static_cast<int>(cell / (s.w - 1));
  const std::size_t a = static_cast<std::size_t>(j) * s.w + i, b = a + 1, c = a + s.w, d = c + 1;
  if (t % 2 == 0) {
    k[0] = a, k[1] = c, k[2] = b;
  } else {
    k[0] = b, k[1] = c, k[2] = d;
  }
}

bool Drawn(const Scene& s, const std::size_t k[3]) {
  return std::isfinite(s.p[k[0]].y) && std::isfinite(s.p[k[1]].y) && std::isfinite(s.p[k[2]].y);
}

// Rasterises every triangle with a z-buffer of 1/depth (nearest wins; on a tie the lower index
// stays), calling visit(pixel, triangle or -1, b1, b2) for each pixel at the end, b1 and b2 the
// perspective-correct barycentrics of corners 1 and 2 at the pixel centre: the screen's edge weights
// e_k interpolate 1/z linearly, so b_k = e_k·(1/z_k) / (1/z) (no second ray per pixel).
template <typename Visit>
void Rasterise(const Scene& s, Visit visit) {
  const std::size_t pixels = static_cast<std::size_t>(s.pw) * s.ph;
  std::vector<double> depth(pixels, 0.0);  // 1/z; 0 = nothing yet
  std::vector<int64_t> id(pixels, -1);
  std::vector<double> bary(2 * pixels, 0.0);  // b1, b2 of the surviving triangle
  const int64_t triangles = 2 * static_cast<int64_t>(s.w - 1) * (s.h - 1);
  for (int64_t t = 0; t < triangles; ++t) {
    std::size_t k[3];
    Corners(s, t, k);
    if (!Drawn(s, k)) continue;
    double x[3], y[3], iz[3];
    if (!Project(s, s.p[k[0]], &x[0], &y[0], &iz[0]) ||
        !Project(s, s.p[k[1]], &x[1], &y[1], &iz[1]) ||
        !Project(s, s.p[k[2]], &x[2], &y[2], &iz[2]))
      continue;
    const double area = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
    if (area == 0 || !std::isfinite(area)) continue;
    const int px0 = std::max(0, static_cast<int>(std::floor(std::min({x[0], x[1], x[2]}) - 0.5)));
    const int px1 =
        std::min(s.pw - 1, static_cast<int>(std::ceil(std::max({x[0], x[1], x[2]}) - 0.5)));
    const int py0 = std::max(0, static_cast<int>(std::floor(std::min({y[0], y[1], y[2]}) - 0.5)));
    const int py1 =
        std::min(s.ph - 1, static_cast<int>(std::ceil(std::max({y[0], y[1], y[2]}) - 0.5)));
    for (int py = py0; py <= py1; ++py) {
      const double cy = py + 0.5;
      for (int px = px0; px <= px1; ++px) {
        const double cx = px + 0.5;
        // Edge functions, signed by the triangle's winding: inside when all >= 0.
        const double e0 = ((x[2] - x[1]) * (cy - y[1]) - (y[2] - y[1]) * (cx - x[1])) / area;
        const double e1 = ((x[0] - x[2]) * (cy - y[2]) - (y[0] - y[2]) * (cx - x[2])) / area;
        const double e2 = 1.0 - e0 - e1;
        if (e0 < 0 || e1 < 0 || e2 < 0) continue;
        const double inv_z = e0 * iz[0] + e1 * iz[1] + e2 * iz[2];
        const std::size_t q = static_cast<std::size_t>(py) * s.pw + px;
        if (!(inv_z > depth[q])) continue;
        depth[q] = inv_z;
        id[q] = t;
        bary[2 * q] = e1 * iz[1] / inv_z;
        bary[2 * q + 1] = e2 * iz[2] / inv_z;
      }
    }
  }
  for (std::size_t q = 0; q < pixels; ++q) visit(q, id[q], bary[2 * q], bary[2 * q + 1]);
}

// Where the ray through pixel centre q meets triangle t: barycentrics (b1, b2 of corners 1 and 2)
// and distance, by Möller–Trumbore; false when it misses.
bool RayHit(const Scene& s, std::size_t q, int64_t t, double* b1, double* b2, double* dist) {
  const double cx = static_cast<double>(q % s.pw) + 0.5, cy = static_cast<double>(q / s.pw) + 0.5;
  const V3 dir = Unit(Add(s.forward, Add(Scale(s.right, (cx - 0.5 * s.pw) / s.focal),
                                         Scale(s.up, (0.5 * s.ph - cy) / s.focal))));
  std::size_t k[3];
  Corners(s, t, k);
  if (!Drawn(s, k)) return false;
  const V3 e1 = Sub(s.p[k[1]], s.p[k[0]]), e2 = Sub(s.p[k[2]], s.p[k[0]]);
  const V3 pv = Cross(dir, e2);
  const double det = Dot(e1, pv);
  if (det == 0) return false;
  const V3 tv = Sub(s.eye, s.p[k[0]]);
  const double u = Dot(tv, pv) / det;
  const V3 qv = Cross(tv, e1);
  const double v = Dot(dir, qv) / det;
  if (u < 0 || v < 0 || u + v > 1) return false;
  *b1 = u;
  *b2 = v;
  *dist = Dot(e2, qv) / det;
  return *dist > 0;
}

// The tint ramp at t in [0, 1]: lowland green, dry grass, earth, rock, snow.
void Tint(double t, double rgb[3]) {
  static const double kStops[5][4] = {{0.00, 0.30, 0.44, 0.24},
                                      {0.30, 0.56, 0.58, 0.36},
                                      {0.55, 0.55, 0.45, 0.33},
                                      {0.80, 0.58, 0.57, 0.55},
                                      {1.00, 0.96, 0.96, 0.97}};
  t = std::min(1.0, std::max(0.0, t));
  int k = 0;
  while (k < 3 && t > kStops[k + 1][0]) ++k;
  const double f = (t - kStops[k][0]) / (kStops[k + 1][0] - kStops[k][0]);
  for (int c = 0; c < 3; ++c)
    rgb[c] = kStops[k][c + 1] + f * (kStops[k + 1][c + 1] - kStops[k][c + 1]);
}

unsigned char Byte(double v) {
  return static_cast<unsigned char>(std::min(255.0, std::max(0.0, v * 255.0 + 0.5)));
}

}  // namespace

Result<Rgba8Image> RenderRelief(const ReliefGrid& grid, const ReliefView& view) {
  if (Status st = CheckInputs(grid, view); !st.ok()) return st;
  const Scene s = MakeScene(grid, view);
  bool any_cell = false;  // a triangle to draw: a cell with three drawn corners
  for (int64_t t = 0; t < 2 * static_cast<int64_t>(s.w - 1) * (s.h - 1) && !any_cell; ++t) {
    std::size_t k[3];
    Corners(s, t, k);
    any_cell = Drawn(s, k);
  }
  if (!any_cell) return Status::Error("view", "the frame holds no cell of the grid");
  // Per-sample colour: tint by height, lit by the sun (Lambert, with a sky's ambient) through the
  // normal from central differences (one-sided at the edges and beside holes).
  const V3 sun = Towards(view.sun_from_deg, view.sun_elevation_deg);
  std::vector<float> colour(3 * s.p.size(), 0.0f);
  const auto at = [&](int i, int j) -> const V3& {
    return s.p[static_cast<std::size_t>(j) * s.w + i];
  };
  for (int j = 0; j < s.h; ++j) {
    for (int i = 0; i < s.w; ++i) {
      const V3& c = at(i, j);
      if (!std::isfinite(c.y)) continue;
      const auto pick = [&](int ii, int jj) -> const V3& {
        return ii >= 0 && jj >= 0 && ii < s.w && jj < s.h && std::isfinite(at(ii, jj).y)
                   ? at(ii, jj)
                   : c;
      };
      const V3 ex = Sub(pick(i + 1, j), pick(i - 1, j)), ez = Sub(pick(i, j + 1), pick(i, j - 1));
      V3 n = Cross(ez, ex);  // z south × x east = up
      n = Dot(n, n) > 0 ? Unit(n) : V3{0, 1, 0};
      const double light = 0.38 + 0.62 * std::max(0.0, Dot(n, sun));
      double rgb[3];
      Tint((c.y / s.exaggeration - s.lo) / (s.hi - s.lo), rgb);
      const std::size_t k = static_cast<std::size_t>(j) * s.w + i;
      for (int ch = 0; ch < 3; ++ch) colour[3 * k + ch] = static_cast<float>(rgb[ch] * light);
    }
  }
  Rgba8Image out = MakeRgba8(view.width, view.height);
  Rasterise(s, [&](std::size_t q, int64_t t, double b1, double b2) {
    unsigned char* px = out.pixels.data() + 4 * q;
    const double fy = static_cast<double>(q / s.pw) / s.ph;
    if (t < 0) {  // sky: pale blue at the top to haze at the bottom
      px[0] = Byte(0.70 + 0.22 * fy);
      px[1] = Byte(0.80 + 0.14 * fy);
      px[2] = Byte(0.93 + 0.04 * fy);
      px[3] = 255;
      return;
    }
    // Gouraud: the colour at the pixel from the perspective-correct barycentrics.
    std::size_t k[3];
    Corners(s, t, k);
    const double b0 = 1.0 - b1 - b2;
    for (int ch = 0; ch < 3; ++ch) {
      px[ch] = Byte(b0 * colour[3 * k[0] + ch] + b1 * colour[3 * k[1] + ch] +
                    b2 * colour[3 * k[2] + ch]);
    }
    px[3] = 255;
  });
  return out;
}

std::vector<int64_t> RenderReliefIds(const ReliefGrid& grid, const ReliefView& view) {
  const Scene s = MakeScene(grid, view);
  std::vector<int64_t> ids(static_cast<std::size_t>(s.pw) * s.ph, -1);
  Rasterise(s, [&](std::size_t q, int64_t t, double, double) { ids[q] = t; });
  return ids;
}

std::vector<int64_t> CastReliefIds(const ReliefGrid& grid, const ReliefView& view) {
  std::vector<int64_t> ids;
  for (const ReliefHit& h : CastReliefHits(grid, view)) ids.push_back(h.triangle);
  return ids;
}

std::vector<ReliefHit> RenderReliefHits(const ReliefGrid& grid, const ReliefView& view) {
  const Scene s = MakeScene(grid, view);
  std::vector<ReliefHit> hits(static_cast<std::size_t>(s.pw) * s.ph);
  Rasterise(s, [&](std::size_t q, int64_t t, double b1, double b2) {
    if (t >= 0) hits[q] = {t, b1, b2};
  });
  return hits;
}

std::vector<ReliefHit> CastReliefHits(const ReliefGrid& grid, const ReliefView& view) {
  const Scene s = MakeScene(grid, view);
  std::vector<ReliefHit> hits(static_cast<std::size_t>(s.pw) * s.ph);
  const int64_t triangles = 2 * static_cast<int64_t>(s.w - 1) * (s.h - 1);
  for (std::size_t q = 0; q < hits.size(); ++q) {
    double best = INFINITY;
    for (int64_t t = 0; t < triangles; ++t) {
      double b1 = 0, b2 = 0, dist = 0;
      if (RayHit(s, q, t, &b1, &b2, &dist) && dist < best) {
        best = dist;
        hits[q] = {t, b1, b2};
      }
    }
  }
  return hits;
}

}  // namespace niwa::image
