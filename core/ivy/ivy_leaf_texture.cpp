// The ivy leaf's texture for the .glb (ivy_leaf_texture.h).
#include "ivy/ivy_leaf_texture.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "image/png.h"

namespace niwa::ivy {
namespace {

struct Segment {
  double ax, ay, bx, by, width;  // a vein from a to b, half-width in leaf units
};

// Midrib, the two lobes' main veins, the basal veins and side veins off the midrib.
const Segment kVeins[] = {{0.0, 0.0, 0.0, 0.98, 0.012},    {0.0, 0.02, 0.47, 0.45, 0.010},
                          {0.0, 0.02, -0.47, 0.45, 0.010}, {0.0, 0.01, 0.33, 0.15, 0.007},
                          {0.0, 0.01, -0.33, 0.15, 0.007}, {0.0, 0.35, 0.22, 0.55, 0.006},
                          {0.0, 0.35, -0.22, 0.55, 0.006}, {0.0, 0.55, 0.17, 0.78, 0.006},
                          {0.0, 0.55, -0.17, 0.78, 0.006}, {0.0, 0.72, 0.11, 0.88, 0.005},
                          {0.0, 0.72, -0.11, 0.88, 0.005}, {0.2, 0.24, 0.38, 0.32, 0.005},
                          {-0.2, 0.24, -0.38, 0.32, 0.005}};

double SegmentDistance(double px, double py, const Segment& s) {
  const double dx = s.bx - s.ax, dy = s.by - s.ay;
  const double len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((px - s.ax) * dx + (py - s.ay) * dy) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  const double ex = s.ax + t * dx - px, ey = s.ay + t * dy - py;
  return std::sqrt(ex * ex + ey * ey);
}

// 0 outside, 1 inside the outline (even-odd), and the distance to the outline's edge.
bool InsideOutline(double x, double y, double* edge) {
  const auto& o = LeafOutlineUnit();
  bool inside = false;
  *edge = 1e9;
  for (std::size_t i = 0, j = o.size() - 1; i < o.size(); j = i++) {
    const double xi = o[i].first, yi = o[i].second, xj = o[j].first, yj = o[j].second;
    if ((yi > y) != (yj > y) && x < (xj - xi) * (y - yi) / (yj - yi) + xi) inside = !inside;
    *edge = std::min(*edge, SegmentDistance(x, y, {xj, yj, xi, yi, 0}));
  }
  return inside;
}

unsigned char Byte(double v) { return static_cast<unsigned char>(std::clamp(v, 0.0, 255.0) + 0.5); }

}  // namespace

const std::vector<std::pair<double, double>>& LeafOutlineUnit() {
  static const std::vector<std::pair<double, double>> outline = {
      {0.0, 0.0}, {0.35, 0.15}, {0.5, 0.45}, {0.3, 0.5},   {0.2, 0.85},
      {0.0, 1.0}, {-0.2, 0.85}, {-0.3, 0.5}, {-0.5, 0.45}, {-0.35, 0.15}};
  return outline;
}

image::Rgba8Image PaintLeafTexture(int size) {
  size = std::clamp(size, 16, 2048);
  image::Rgba8Image img = image::MakeRgba8(size, size);
  for (int py = 0; py < size; ++py) {
    for (int px = 0; px < size; ++px) {
      // The pixel centre in leaf units (LeafUv inverted).
      const double x = (px + 0.5) / size - 0.5, y = 1.0 - (py + 0.5) / size;
      double edge = 0;
      const bool inside = InsideOutline(x, y, &edge);
      // Blade: deep green at the tips, lighter toward the petiole; darker along the rim.
      const double t = std::clamp(y, 0.0, 1.0);
      double r = 74 - 30 * t, g = 128 - 28 * t, b = 44 - 14 * t;
      const double rim = std::clamp(1.0 - edge / 0.03, 0.0, 1.0);
      r -= 14 * rim, g -= 22 * rim, b -= 8 * rim;
      double vein = 0;
      for (const Segment& s : kVeins) {
        const double d = SegmentDistance(x, y, s);
        vein = std::max(vein, std::clamp(1.0 - d / s.width, 0.0, 1.0));
      }
      r += (150 - r) * 0.55 * vein, g += (178 - g) * 0.55 * vein, b += (92 - b) * 0.55 * vein;
      unsigned char* p = img.At(px, py);
      p[0] = Byte(r);
      p[1] = Byte(g);
      p[2] = Byte(b);
      p[3] = inside ? 255 : 0;  // outside keeps the blade's colour: no dark fringe when filtered
    }
  }
  return img;
}

const Result<std::vector<unsigned char>>& LeafTexturePng() {
  static const Result<std::vector<unsigned char>> png =
      image::EncodeRgba8Png(PaintLeafTexture(kLeafTextureSize));
  return png;
}

}  // namespace niwa::ivy
