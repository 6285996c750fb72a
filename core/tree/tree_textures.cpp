// Procedural bark, leaf and flower textures of the tree (integer hashes + det:: math).
#include "tree/tree_textures.h"

#include <algorithm>
#include <cmath>

#include "math/det_math.h"

namespace niwa {
namespace {

// Integer hash (lowbias32 finaliser) of a lattice point and a seed, uniform in [0, 1).
double Hash01(uint32_t x, uint32_t y, uint32_t seed) {
  uint32_t h = x * 0x8da6b343u ^ y * 0xd8163841u ^ seed * 0xcb1ab31fu;
  h ^= h >> 16;
  h *= 0x7feb352du;
  h ^= h >> 15;
  h *= 0x846ca68bu;
  h ^= h >> 16;
  return static_cast<double>(h) * (1.0 / 4294967296.0);
}

double Clamp01(double x) { return std::min(1.0, std::max(0.0, x)); }

double SmoothStep(double lo, double hi, double x) {
  double t = Clamp01((x - lo) / (hi - lo));
  return t * t * (3.0 - 2.0 * t);
}

double Mix(double a, double b, double t) { return a + (b - a) * t; }

// Value noise on a px × py lattice that wraps in both directions; (x, y) in lattice units.
double PeriodicNoise(double x, double y, int px, int py, uint32_t seed) {
  double fx = std::floor(x), fy = std::floor(y);
  double tx = x - fx, ty = y - fy;
  tx = tx * tx * (3.0 - 2.0 * tx);
  ty = ty * ty * (3.0 - 2.0 * ty);
  auto wrap = [](double i, int p) {
    int k = static_cast<int>(i) % p;
    return static_cast<uint32_t>(k < 0 ? k + p : k);
  };
  uint32_t x0 = wrap(fx, px), x1 = wrap(fx + 1.0, px), y0 = wrap(fy, py), y1 = wrap(fy + 1.0, py);
  double a = Mix(Hash01(x0, y0, seed), Hash01(x1, y0, seed), tx);
  double b = Mix(Hash01(x0, y1, seed), Hash01(x1, y1, seed), tx);
  return Mix(a, b, ty);
}

// Fractal sum of periodic noise over (u, v) in [0, 1)², tileable; result in [0, 1).
double PeriodicFbm(double u, double v, int px, int py, int octaves, uint32_t seed) {
  double sum = 0.0, weight = 1.0, total = 0.0;
  for (int o = 0; o < octaves; ++o) {
    sum += weight * PeriodicNoise(u * px, v * py, px, py, seed + static_cast<uint32_t>(o));
    total += weight;
    weight *= 0.5;
    px *= 2;
    py *= 2;
  }
  return sum / total;
}

unsigned char ToByte(double x) { return static_cast<unsigned char>(Clamp01(x) * 255.0 + 0.5); }

void SetPixel(Rgba8Image* image, int x, int y, double r, double g, double b, double a) {
  unsigned char* p = image->At(x, y);
  p[0] = ToByte(r);
  p[1] = ToByte(g);
  p[2] = ToByte(b);
  p[3] = ToByte(a);
}

Rgba8Image Allocate(int width, int height) { return image::MakeRgba8(width, height, 0, 0, 0, 0); }

}  // namespace

Rgba8Image MakeBarkTexture(int width, int height) {
  Rgba8Image image = Allocate(width, height);
  constexpr int kFurrows = 7;  // ridges around the circumference
  for (int y = 0; y < image.height; ++y) {
    double v = (y + 0.5) / image.height;
    for (int x = 0; x < image.width; ++x) {
      double u = (x + 0.5) / image.width;
      // Furrows wander a little sideways along the wood.
      double warp = PeriodicFbm(u, v, 4, 6, 3, 11u) - 0.5;
      double phase = (u + 0.12 * warp) * kFurrows;
      double f = phase - std::floor(phase);
      double plate = SmoothStep(0.04, 0.32, std::min(f, 1.0 - f));  // 0 in a furrow, 1 on a ridge
      // Ridges broken into elongated plates, with some grain.
      double detail = PeriodicFbm(u, v, 16, 8, 3, 23u);
      double crack = SmoothStep(0.30, 0.22, PeriodicFbm(u, v, 8, 12, 2, 37u));
      double grain = Hash01(static_cast<uint32_t>(x), static_cast<uint32_t>(y), 41u) - 0.5;
      double shade = plate * (0.72 + 0.45 * detail) * (1.0 - 0.45 * crack) + 0.08 * grain;
      shade = Clamp01(shade);
      double r = Mix(0.16, 0.47, shade), g = Mix(0.11, 0.35, shade), b = Mix(0.08, 0.25, shade);
      SetPixel(&image, x, y, r, g, b, 1.0);
    }
  }
  return image;
}

Rgba8Image MakeLeafTexture(int width, int height) {
  Rgba8Image image = Allocate(width, height);
  constexpr double kStem = 0.06;  // petiole, v < kStem
  for (int y = 0; y < image.height; ++y) {
    double v = (y + 0.5) / image.height;
    double half_width;  // of the silhouette, in u
    if (v < kStem) {
      half_width = 0.02;
    } else {
      double t = (v - kStem) / (1.0 - kStem);
      half_width =
          std::max(0.02 * (1.0 - t / 0.05), 0.0) + 0.5 * det::Sin(det::kPi * t) * (1.1 - 0.45 * t);
      half_width = std::min(half_width, 0.47);
    }
    for (int x = 0; x < image.width; ++x) {
      double u = (x + 0.5) / image.width;
      double d = std::fabs(u - 0.5);
      double alpha = Clamp01((half_width - d) * image.width + 0.5);
      // Physical coordinates: the quad is twice as long as it is wide.
      double across = d * 0.5;
      double vein_phase = (v - 1.2 * across) * 9.0;
      double g = vein_phase - std::floor(vein_phase);
      double vein = 1.0 - SmoothStep(0.0, 0.07, std::min(g, 1.0 - g));
      vein *= SmoothStep(0.0, 0.03, d) * SmoothStep(0.1, 0.2, v);
      double midrib = 1.0 - SmoothStep(0.008, 0.02, d);
      double edge = half_width > 0.0 ? Clamp01(d / half_width) : 1.0;
      double mottle = PeriodicFbm(u, v, 6, 6, 2, 53u) - 0.5;
      double shade = (0.88 + 0.12 * v) * (1.0 - 0.18 * edge * edge) + 0.12 * mottle;
      double r = 0.22 * shade, gr = 0.52 * shade, b = 0.15 * shade;
      double light = std::max(midrib, 0.35 * vein);
      r = Mix(r, 0.55, light);
      gr = Mix(gr, 0.72, light);
      b = Mix(b, 0.30, light);
      SetPixel(&image, x, y, r, gr, b, alpha);
    }
  }
  return image;
}

Rgba8Image MakeFlowerTexture(int size) {
  Rgba8Image image = Allocate(size, size);
  constexpr int kPetals = 5;
  for (int y = 0; y < image.height; ++y) {
    double dy = (y + 0.5) / image.height - 0.5;
    for (int x = 0; x < image.width; ++x) {
      double dx = (x + 0.5) / image.width - 0.5;
      double r = std::sqrt(dx * dx + dy * dy);
      double angle = det::Atan2(dy, dx);
      double c = det::Cos(kPetals * angle);  // 1 at the petal tips
      double radius = 0.5 * (0.5 + 0.44 * SmoothStep(-1.0, 1.0, c));
      radius -= 0.07 * SmoothStep(0.985, 1.0, c);  // cherry-blossom notch at the tip
      double alpha = Clamp01((radius - r) * image.width + 0.5);
      double centre = 1.0 - SmoothStep(0.04, 0.2, r);
      double red = Mix(0.99, 0.90, centre), green = Mix(0.80, 0.45, centre),
             blue = Mix(0.86, 0.60, centre);
      double stamen = 1.0 - SmoothStep(0.03, 0.05, r);
      red = Mix(red, 0.95, stamen);
      green = Mix(green, 0.80, stamen);
      blue = Mix(blue, 0.35, stamen);
      SetPixel(&image, x, y, red, green, blue, alpha);
    }
  }
  return image;
}

}  // namespace niwa
