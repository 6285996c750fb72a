// Procedural bark (colour + normal map), leaf blades per shape and season, and blossom textures of
// the tree (integer hashes + det:: math, so both builds paint the same bytes).
#include "tree/tree_textures.h"

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <vector>

#include "math/det_math.h"

namespace niwa {
namespace {

constexpr double kDegree = det::kPi / 180.0;

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

struct Rgb {
  double r, g, b;
};

Rgb MixRgb(const Rgb& a, const Rgb& b, double t) {
  return {Mix(a.r, b.r, t), Mix(a.g, b.g, t), Mix(a.b, b.b, t)};
}
Rgb Scale(const Rgb& c, double s) { return {c.r * s, c.g * s, c.b * s}; }

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

void SetPixel(Rgba8Image* image, int x, int y, const Rgb& c, double a) {
  unsigned char* p = image->At(x, y);
  p[0] = ToByte(c.r);
  p[1] = ToByte(c.g);
  p[2] = ToByte(c.b);
  p[3] = ToByte(a);
}

Rgba8Image Allocate(int width, int height) { return image::MakeRgba8(width, height, 0, 0, 0, 0); }

// ---- Bark ----

// Relief of the bark at (u, v): 0 in a furrow or crack, about 1 on a plate; tileable.
double BarkRelief(double u, double v) {
  constexpr int kFurrows = 7;                           // ridges around the circumference
  double warp = PeriodicFbm(u, v, 4, 6, 3, 11u) - 0.5;  // furrows wander along the wood
  double phase = (u + 0.12 * warp) * kFurrows;
  double f = phase - std::floor(phase);
  double plate = SmoothStep(0.04, 0.32, std::min(f, 1.0 - f));
  double detail = PeriodicFbm(u, v, 16, 8, 3, 23u);  // ridges broken into elongated plates
  double crack = SmoothStep(0.30, 0.22, PeriodicFbm(u, v, 8, 12, 2, 37u));
  return plate * (0.72 + 0.45 * detail) * (1.0 - 0.45 * crack);
}

// Relief of every pixel of a width × height bark image.
std::vector<double> BarkReliefImage(int width, int height) {
  std::vector<double> relief(static_cast<std::size_t>(std::max(0, width) * std::max(0, height)));
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      relief[static_cast<std::size_t>(y * width + x)] =
          BarkRelief((x + 0.5) / width, (y + 0.5) / height);
    }
  }
  return relief;
}

// ---- Leaves ----

// One sample of a blade: inside the silhouette, and how much of a vein / midrib is there.
struct BladeSample {
  bool inside = false;
  double vein = 0.0;  // 0..1, lighter
  double edge = 0.0;  // 0 at the midrib or centre, 1 at the margin (darker)
};

// Elliptic blade (u-space as the quad is half as wide as long), midrib and pinnate veins.
BladeSample BroadBlade(double u, double v) {
  BladeSample s;
  constexpr double kStem = 0.06;  // petiole, v < kStem
  double half_width;              // of the silhouette, in u
  if (v < kStem) {
    half_width = 0.02;
  } else {
    double t = (v - kStem) / (1.0 - kStem);
    half_width =
        std::max(0.02 * (1.0 - t / 0.05), 0.0) + 0.5 * det::Sin(det::kPi * t) * (1.1 - 0.45 * t);
    half_width = std::min(half_width, 0.47);
  }
  double d = std::fabs(u - 0.5);
  s.inside = d < half_width;
  double across = d * 0.5;  // physical: the quad is twice as long as it is wide
  double vein_phase = (v - 1.2 * across) * 9.0;
  double g = vein_phase - std::floor(vein_phase);
  double vein = (1.0 - SmoothStep(0.0, 0.07, std::min(g, 1.0 - g))) * SmoothStep(0.0, 0.03, d) *
                SmoothStep(0.1, 0.2, v);
  double midrib = 1.0 - SmoothStep(0.008, 0.02, d);
  s.vein = std::max(midrib, 0.35 * vein);
  s.edge = half_width > 0.0 ? Clamp01(d / half_width) : 1.0;
  return s;
}

// A pine fascicle: fourteen needles fanning ±22° from a short sheath at the base; x, y physical
// (x across in [-0.4, 0.4], y along in [0, 1]).
BladeSample NeedleCluster(double x, double y) {
  BladeSample s;
  constexpr int kNeedles = 14;
  constexpr double kOriginY = 0.08;
  if (std::fabs(x) < 0.014 && y > 0.02 && y < 0.10) {  // the sheath
    s.inside = true;
    s.edge = 1.0;
    return s;
  }
  for (int k = 0; k < kNeedles; ++k) {
    const uint32_t key = static_cast<uint32_t>(k);
    double angle =
        (-22.0 + 44.0 * k / (kNeedles - 1) + 3.0 * (Hash01(key, 1u, 71u) - 0.5)) * kDegree;
    double length = 0.80 + 0.12 * Hash01(key, 2u, 71u);
    double dx = det::Sin(angle), dy = det::Cos(angle);
    double px = x, py = y - kOriginY;
    double t = (px * dx + py * dy) / length;  // 0 at the sheath, 1 at the needle's tip
    if (t < 0.0 || t > 1.0) continue;
    double perp = std::fabs(px * dy - py * dx);
    double half = 0.011 * (1.0 - 0.75 * t);
    if (perp < half) {
      s.inside = true;
      s.vein = 0.45 * (1.0 - perp / half) * (1.0 - t);
      s.edge = std::max(s.edge, perp / half);
      return s;
    }
  }
  return s;
}

// Acer palmatum: seven pointed lobes from the blade's centre (0, 0.40), deep sinuses, finely
// toothed margin, a vein along every lobe, a petiole below; x in [-0.5, 0.5].
BladeSample PalmateBlade(double x, double y) {
  BladeSample s;
  constexpr double kCentreY = 0.40;
  if (std::fabs(x) < 0.012 && y >= 0.0 && y < kCentreY) {  // petiole
    s.inside = true;
    s.vein = 0.3;
    return s;
  }
  static const double kLobeLength[4] = {0.57, 0.52, 0.40, 0.26};  // centre lobe, then outwards
  constexpr double kLobeStep = 36.0 * kDegree, kLobeHalfWidth = 21.0 * kDegree;
  double dx = x, dy = y - kCentreY;
  double r = std::sqrt(dx * dx + dy * dy);
  double theta = det::Atan2(dx, dy);  // 0 straight up, ± to the sides
  double reach = 0.10;
  double vein = 0.0;
  for (int k = -3; k <= 3; ++k) {
    double lobe = kLobeLength[std::abs(k)];
    double off = std::fabs(theta - k * kLobeStep);
    reach = std::max(reach, 0.10 + lobe * std::max(0.0, 1.0 - off / kLobeHalfWidth));
    if (off < 0.5 * det::kPi && r < lobe) {
      double perp = r * det::Sin(off);
      vein = std::max(vein, 1.0 - SmoothStep(0.003, 0.009, perp));
    }
  }
  reach *= 1.0 + 0.03 * det::Sin(theta * 80.0);  // teeth
  s.inside = r < reach;
  s.vein = 0.6 * vein;
  s.edge = Clamp01(r / reach);
  return s;
}

// Ginkgo: a fan spanning ±66° above the petiole's top (0, 0.30), notched in the middle, wavy at
// the rim, with fine radial veins; x in [-0.6, 0.6].
BladeSample FanBlade(double x, double y) {
  BladeSample s;
  constexpr double kCentreY = 0.30;
  if (std::fabs(x) < 0.012 && y >= 0.0 && y < kCentreY + 0.02) {  // petiole
    s.inside = true;
    s.vein = 0.3;
    return s;
  }
  double dx = x, dy = y - kCentreY;
  double r = std::sqrt(dx * dx + dy * dy);
  double theta = det::Atan2(dx, dy);
  double off = std::fabs(theta);
  if (off > 66.0 * kDegree) return s;
  double reach = 0.64 * (1.0 - 0.22 * std::max(0.0, 1.0 - off / (7.0 * kDegree)));  // the notch
  reach *= 1.0 + 0.025 * det::Sin(theta * 24.0);                                    // wavy rim
  s.inside = r < reach;
  double phase = theta / (3.0 * kDegree);
  double g = phase - std::floor(phase);
  s.vein = 0.25 * (1.0 - SmoothStep(0.0, 0.18, std::min(g, 1.0 - g))) * SmoothStep(0.05, 0.15, r);
  s.edge = Clamp01(r / reach);
  return s;
}

BladeSample SampleBlade(LeafShape shape, double u, double v) {
  const double x = (u - 0.5) * LeafQuadAspect(shape);  // physical, in leaf lengths
  switch (shape) {
    case LeafShape::kNeedle:
      return NeedleCluster(x, v);
    case LeafShape::kPalmate:
      return PalmateBlade(x, v);
    case LeafShape::kFan:
      return FanBlade(x, v);
    case LeafShape::kBroad:
    default:
      return BroadBlade(u, v);
  }
}

// The blade's colour in this look (tree_look.h).
Rgb LeafColour(const TreeLook& look) {
  const bool evergreen = look.autumn == AutumnColour::kEvergreen;
  const bool needle = look.leaf_shape == LeafShape::kNeedle;
  if (look.season == Season::kSpring) {
    return needle ? Rgb{0.22, 0.46, 0.18} : Rgb{0.38, 0.66, 0.18};
  }
  if (look.season == Season::kSummer) return needle ? Rgb{0.15, 0.36, 0.16} : Rgb{0.22, 0.52, 0.15};
  if (evergreen) return needle ? Rgb{0.13, 0.31, 0.15} : Rgb{0.15, 0.34, 0.12};
  if (look.season == Season::kWinter) return {0.45, 0.32, 0.18};  // dead leaf (not drawn)
  switch (look.autumn) {
    case AutumnColour::kRed:
      return {0.80, 0.09, 0.06};
    case AutumnColour::kYellow:
      return {0.95, 0.80, 0.12};
    case AutumnColour::kOrangeBrown:
      return {0.68, 0.36, 0.12};
    case AutumnColour::kRedOrange:
    default:
      return {0.86, 0.34, 0.10};
  }
}

// ---- Leaf sprays (leaf_spray > 1) ----

// One blade on a spray card: its base (x across, y along the twig, in leaf lengths), its direction
// (radians from the twig, positive towards +x), its length over the species' leaf length, a shade
// factor, and the box its silhouette covers on the card.
struct SprayLeaf {
  double x = 0, y = 0, angle = 0, scale = 1, shade = 1;
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
};

struct Spray {
  std::vector<SprayLeaf> leaves;  // painted in this order, each over the ones before
  double twig = 0.0;              // the twig's length from the base (0, 0)
  double width = 0.0, length = 0.0;
};

// Where (x, y) falls on a blade of the spray: the blade's own sample (physical leaf-local
// coordinates turned into the single leaf's (u, v)); outside when off the blade's quad.
BladeSample SampleSprayLeaf(LeafShape shape, double aspect, const SprayLeaf& leaf, double x,
                            double y, double* v_out) {
  const double dx = x - leaf.x, dy = y - leaf.y;
  const double s = det::Sin(leaf.angle), c = det::Cos(leaf.angle);
  const double along = (dx * s + dy * c) / leaf.scale, across = (dx * c - dy * s) / leaf.scale;
  const double u = across / aspect + 0.5;
  *v_out = along;
  if (along < 0.0 || along > 1.0 || u < 0.0 || u > 1.0) return {};
  return SampleBlade(shape, u, along);
}

// The spray's layout for `count` leaves of `shape` (count >= 2). Fixed hashes: the same card for
// every tree of a look.
Spray LayoutSpray(LeafShape shape, int count) {
  Spray spray;
  const int laterals = count - 1;
  auto jitter = [](int k, uint32_t salt) {
    return Hash01(static_cast<uint32_t>(k), salt, 131u) - 0.5;
  };
  auto add = [&](int k, double x, double y, double angle_deg) {
    SprayLeaf leaf;
    leaf.x = x;
    leaf.y = y;
    leaf.angle = (angle_deg + 6.0 * jitter(k, 1u)) * kDegree;
    leaf.scale = 0.88 + 0.12 * (jitter(k, 2u) + 0.5);
    leaf.shade = 0.90 + 0.16 * (jitter(k, 3u) + 0.5);
    spray.leaves.push_back(leaf);
  };
  switch (shape) {
    case LeafShape::kPalmate: {
      // Acer: opposite pairs on long petioles (the blade's own), then a terminal leaf.
      constexpr double kSpacing = 0.55;
      for (int k = 0; k < laterals; ++k) {
        const double side = (k % 2 == 0) ? -1.0 : 1.0;
        add(k, 0.0, 0.05 + kSpacing * (k / 2), side * (64.0 - 8.0 * (k / 2)));
      }
      spray.twig = 0.05 + kSpacing * ((laterals - 1) / 2) + 0.30;
      add(laterals, 0.0, spray.twig, 0.0);
      break;
    }
    case LeafShape::kNeedle: {
      // Pine: fascicles around the shoot's tip, pointing forward, and one at the tip.
      constexpr double kSpacing = 0.14;
      for (int k = 0; k < laterals; ++k) {
        const double side = (k % 2 == 0) ? -1.0 : 1.0;
        add(k, 0.0, 0.04 + kSpacing * k, side * (34.0 - 10.0 * k / std::max(1, laterals - 1)));
      }
      spray.twig = 0.04 + kSpacing * std::max(0, laterals - 1) + 0.10;
      add(laterals, 0.0, spray.twig, 0.0);
      break;
    }
    case LeafShape::kFan:
    case LeafShape::kBroad:
    default: {
      // Alternate leaves along a twig (a ginkgo's long shoot too, its fans farther apart),
      // spreading about 55° and less towards the tip, and a terminal leaf.
      const bool fan = shape == LeafShape::kFan;
      const double spacing = fan ? 0.55 : 0.31, spread = fan ? 58.0 : 54.0;
      for (int k = 0; k < laterals; ++k) {
        const double side = (k % 2 == 0) ? -1.0 : 1.0;
        add(k, 0.0, 0.06 + spacing * k, side * (spread - 10.0 * k / std::max(1, laterals - 1)));
      }
      spray.twig = 0.06 + spacing * std::max(0, laterals - 1) + 0.22;
      add(laterals, 0.0, spray.twig, 0.0);
      break;
    }
  }
  // Each blade's box, from its silhouette sampled on a 48 × 48 grid over its quad; then the card:
  // symmetric about the twig, from the base (everything moved up when a blade dips below it).
  const double aspect = LeafQuadAspect(shape);
  constexpr int kGrid = 48;
  double lowest = 0.0;
  for (SprayLeaf& leaf : spray.leaves) {
    const double s = det::Sin(leaf.angle), c = det::Cos(leaf.angle);
    leaf.x0 = leaf.x1 = leaf.x;  // the base (a petiole or sheath thinner than the grid) is in
    leaf.y0 = leaf.y1 = leaf.y;
    for (int i = 0; i < kGrid; ++i) {
      for (int j = 0; j < kGrid; ++j) {
        const double u = (i + 0.5) / kGrid, v = (j + 0.5) / kGrid;
        if (!SampleBlade(shape, u, v).inside) continue;
        const double across = (u - 0.5) * aspect * leaf.scale, along = v * leaf.scale;
        const double x = leaf.x + across * c + along * s, y = leaf.y - across * s + along * c;
        leaf.x0 = std::min(leaf.x0, x);
        leaf.x1 = std::max(leaf.x1, x);
        leaf.y0 = std::min(leaf.y0, y);
        leaf.y1 = std::max(leaf.y1, y);
      }
    }
    // A grid cell's reach around each sample, so nothing of the silhouette falls off the box.
    const double pad = 1.5 * std::max(1.0, aspect) * leaf.scale / kGrid;
    leaf.x0 -= pad;
    leaf.x1 += pad;
    leaf.y0 -= pad;
    leaf.y1 += pad;
    lowest = std::min(lowest, leaf.y0);
  }
  double half = 0.0, top = spray.twig;
  for (SprayLeaf& leaf : spray.leaves) {
    leaf.y -= lowest;
    leaf.y0 -= lowest;
    leaf.y1 -= lowest;
    half = std::max(half, std::max(std::fabs(leaf.x0), std::fabs(leaf.x1)));
    top = std::max(top, leaf.y1);
  }
  spray.twig -= lowest;
  spray.width = 2.0 * half;
  spray.length = top;
  return spray;
}

// What covers the card point (x, y) of a spray (leaf lengths): the topmost blade (its index, its
// sample and its v), or the twig (index -1, inside), or nothing.
struct SprayHit {
  int leaf = -1;
  BladeSample sample;
  double v = 0.0;
};

SprayHit HitSpray(const Spray& spray, LeafShape shape, double aspect, double x, double y) {
  SprayHit hit;
  for (int k = static_cast<int>(spray.leaves.size()); k-- > 0;) {
    const SprayLeaf& leaf = spray.leaves[static_cast<std::size_t>(k)];
    if (x < leaf.x0 || x > leaf.x1 || y < leaf.y0 || y > leaf.y1) continue;
    double v = 0.0;
    BladeSample s = SampleSprayLeaf(shape, aspect, leaf, x, y, &v);
    if (s.inside) {
      hit.leaf = k;
      hit.sample = s;
      hit.v = v;
      return hit;
    }
  }
  // The twig: tapering from 0.024 to 0.012 leaf lengths across, from the base to its end.
  if (y >= 0.0 && y <= spray.twig) {
    const double t = spray.twig > 0.0 ? y / spray.twig : 1.0;
    if (std::fabs(x) < 0.012 - 0.006 * t) hit.sample.inside = true;
  }
  return hit;
}

// The spray card's texture (MakeLeafTexture with leaf_spray > 1): each blade coloured as the single
// leaf's (its own v for the light tip and mottle), shaded by its own factor, over a brown twig.
Rgba8Image MakeSprayTexture(const TreeLook& look, const Rgb& base, const Rgb& light,
                            Rgba8Image image) {
  const Spray spray = LayoutSpray(look.leaf_shape, std::min(look.leaf_spray, kMaxLeafSpray));
  const double aspect = LeafQuadAspect(look.leaf_shape);
  const Rgb twig{0.34, 0.24, 0.15};
  auto card_x = [&](double px) { return (px / image.width - 0.5) * spray.width; };
  auto card_y = [&](double py) { return py / image.height * spray.length; };
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      int covered = 0;
      for (int k = 0; k < 4; ++k) {
        const double cx = card_x(x + 0.25 + 0.5 * (k & 1)), cy = card_y(y + 0.25 + 0.5 * (k >> 1));
        covered += HitSpray(spray, look.leaf_shape, aspect, cx, cy).sample.inside ? 1 : 0;
      }
      if (covered == 0) {  // the blade's colour under alpha 0, so filtering fringes stay green
        SetPixel(&image, x, y, Scale(base, 0.85), 0.0);
        continue;
      }
      const double cx = card_x(x + 0.5), cy = card_y(y + 0.5);
      SprayHit hit = HitSpray(spray, look.leaf_shape, aspect, cx, cy);
      Rgb colour = twig;
      if (hit.leaf >= 0) {
        const SprayLeaf& leaf = spray.leaves[static_cast<std::size_t>(hit.leaf)];
        const BladeSample& s = hit.sample;
        const double v = hit.v;
        const double mottle = PeriodicFbm(cx / spray.width + 0.5, cy / spray.length, 6, 6, 2, 53u);
        double shade = (0.88 + 0.12 * v) * (1.0 - 0.18 * s.edge * s.edge) + 0.12 * (mottle - 0.5);
        colour = MixRgb(Scale(base, shade * leaf.shade), light, Clamp01(s.vein));
      } else if (!hit.sample.inside) {
        // The centre is off every blade (an edge pixel): the nearest sample's colour would do; the
        // blade colour keeps the edge from darkening.
        colour = base;
      }
      SetPixel(&image, x, y, colour, covered / 4.0);
    }
  }
  return image;
}

// ---- Blossoms ----

// The petals' colours of a flower_colour (tree_look.h): petal, the centre or throat (and an
// azalea's blotch), the stamens' filaments, the anthers.
struct Palette {
  Rgb petal, centre, stamen, anther;
};

Palette FlowerPalette(FlowerColour colour) {
  switch (colour) {
    case FlowerColour::kDeepPink:
      return {{0.97, 0.60, 0.74}, {0.82, 0.28, 0.47}, {0.95, 0.80, 0.40}, {0.85, 0.62, 0.25}};
    case FlowerColour::kMagenta:
      return {{0.86, 0.20, 0.58}, {0.58, 0.05, 0.34}, {0.93, 0.52, 0.76}, {0.36, 0.14, 0.22}};
    case FlowerColour::kRed:
      return {{0.88, 0.12, 0.16}, {0.56, 0.03, 0.07}, {0.95, 0.42, 0.42}, {0.35, 0.12, 0.10}};
    case FlowerColour::kWhite:
      return {{0.97, 0.96, 0.94}, {0.78, 0.85, 0.60}, {0.95, 0.86, 0.42}, {0.80, 0.62, 0.22}};
    case FlowerColour::kPalePink:
    default:
      return {{0.99, 0.83, 0.88}, {0.90, 0.45, 0.60}, {0.95, 0.80, 0.35}, {0.95, 0.80, 0.35}};
  }
}

const Palette kCherryPalette = FlowerPalette(FlowerColour::kPalePink);

// A five-petal blossom of radius 1 centred at the origin, one petal pointing along `rotation`:
// coverage (0..1, antialiased over `pixel` units) and colour at (dx, dy).
double Blossom(double dx, double dy, double rotation, double pixel, const Palette& palette,
               Rgb* colour) {
  constexpr int kPetals = 5;
  double r = std::sqrt(dx * dx + dy * dy);
  if (r > 1.0 + pixel) return 0.0;
  double angle = det::Atan2(dy, dx) - rotation;
  double c = det::Cos(kPetals * angle);  // 1 at the petal tips
  // Broad, rounded petals (a flattened cosine lobe) with the cherry blossom's notch at the tip.
  double radius = 0.52 + 0.44 * std::sqrt(std::sqrt(0.5 + 0.5 * c));
  radius -= 0.09 * SmoothStep(0.992, 1.0, c);
  double coverage = Clamp01((radius - r) / pixel + 0.5);
  if (coverage <= 0.0) return 0.0;
  double centre = 0.6 * (1.0 - SmoothStep(0.06, 0.32, r));
  double rim = SmoothStep(radius - 0.08, radius, r);  // a faint darker outline between blossoms
  Rgb petal = Scale(MixRgb(palette.petal, palette.centre, centre), 1.0 - 0.12 * rim);
  double stamen = 1.0 - SmoothStep(0.06, 0.10, r);
  *colour = MixRgb(petal, palette.stamen, stamen);
  return coverage;
}

// Coverage of a segment from the origin along the unit direction (ux, uy), `length` long and
// `half` wide, at (dx, dy), antialiased over `pixel`.
double Stroke(double dx, double dy, double ux, double uy, double length, double half,
              double pixel) {
  double t = dx * ux + dy * uy;
  if (t < 0.0 || t > length) return 0.0;
  double perp = std::fabs(dx * uy - dy * ux);
  return Clamp01((half - perp) / pixel + 0.5);
}

// A Rhododendron (azalea) flower seen face-on, radius 1 at the lobe tips, its upper lobe along
// `rotation`: a funnel-shaped corolla of five fused, rounded lobes (shallow sinuses, no notch),
// shaded darker into the throat, a blotch of darker spots on the upper lobe, and five long
// stamens with the style curving out of the throat on the lower side (declinate), each ending in
// a dark anther. Coverage and colour at (dx, dy), as Blossom.
double AzaleaFlower(double dx, double dy, double rotation, double pixel, const Palette& palette,
                    Rgb* colour) {
  constexpr int kLobes = 5;
  const double r = std::sqrt(dx * dx + dy * dy);
  const double angle = det::Atan2(dy, dx) - rotation;  // 0 at the upper lobe's midline
  const double c = det::Cos(kLobes * angle);
  // Stamens and style: six strokes from the throat towards the lower side, fanned ±20°.
  double filament = 0.0, anther = 0.0;
  for (int k = 0; k < 6; ++k) {
    const double a = rotation + det::kPi + (-20.0 + 8.0 * k) * kDegree;
    const double ux = det::Cos(a), uy = det::Sin(a);
    const double length = (k == 3 ? 1.02 : 0.86 + 0.03 * (k % 3));  // the style the longest
    filament = std::max(filament, Stroke(dx, dy, ux, uy, length, 0.013, pixel));
    const double ex = dx - ux * length, ey = dy - uy * length;
    anther = std::max(anther, Clamp01((0.045 - std::sqrt(ex * ex + ey * ey)) / pixel + 0.5));
  }
  double radius = 0.70 + 0.28 * std::sqrt(0.5 + 0.5 * c);  // fused lobes: shallow sinuses
  double corolla = r > 1.0 + pixel ? 0.0 : Clamp01((radius - r) / pixel + 0.5);
  double coverage = std::max(corolla, std::max(filament, anther));
  if (coverage <= 0.0) return 0.0;
  // The funnel: darker and more saturated towards the throat; a faint rim between lobes.
  double throat = 0.75 * (1.0 - SmoothStep(0.05, 0.45, r));
  double rim = SmoothStep(radius - 0.06, radius, r);
  double vein = 0.06 * (0.5 + 0.5 * det::Cos(2.0 * kLobes * angle));  // a crease along each lobe
  Rgb petal = Scale(MixRgb(palette.petal, palette.centre, throat), 1.0 - 0.10 * rim - vein);
  // The blotch: darker spots on the upper lobe, between r 0.18 and 0.62, within ±24°.
  double wrapped = angle - 2.0 * det::kPi * std::floor((angle + det::kPi) / (2.0 * det::kPi));
  if (std::fabs(wrapped) < 24.0 * kDegree && r > 0.18 && r < 0.62) {
    double sx = r * 11.0, sy = wrapped / kDegree / 7.0;  // a lattice of spots
    double fx = sx - std::floor(sx) - 0.5, fy = sy - std::floor(sy) - 0.5;
    double spot = 1.0 - SmoothStep(0.16, 0.30, std::sqrt(fx * fx + fy * fy));
    petal = MixRgb(petal, Scale(palette.centre, 0.7), 0.85 * spot);
  }
  Rgb out = corolla > 0.0 ? petal : palette.stamen;
  out = MixRgb(out, palette.stamen, filament * (corolla > 0.0 ? 0.9 : 1.0));
  out = MixRgb(out, palette.anther, anther);
  *colour = out;
  return coverage;
}

// One flower placed on a flower card: centre, radius, rotation (uv units) and a shade factor.
struct Placed {
  double x, y, radius, rotation, shade;
};

// Paints placed flowers back to front ("over"), each with `flower`, into a size × size image.
template <typename Flower>
Rgba8Image PaintFlowers(int size, const std::vector<Placed>& placed, const Palette& palette,
                        Flower flower) {
  Rgba8Image image = Allocate(size, size);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      double px = (x + 0.5) / image.width - 0.5, py = (y + 0.5) / image.height - 0.5;
      Rgb out{palette.petal};
      double alpha = 0.0;
      for (const Placed& b : placed) {
        Rgb colour{0, 0, 0};
        double a = flower((px - b.x) / b.radius, (py - b.y) / b.radius, b.rotation,
                          1.0 / (b.radius * image.width), palette, &colour);
        if (a <= 0.0) continue;
        out = MixRgb(alpha > 0.0 ? out : colour, Scale(colour, b.shade), a);  // "over"
        alpha = a + alpha * (1.0 - a);
      }
      SetPixel(&image, x, y, out, alpha);
    }
  }
  return image;
}

}  // namespace

Rgba8Image MakeBarkTexture(int width, int height) {
  Rgba8Image image = Allocate(width, height);
  const std::vector<double> relief = BarkReliefImage(image.width, image.height);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      double grain = Hash01(static_cast<uint32_t>(x), static_cast<uint32_t>(y), 41u) - 0.5;
      double shade = Clamp01(relief[static_cast<std::size_t>(y * image.width + x)] + 0.08 * grain);
      SetPixel(&image, x, y,
               {Mix(0.16, 0.47, shade), Mix(0.11, 0.35, shade), Mix(0.08, 0.25, shade)}, 1.0);
    }
  }
  return image;
}

Rgba8Image MakeBarkNormalMap(int width, int height) {
  Rgba8Image image = Allocate(width, height);
  if (image.empty()) return image;
  const std::vector<double> relief = BarkReliefImage(image.width, image.height);
  auto h = [&](int x, int y) {
    x = (x + image.width) % image.width;
    y = (y + image.height) % image.height;
    return relief[static_cast<std::size_t>(y * image.width + x)];
  };
  // Slope per unit of relief change between neighbouring texels: a plate stands about 6 texels
  // proud of its furrow at 512 px (deep-furrowed bark); scaled with the size so the look stays.
  const double strength_x = 6.0 * image.width / 512.0, strength_y = 6.0 * image.height / 512.0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      double du = 0.5 * (h(x + 1, y) - h(x - 1, y)) * strength_x;
      double drow = 0.5 * (h(x, y + 1) - h(x, y - 1)) * strength_y;
      // +y of the map is up in the image (towards row 0): d/d(up) = -d/d(row).
      double nx = -du, ny = drow, nz = 1.0;
      double n = std::sqrt(nx * nx + ny * ny + nz * nz);
      SetPixel(&image, x, y, {0.5 + 0.5 * nx / n, 0.5 + 0.5 * ny / n, 0.5 + 0.5 * nz / n}, 1.0);
    }
  }
  return image;
}

LeafCardSize LeafCardOf(const TreeLook& look) {
  if (look.leaf_spray <= 1) return {LeafQuadAspect(look.leaf_shape), 1.0f};
  const Spray spray = LayoutSpray(look.leaf_shape, std::min(look.leaf_spray, kMaxLeafSpray));
  return {static_cast<float>(spray.width), static_cast<float>(spray.length)};
}

Rgba8Image MakeLeafTexture(const TreeLook& look, int size) {
  Rgba8Image image = Allocate(size, size);
  const Rgb base = LeafColour(look);
  const Rgb light = MixRgb(base, {1.0, 1.0, 0.85}, 0.42);
  if (look.leaf_spray > 1) return MakeSprayTexture(look, base, light, std::move(image));
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      // Coverage from 2 × 2 samples; the colour from the pixel's centre.
      int covered = 0;
      for (int k = 0; k < 4; ++k) {
        double u = (x + 0.25 + 0.5 * (k & 1)) / image.width;
        double v = (y + 0.25 + 0.5 * (k >> 1)) / image.height;
        covered += SampleBlade(look.leaf_shape, u, v).inside ? 1 : 0;
      }
      double u = (x + 0.5) / image.width, v = (y + 0.5) / image.height;
      BladeSample s = SampleBlade(look.leaf_shape, u, v);
      double mottle = PeriodicFbm(u, v, 6, 6, 2, 53u) - 0.5;
      double shade = (0.88 + 0.12 * v) * (1.0 - 0.18 * s.edge * s.edge) + 0.12 * mottle;
      Rgb colour = MixRgb(Scale(base, shade), light, Clamp01(s.vein));
      SetPixel(&image, x, y, colour, covered / 4.0);
    }
  }
  return image;
}

Rgba8Image MakeBlossomTexture(int size) {
  Rgba8Image image = Allocate(size, size);
  const double pixel = 2.0 / std::max(1, size);  // one texel in blossom radii
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      double dx = 2.0 * (x + 0.5) / image.width - 1.0, dy = 2.0 * (y + 0.5) / image.height - 1.0;
      Rgb colour{0, 0, 0};
      double a = Blossom(dx, dy, 0.5 * det::kPi, pixel, kCherryPalette, &colour);
      SetPixel(&image, x, y, a > 0.0 ? colour : kCherryPalette.petal, a);
    }
  }
  return image;
}

Rgba8Image MakeBlossomClusterTexture(int size) { return MakeFlowerTexture(TreeLook{}, size); }

Rgba8Image MakeFlowerTexture(const TreeLook& look, int size) {
  const Palette palette = FlowerPalette(look.flower_colour);
  std::vector<Placed> placed;
  if (look.flower_form == FlowerForm::kAzalea) {
    // A truss of three funnel flowers (Kurume azaleas: 2-4 a truss, 2.5-4 cm across), each
    // facing outwards: its spotted upper lobe towards the truss's centre, its stamens out.
    for (int k = 0; k < 3; ++k) {
      const uint32_t key = static_cast<uint32_t>(k);
      double at = (90.0 + 120.0 * k + 16.0 * (Hash01(key, 4u, 83u) - 0.5)) * kDegree;
      double ring = 0.205 + 0.02 * (Hash01(key, 3u, 83u) - 0.5);
      placed.push_back({ring * det::Cos(at), ring * det::Sin(at),
                        0.28 + 0.015 * Hash01(key, 5u, 83u),
                        at + det::kPi + 12.0 * (Hash01(key, 6u, 83u) - 0.5) * kDegree,
                        0.9 + 0.1 * Hash01(key, 7u, 83u)});
    }
    return PaintFlowers(size, placed, palette, AzaleaFlower);
  }
  // Six blossoms around one, each turned and shaded a little differently (fixed hashes).
  for (int k = 0; k < 7; ++k) {
    const uint32_t key = static_cast<uint32_t>(k);
    double ring = k == 0 ? 0.0 : 0.29 + 0.03 * (Hash01(key, 3u, 97u) - 0.5);
    double at = (60.0 * k + 14.0 * (Hash01(key, 4u, 97u) - 0.5)) * kDegree;
    double radius = k == 0 ? 0.21 : 0.19 + 0.02 * Hash01(key, 5u, 97u);
    placed.push_back({ring * det::Cos(at), ring * det::Sin(at), radius,
                      2.0 * det::kPi * Hash01(key, 6u, 97u), 0.9 + 0.1 * Hash01(key, 7u, 97u)});
  }
  std::rotate(placed.begin(), placed.begin() + 1, placed.end());  // the centre one on top
  return PaintFlowers(size, placed, palette, Blossom);
}

std::string ImageDigest(const Rgba8Image& image) {
  uint64_t h = 0xcbf29ce484222325ull;
  auto mix = [&h](unsigned char byte) {
    h ^= byte;
    h *= 0x100000001b3ull;
  };
  for (int shift = 0; shift < 32; shift += 8) {
    mix(static_cast<unsigned char>(static_cast<uint32_t>(image.width) >> shift));
    mix(static_cast<unsigned char>(static_cast<uint32_t>(image.height) >> shift));
  }
  for (unsigned char byte : image.pixels) mix(byte);
  char text[17];
  std::snprintf(text, sizeof text, "%016" PRIx64, h);
  return text;
}

}  // namespace niwa
