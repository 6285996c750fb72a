// DEM reading and the real-against-grown measures (see compare.h).
#include "terrain/compare.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <nlohmann/json.hpp>

#include "image/png.h"
#include "math/det_math.h"
#include "params/json_guard.h"
#include "params/param_text.h"
#include "terrain/generate.h"

namespace niwa::terrain {
namespace {

// One cell test of the peak search, counted at its worst (every cell a candidate, the whole
// disc tested): 0.45 ns measured against that count (docs/budgets.md), about twice taken.
constexpr double kNsPerPeakTest = 1;

}  // namespace

Result<Heightfield> ReadHeightmap(const std::vector<unsigned char>& png, const std::string& sidecar,
                                  const std::string& field) {
  image::PngInfo info;
  Result<image::Gray16Image> img = image::DecodeGray16Png(png.data(), png.size(), &info);
  if (!img.ok()) return Status::Error(field, img.status().message());
  if (info.bit_depth != 16)
    return Status::Error(
        field, "a " + std::to_string(info.bit_depth) + "-bit PNG; must be 16-bit greyscale");
  NIWA_RETURN_IF_ERROR(CheckJsonKeys(sidecar, field));
  nlohmann::json j = nlohmann::json::parse(sidecar, nullptr, false);
  const auto num = [&j](const char* a, const char* b = nullptr) {
    const nlohmann::json* v = j.is_object() && j.contains(a) ? &j[a] : nullptr;
    if (v && b) v = v->is_object() && v->contains(b) ? &(*v)[b] : nullptr;
    return v && v->is_number() ? v->get<double>() : NAN;
  };
  const double lo = num("min_elevation"), hi = num("max_elevation"), cell = num("cell_size");
  const double x0 = num("origin", "x"), y1 = num("origin", "y");
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(cell > 0) || !std::isfinite(x0) ||
      !std::isfinite(y1) || hi < lo || num("width") != img->width || num("height") != img->height) {
    return Status::Error(field,
                         "sidecar JSON must hold width and height (the PNG's), "
                         "min_elevation <= max_elevation, cell_size > 0 and origin {x, y}");
  }
  Heightfield hf;
  hf.width = img->width;
  hf.height = img->height;
  hf.x0 = x0;
  hf.y1 = y1;
  hf.cell = cell;
  hf.h.resize(img->pixels.size());
  hf.band.assign(img->pixels.size(), 0);
  for (std::size_t k = 0; k < hf.h.size(); ++k) hf.h[k] = lo + img->pixels[k] / 65535.0 * (hi - lo);
  return hf;
}

SurfaceMeasures MeasureSurface(const Heightfield& s, const std::vector<char>& inside, double h0,
                               double dh, double d) {
  SurfaceMeasures m;
  m.slope_share.assign(kSlopeBins, 0.0);
  double top = h0, sum = 0;
  const auto in = [&](int i, int j) {
    return i >= 0 && j >= 0 && i < s.width && j < s.height &&
           inside[static_cast<std::size_t>(j) * s.width + i];
  };
  std::vector<double> slopes;
  for (int j = 0; j < s.height; ++j) {
    for (int i = 0; i < s.width; ++i) {
      if (!in(i, j)) continue;
      ++m.cells;
      top = std::max(top, s.At(i, j));
      sum += s.At(i, j);
      if (!in(i - 1, j) || !in(i + 1, j) || !in(i, j - 1) || !in(i, j + 1)) continue;
      const double gx = (s.At(i + 1, j) - s.At(i - 1, j)) / (2 * s.cell);
      const double gy = (s.At(i, j - 1) - s.At(i, j + 1)) / (2 * s.cell);
      slopes.push_back(det::Atan2(std::sqrt(gx * gx + gy * gy), 1.0) * 180.0 /
                       3.14159265358979323846);
    }
  }
  m.relief = top - h0;
  if (m.cells > 0 && top > h0) m.hypsometric_integral = (sum / m.cells - h0) / (top - h0);
  if (!slopes.empty()) {
    double total = 0;
    for (double a : slopes) {
      total += a;
      m.slope_share[static_cast<std::size_t>(std::min(kSlopeBins - 1, static_cast<int>(a / 5)))] +=
          1.0 / static_cast<double>(slopes.size());
    }
    m.mean_slope_deg = total / static_cast<double>(slopes.size());
    std::vector<double> sorted = slopes;
    std::sort(sorted.begin(), sorted.end());
    m.slope_p90_deg =
        sorted[static_cast<std::size_t>(0.9 * static_cast<double>(sorted.size() - 1))];
  }
  // 64-bit: a small cell under a large d gives r past 46,341, whose square overflows an int
  // (CheckCompareCost refuses such a search before it starts; the width bounds it here).
  const int64_t r = std::min<int64_t>(
      std::max<int64_t>(1, static_cast<int64_t>(std::llround(d / s.cell))),
      int64_t{1} + s.width + s.height);  // past w + h every cell is in the disc: the same result
  for (int j = 0; j < s.height; ++j) {
    for (int i = 0; i < s.width; ++i) {
      if (!in(i, j) || s.At(i, j) <= h0 + dh) continue;
      bool peak = true;
      for (int64_t dj = -r; dj <= r && peak; ++dj) {
        for (int64_t di = -r; di <= r && peak; ++di) {
          if ((di == 0 && dj == 0) || di * di + dj * dj > r * r ||
              !in(static_cast<int>(i + di), static_cast<int>(j + dj)))
            continue;
          const double o = s.At(static_cast<int>(i + di), static_cast<int>(j + dj));
          const bool earlier = dj < 0 || (dj == 0 && di < 0);
          if (o > s.At(i, j) || (o == s.At(i, j) && earlier)) peak = false;
        }
      }
      if (peak) ++m.peaks;
    }
  }
  return m;
}

double ComparePeakTests(const Heightfield& dem, double d) {
  const double side = 1.0 + dem.width + dem.height;
  const double r = std::min(side, std::max(1.0, std::round(d / dem.cell)));
  // Both surfaces (the DEM's and the grown one on its grid), every cell a candidate at worst.
  return 2.0 * static_cast<double>(dem.width) * static_cast<double>(dem.height) * (2 * r + 1) *
         (2 * r + 1);
}

Status CheckCompareCost(const Heightfield& dem, double d, const Budget& budget) {
  const double tests = ComparePeakTests(dem, d);
  const double seconds = kNsPerPeakTest * 1e-9 * tests;
  if (seconds <= budget.seconds) return Status::Ok();
  const double r = std::max(1.0, std::round(d / dem.cell));
  return Status::Error("dem",
                       "cells of " + FormatNumber(dem.cell) + " m under d = " + FormatNumber(d) +
                           " m make each peak test look " + FormatCount(r) + " cells around (" +
                           FormatCount(tests) + " cell tests, about " + FormatSeconds(seconds) +
                           "); must take at most " + FormatSeconds(budget.seconds) + " (" +
                           budget.seconds_limit + "); use coarser cells or a smaller d" +
                           RaiseHint(budget.seconds_limit));
}

Comparison CompareTerrain(const Heightfield& dem, const Terrain& grown) {
  Comparison c;
  if (grown.contours.empty()) return c;
  const Heightfield g = BuildHeightfieldOn(grown, dem);
  std::vector<char> inside(g.band.size());
  for (std::size_t k = 0; k < g.band.size(); ++k) inside[k] = g.band[k] >= 0;
  const double h0 = grown.contours[0].elevation;
  c.real = MeasureSurface(dem, inside, h0, grown.dh, grown.d);
  c.grown = MeasureSurface(g, inside, h0, grown.dh, grown.d);
  for (int b = 0; b < kSlopeBins; ++b)
    c.slope_share_l1 += std::fabs(c.real.slope_share[static_cast<std::size_t>(b)] -
                                  c.grown.slope_share[static_cast<std::size_t>(b)]);
  double iou_sum = 0;
  // The grown levels' own heights (h0 + k·Δh only when dh_ratio = 1), counted from the lowest
  // contour (a `down` level when there are any), and past the top by the same law.
  const int lowest = grown.contours[0].level;
  for (int up = 1;; ++up) {
    LevelOverlap o;
    o.level = lowest + up;
    o.elevation = LevelElevation(grown, o.level);
    int both = 0, either = 0;
    for (std::size_t k = 0; k < inside.size(); ++k) {
      if (!inside[k]) continue;
      const bool r = dem.h[k] >= o.elevation, q = g.h[k] >= o.elevation;
      o.real_cells += r;
      o.grown_cells += q;
      both += r && q;
      either += r || q;
    }
    if (either == 0) break;
    o.iou = static_cast<double>(both) / either;
    iou_sum += o.iou;
    c.levels.push_back(o);
  }
  if (!c.levels.empty()) c.mean_iou = iou_sum / static_cast<double>(c.levels.size());
  return c;
}

}  // namespace niwa::terrain
