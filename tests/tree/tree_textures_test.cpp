// Unit tests of the tree's procedural material textures: sizes, alpha coverage and outline per leaf
// shape, season colours, blossoms, bark colour and normal map tiling, digests (native == WASM),
// PNG.
#include "tree/tree_textures.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "image/png.h"
#include "math/det_math.h"

namespace niwa {
namespace {

bool HasPngMagic(const std::vector<unsigned char>& png) {
  static const unsigned char kMagic[8] = {0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A};
  return png.size() > 8 && std::equal(kMagic, kMagic + 8, png.begin());
}

uint32_t ReadBigEndian(const std::vector<unsigned char>& bytes, std::size_t offset) {
  return (uint32_t{bytes[offset]} << 24) | (uint32_t{bytes[offset + 1]} << 16) |
         (uint32_t{bytes[offset + 2]} << 8) | uint32_t{bytes[offset + 3]};
}

// Mean absolute difference of the RGB of two columns, 0..255.
double ColumnDifference(const Rgba8Image& image, int a, int b) {
  double sum = 0.0;
  for (int y = 0; y < image.height; ++y) {
    for (int c = 0; c < 3; ++c) sum += std::abs(image.At(a, y)[c] - image.At(b, y)[c]);
  }
  return sum / (3.0 * image.height);
}

TreeLook Look(LeafShape shape, Season season = Season::kSummer,
              AutumnColour autumn = AutumnColour::kRedOrange) {
  TreeLook look;
  look.leaf_shape = shape;
  look.season = season;
  look.autumn = autumn;
  return look;
}

const LeafShape kShapes[] = {LeafShape::kBroad, LeafShape::kNeedle, LeafShape::kPalmate,
                             LeafShape::kFan};

// Share of the pixels with alpha >= 128.
double Coverage(const Rgba8Image& image) {
  int opaque = 0;
  for (std::size_t i = 3; i < image.pixels.size(); i += 4) opaque += image.pixels[i] >= 128;
  return static_cast<double>(opaque) / (image.width * image.height);
}

// Mean r, g, b (0..255) of the pixels with alpha >= 128.
std::array<double, 3> MeanOpaqueColour(const Rgba8Image& image) {
  std::array<double, 3> sum{0, 0, 0};
  int n = 0;
  for (std::size_t i = 0; i < image.pixels.size(); i += 4) {
    if (image.pixels[i + 3] < 128) continue;
    for (int c = 0; c < 3; ++c)
      sum[static_cast<std::size_t>(c)] += image.pixels[i + static_cast<std::size_t>(c)];
    ++n;
  }
  for (double& c : sum) c /= std::max(1, n);
  return sum;
}

// Runs of opaque pixels (alpha >= 128) met along a path of texel coordinates.
int OpaqueRuns(const Rgba8Image& image, const std::vector<std::pair<int, int>>& path) {
  int runs = 0;
  bool inside = false;
  for (auto [x, y] : path) {
    bool opaque = image.At(x, y)[3] >= 128;
    if (opaque && !inside) ++runs;
    inside = opaque;
  }
  return runs;
}

std::vector<std::pair<int, int>> Row(const Rgba8Image& image, double v) {
  std::vector<std::pair<int, int>> path;
  int y = static_cast<int>(v * image.height);
  for (int x = 0; x < image.width; ++x) path.push_back({x, y});
  return path;
}

TEST(TexturesTest, SizesAreAtLeast512AndPixelCountsMatch) {
  EXPECT_EQ(kTreeTextureSize, 512);
  for (const Rgba8Image& image : {MakeBarkTexture(), MakeBarkNormalMap(), MakeLeafTexture({}),
                                  MakeBlossomTexture(), MakeBlossomClusterTexture()}) {
    EXPECT_EQ(image.width, 512);
    EXPECT_EQ(image.height, 512);
    EXPECT_TRUE(image.consistent());
    EXPECT_EQ(image.pixels.size(), 4u * 512u * 512u);
  }
  for (LeafShape shape : kShapes) {
    Rgba8Image leaf = MakeLeafTexture(Look(shape), 64);
    EXPECT_EQ(leaf.width, 64);
    EXPECT_EQ(leaf.pixels.size(), 4u * 64u * 64u);
  }
  EXPECT_EQ(MakeBlossomTexture(32).pixels.size(), 4u * 32u * 32u);
  EXPECT_TRUE(MakeBarkTexture(0, 16).pixels.empty());
  EXPECT_TRUE(MakeBarkNormalMap(16, 0).pixels.empty());
  EXPECT_FALSE(image::EncodeRgba8Png(Rgba8Image{}).ok());
}

TEST(TexturesTest, DeterministicPixelsAndPngBytes) {
  EXPECT_EQ(MakeBarkTexture().pixels, MakeBarkTexture().pixels);
  EXPECT_EQ(MakeBarkNormalMap().pixels, MakeBarkNormalMap().pixels);
  EXPECT_EQ(MakeBlossomClusterTexture().pixels, MakeBlossomClusterTexture().pixels);
  for (LeafShape shape : kShapes) {
    EXPECT_EQ(MakeLeafTexture(Look(shape)).pixels, MakeLeafTexture(Look(shape)).pixels);
  }
  EXPECT_EQ(*image::EncodeRgba8Png(MakeBarkTexture()), *image::EncodeRgba8Png(MakeBarkTexture()));
  EXPECT_EQ(*image::EncodeRgba8Png(MakeLeafTexture({})),
            *image::EncodeRgba8Png(MakeLeafTexture({})));
}

// The digests the native build gives (printed by this test when they differ). This binary also
// runs under node on the WASM build (tests/CMakeLists.txt), where the same pixels must come out:
// the native == WASM check of the texture generator. A change of a texture changes its digest
// here on purpose.
TEST(TexturesTest, DigestsAreTheSameInBothBuilds) {
  EXPECT_EQ(ImageDigest(MakeBarkTexture()), "611837a32a63d9a6");
  EXPECT_EQ(ImageDigest(MakeBarkNormalMap()), "b45e564d5717ba10");
  EXPECT_EQ(ImageDigest(MakeBlossomClusterTexture()), "48b8b94065b4126f");
  EXPECT_EQ(ImageDigest(MakeLeafTexture(Look(LeafShape::kBroad))), "902164d1b8a9e981");
  EXPECT_EQ(ImageDigest(MakeLeafTexture(Look(LeafShape::kNeedle))), "20d37772113f831f");
  EXPECT_EQ(
      ImageDigest(MakeLeafTexture(Look(LeafShape::kPalmate, Season::kAutumn, AutumnColour::kRed))),
      "8c960e408a920d4f");
  EXPECT_EQ(
      ImageDigest(MakeLeafTexture(Look(LeafShape::kFan, Season::kAutumn, AutumnColour::kYellow))),
      "7efb5f0052030506");
  // The digest sees a one-byte change and the size.
  Rgba8Image a = MakeBlossomTexture(16), b = a;
  b.pixels[77] ^= 1;
  EXPECT_NE(ImageDigest(a), ImageDigest(b));
  EXPECT_NE(ImageDigest(image::MakeRgba8(4, 8)), ImageDigest(image::MakeRgba8(8, 4)));
}

TEST(TexturesTest, PngHeaderMatchesTheImage) {
  std::vector<unsigned char> png = *image::EncodeRgba8Png(MakeLeafTexture({}));
  ASSERT_TRUE(HasPngMagic(png));
  ASSERT_GT(png.size(), 33u);
  EXPECT_EQ(std::string(png.begin() + 12, png.begin() + 16), "IHDR");
  EXPECT_EQ(ReadBigEndian(png, 16), 512u);  // width
  EXPECT_EQ(ReadBigEndian(png, 20), 512u);  // height
  EXPECT_EQ(png[24], 8);                    // bit depth
  EXPECT_EQ(png[25], 6);                    // colour type RGBA
  EXPECT_EQ(std::string(png.end() - 8, png.end() - 4), "IEND");
}

TEST(TexturesTest, EveryLeafShapeIsCutOutWithTransparentCorners) {
  for (LeafShape shape : kShapes) {
    Rgba8Image leaf = MakeLeafTexture(Look(shape));
    const int w = leaf.width - 1, h = leaf.height - 1;
    for (auto [x, y] : {std::pair{0, 0}, {w, 0}, {0, h}, {w, h}}) {
      EXPECT_EQ(leaf.At(x, y)[3], 0) << LeafShapeName(shape) << " " << x << "," << y;
    }
    for (int y = 0; y <= h; ++y) {  // the quad's sides are outside every blade
      EXPECT_EQ(leaf.At(0, y)[3], 0) << LeafShapeName(shape) << " " << y;
      EXPECT_EQ(leaf.At(w, y)[3], 0) << LeafShapeName(shape) << " " << y;
    }
    // The base (petiole or sheath) is on the midline and opaque.
    EXPECT_EQ(leaf.At(leaf.width / 2, leaf.height / 20)[3], 255) << LeafShapeName(shape);
  }
}

// Coverage of each blade against its area worked out from its outline (tree_textures.cpp):
// broad ∫ 2·w(v) dv ≈ 0.55 of its quad; needles 14 × 0.86 long × 0.0138 mean width ≈ 0.17 of a
// 0.8-wide quad plus the sheath; palmate, seven lobes out to 0.26-0.57 from a 0.1 core ≈ 0.3-0.5;
// fan, a 132° sector of radius 0.64 = 0.47 in a 1.2 quad ≈ 0.39 minus the notch.
TEST(TexturesTest, AlphaCoveragePerShape) {
  const double broad = Coverage(MakeLeafTexture(Look(LeafShape::kBroad)));
  const double needle = Coverage(MakeLeafTexture(Look(LeafShape::kNeedle)));
  const double palmate = Coverage(MakeLeafTexture(Look(LeafShape::kPalmate)));
  const double fan = Coverage(MakeLeafTexture(Look(LeafShape::kFan)));
  EXPECT_GT(broad, 0.45);
  EXPECT_LT(broad, 0.70);
  EXPECT_GT(needle, 0.14);
  EXPECT_LT(needle, 0.28);
  EXPECT_GT(palmate, 0.28);
  EXPECT_LT(palmate, 0.55);
  EXPECT_GT(fan, 0.32);
  EXPECT_LT(fan, 0.42);
}

TEST(TexturesTest, ShapesReadAsTheirShapes) {
  // Broad: one blade across any row; needles: many across the upper half.
  Rgba8Image broad = MakeLeafTexture(Look(LeafShape::kBroad));
  EXPECT_EQ(OpaqueRuns(broad, Row(broad, 0.5)), 1);
  Rgba8Image needle = MakeLeafTexture(Look(LeafShape::kNeedle));
  EXPECT_GE(OpaqueRuns(needle, Row(needle, 0.7)), 10);
  // Palmate: seven lobes met on a circle of radius 0.33 round the blade's centre (0.5, 0.40).
  Rgba8Image palmate = MakeLeafTexture(Look(LeafShape::kPalmate));
  std::vector<std::pair<int, int>> circle;
  for (int k = 0; k <= 720; ++k) {
    double angle = (-140.0 + 280.0 * k / 720.0) * det::kPi / 180.0;  // 0 up
    double u = 0.5 + 0.33 * det::Sin(angle), v = 0.40 + 0.33 * det::Cos(angle);
    circle.push_back({static_cast<int>(u * palmate.width), static_cast<int>(v * palmate.height)});
  }
  EXPECT_EQ(OpaqueRuns(palmate, circle), 7);
  // Fan: the notch at the top middle is open while the rim beside it is blade.
  Rgba8Image fan = MakeLeafTexture(Look(LeafShape::kFan));
  auto alpha = [&fan](double u, double v) {
    return fan.At(static_cast<int>(u * fan.width), static_cast<int>(v * fan.height))[3];
  };
  EXPECT_EQ(alpha(0.5, 0.85), 0);
  EXPECT_EQ(alpha(0.58, 0.85), 255);
  EXPECT_EQ(alpha(0.42, 0.85), 255);
  EXPECT_EQ(OpaqueRuns(fan, Row(fan, 0.85)), 2);
}

TEST(TexturesTest, SeasonsColourTheLeaves) {
  auto mean = [](LeafShape shape, Season season, AutumnColour autumn) {
    return MeanOpaqueColour(MakeLeafTexture(Look(shape, season, autumn), 128));
  };
  auto summer = mean(LeafShape::kBroad, Season::kSummer, AutumnColour::kRedOrange);
  EXPECT_GT(summer[1], summer[0]);  // green
  EXPECT_GT(summer[1], summer[2]);
  auto spring = mean(LeafShape::kBroad, Season::kSpring, AutumnColour::kRedOrange);
  EXPECT_GT(spring[1], summer[1]);  // fresher, lighter green
  auto maple = mean(LeafShape::kPalmate, Season::kAutumn, AutumnColour::kRed);
  EXPECT_GT(maple[0], 2.5 * maple[1]);  // red
  auto ginkgo = mean(LeafShape::kFan, Season::kAutumn, AutumnColour::kYellow);
  EXPECT_GT(ginkgo[0], 150.0);  // yellow: red and green high, blue low
  EXPECT_GT(ginkgo[1], 130.0);
  EXPECT_LT(ginkgo[2], 0.4 * ginkgo[1]);
  auto sakura = mean(LeafShape::kBroad, Season::kAutumn, AutumnColour::kRedOrange);
  EXPECT_GT(sakura[0], 1.8 * sakura[1]);
  EXPECT_GT(sakura[1], 1.5 * sakura[2]);
  auto keyaki = mean(LeafShape::kBroad, Season::kAutumn, AutumnColour::kOrangeBrown);
  EXPECT_LT(keyaki[0], sakura[0]);  // browner: darker than sakura's red-orange
  auto pine = mean(LeafShape::kNeedle, Season::kWinter, AutumnColour::kEvergreen);
  EXPECT_GT(pine[1], pine[0]);  // an evergreen stays green
}

TEST(TexturesTest, BlossomHasFivePetalsAndTheClusterSeveralBlossoms) {
  Rgba8Image flower = MakeBlossomTexture();
  const int n = flower.width - 1;
  EXPECT_EQ(flower.At(0, 0)[3], 0);
  EXPECT_EQ(flower.At(n, n)[3], 0);
  EXPECT_EQ(flower.At(flower.width / 2, flower.height / 2)[3], 255);
  // Five petals met on a circle of 0.8 radii round the centre.
  std::vector<std::pair<int, int>> circle;
  for (int k = 0; k < 720; ++k) {
    // From a gap between petals (tips at 90° + k·72°, gaps 36° beyond), once round.
    double angle = 2.0 * det::kPi * (k + 0.5) / 720.0 + 0.7 * det::kPi;
    circle.push_back({static_cast<int>((0.5 + 0.4 * det::Cos(angle)) * flower.width),
                      static_cast<int>((0.5 + 0.4 * det::Sin(angle)) * flower.height)});
  }
  EXPECT_EQ(OpaqueRuns(flower, circle), 5);
  auto pink = MeanOpaqueColour(flower);
  EXPECT_GT(pink[0], pink[1]);
  EXPECT_GT(pink[2], pink[1]);

  Rgba8Image cluster = MakeBlossomClusterTexture();
  EXPECT_EQ(cluster.At(0, 0)[3], 0);
  EXPECT_EQ(cluster.At(cluster.width - 1, cluster.height / 2)[3], 0);  // outside the disc
  EXPECT_EQ(cluster.At(cluster.width / 2, cluster.height / 2)[3], 255);
  const double coverage = Coverage(cluster);
  EXPECT_GT(coverage, 0.35);  // most of the card's disc (π/4 = 0.785 of the square)
  EXPECT_LT(coverage, 0.75);
  // Across the middle row: the centre blossom and one on each side at least.
  EXPECT_GE(OpaqueRuns(cluster, Row(cluster, 0.5)), 1);
  auto cluster_pink = MeanOpaqueColour(cluster);
  EXPECT_GT(cluster_pink[0], cluster_pink[1]);
}

TEST(TexturesTest, BarkNormalMapPointsOutAndTiles) {
  Rgba8Image normal = MakeBarkNormalMap();
  double z = 0.0, spread = 0.0;
  for (std::size_t i = 0; i < normal.pixels.size(); i += 4) {
    EXPECT_EQ(normal.pixels[i + 3], 255);
    double nx = normal.pixels[i] / 127.5 - 1.0, ny = normal.pixels[i + 1] / 127.5 - 1.0,
           nz = normal.pixels[i + 2] / 127.5 - 1.0;
    EXPECT_NEAR(nx * nx + ny * ny + nz * nz, 1.0, 0.03);  // unit (8-bit rounding)
    z += nz;
    spread += std::fabs(nx);
  }
  const double pixels = normal.width * normal.height;
  EXPECT_GT(z / pixels, 0.8);        // mostly out of the wood
  EXPECT_GT(spread / pixels, 0.05);  // with relief: the furrows tilt it across (x)
  EXPECT_LT(ColumnDifference(normal, normal.width - 1, 0),
            3.0 * ColumnDifference(normal, 0, 1) + 3.0);  // wraps around the tube
}

TEST(TexturesTest, BarkIsOpaqueBrownAndTileable) {
  Rgba8Image bark = MakeBarkTexture();
  double r = 0, g = 0, b = 0;
  for (std::size_t i = 0; i < bark.pixels.size(); i += 4) {
    EXPECT_EQ(bark.pixels[i + 3], 255);
    r += bark.pixels[i];
    g += bark.pixels[i + 1];
    b += bark.pixels[i + 2];
  }
  EXPECT_GT(r, g);  // brown
  EXPECT_GT(g, b);
  // Wraps around the tube: the last column continues into the first about as smoothly as any
  // two neighbouring columns do, unlike columns half a texture apart.
  double seam = ColumnDifference(bark, bark.width - 1, 0);
  double neighbours = 0.0;
  for (int x = 0; x + 1 < bark.width; ++x) neighbours += ColumnDifference(bark, x, x + 1);
  neighbours /= bark.width - 1;
  double far = ColumnDifference(bark, 0, bark.width / 2 + 5);
  EXPECT_LT(seam, 2.0 * neighbours + 2.0) << seam << " vs " << neighbours;
  EXPECT_LT(seam, far);
  // It also repeats along the wood (v).
  double row_seam = 0.0;
  for (int x = 0; x < bark.width; ++x) {
    for (int c = 0; c < 3; ++c) {
      row_seam += std::abs(bark.At(x, bark.height - 1)[c] - bark.At(x, 0)[c]);
    }
  }
  row_seam /= 3.0 * bark.width;
  EXPECT_LT(row_seam, 2.0 * neighbours + 2.0);
  // Vertical furrows: columns vary more across than rows along.
  double along = 0.0;
  for (int y = 0; y + 1 < bark.height; ++y) {
    for (int x = 0; x < bark.width; ++x) along += std::abs(bark.At(x, y + 1)[0] - bark.At(x, y)[0]);
  }
  along /= (bark.height - 1) * bark.width;
  double across = 0.0;
  for (int x = 0; x + 1 < bark.width; ++x) across += ColumnDifference(bark, x, x + 1);
  across /= bark.width - 1;
  EXPECT_GT(across, along * 0.8);
}

// Connected groups (4-neighbour) of the opaque (alpha >= 128) leaf-coloured pixels: green over
// red in a summer look, so a brown twig joins nothing; their sizes, largest first.
std::vector<int> LeafBlobs(const Rgba8Image& image) {
  const int w = image.width, h = image.height;
  std::vector<int> label(static_cast<std::size_t>(w * h), 0);
  auto leafy = [&](int x, int y) {
    const unsigned char* p = image.At(x, y);
    return p[3] >= 128 && p[1] > p[0];
  };
  std::vector<int> sizes;
  std::vector<std::pair<int, int>> stack;
  for (int y0 = 0; y0 < h; ++y0) {
    for (int x0 = 0; x0 < w; ++x0) {
      if (!leafy(x0, y0) || label[static_cast<std::size_t>(y0 * w + x0)] != 0) continue;
      const int id = static_cast<int>(sizes.size()) + 1;
      int size = 0;
      stack.assign(1, {x0, y0});
      label[static_cast<std::size_t>(y0 * w + x0)] = id;
      while (!stack.empty()) {
        auto [x, y] = stack.back();
        stack.pop_back();
        ++size;
        for (auto [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
          const int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
          int& l = label[static_cast<std::size_t>(ny * w + nx)];
          if (l != 0 || !leafy(nx, ny)) continue;
          l = id;
          stack.push_back({nx, ny});
        }
      }
      sizes.push_back(size);
    }
  }
  std::sort(sizes.rbegin(), sizes.rend());
  return sizes;
}

TreeLook Spray(LeafShape shape, int leaves) {
  TreeLook look = Look(shape);
  look.leaf_spray = leaves;
  return look;
}

// Blobs of LeafBlobs at least a tenth of the largest: the leaves (or groups of touching leaves).
int BigBlobs(const Rgba8Image& image) {
  const std::vector<int> blobs = LeafBlobs(image);
  int big = 0;
  for (int size : blobs) big += size * 10 >= blobs.front() ? 1 : 0;
  return big;
}

// leaf_spray (issue 32 item 3): one card paints a twig with several leaves. Broad leaves
// alternate along the twig without touching: one blob of leaf colour each; a ginkgo's fans mostly
// (the terminal fan overlaps one); a maple's opposite pairs overlap the pair above and needle
// fascicles cross one another (their leaf area is checked). A brown twig on the midline at the
// base.
TEST(LeafSpray, ACardHoldsSeveralSeparateLeavesOnATwig) {
  for (LeafShape shape : kShapes) {
    const Rgba8Image spray = MakeLeafTexture(Spray(shape, 5), 256);
    const int leaves = BigBlobs(spray);
    const int expected = shape == LeafShape::kBroad ? 5 : shape == LeafShape::kFan ? 4 : 1;
    EXPECT_GE(leaves, expected) << LeafShapeName(shape);
    // The painted leaf area (leaf lengths²): at least three single leaves' worth.
    const LeafCardSize card = LeafCardOf(Spray(shape, 5));
    const double one = Coverage(MakeLeafTexture(Look(shape), 256)) * LeafQuadAspect(shape);
    EXPECT_GT(Coverage(spray) * card.width * card.length, 3.0 * one) << LeafShapeName(shape);
    // The twig: brown (red over green) opaque pixels on the midline near the base.
    const unsigned char* twig = spray.At(spray.width / 2, 2);
    EXPECT_EQ(twig[3], 255) << LeafShapeName(shape);
    EXPECT_GT(twig[0], twig[1]) << LeafShapeName(shape);
  }
  EXPECT_EQ(LeafBlobs(MakeLeafTexture(Look(LeafShape::kBroad), 256)).size(), 1u);
  // More leaves, more blobs.
  EXPECT_GT(BigBlobs(MakeLeafTexture(Spray(LeafShape::kBroad, 7), 256)),
            BigBlobs(MakeLeafTexture(Spray(LeafShape::kBroad, 3), 256)));
}

TEST(LeafSpray, OneLeafIsTodaysBladeAndASprayCardIsLargerAndTheSameEveryTime) {
  for (LeafShape shape : kShapes) {
    EXPECT_EQ(MakeLeafTexture(Spray(shape, 1), 64).pixels, MakeLeafTexture(Look(shape), 64).pixels);
    const LeafCardSize one = LeafCardOf(Spray(shape, 1)), five = LeafCardOf(Spray(shape, 5));
    EXPECT_EQ(one.width, LeafQuadAspect(shape));
    EXPECT_EQ(one.length, 1.0f);
    EXPECT_GT(five.width, one.width) << LeafShapeName(shape);
    EXPECT_GT(five.length, one.length) << LeafShapeName(shape);
    EXPECT_LT(five.width * five.length, 8.0f) << LeafShapeName(shape);
  }
  // Values outside the row are clamped to its range by the look (tree_look.cpp), so the card never
  // grows past kMaxLeafSpray leaves.
  EXPECT_EQ(LeafCardOf(Spray(LeafShape::kBroad, 99)).length,
            LeafCardOf(Spray(LeafShape::kBroad, kMaxLeafSpray)).length);
  // native == WASM: the digest of a spray (this binary also runs on the WASM build).
  EXPECT_EQ(ImageDigest(MakeLeafTexture(Spray(LeafShape::kBroad, 5), 128)), "bd73e7ecc6ff1da7");
  // The pine preset's card in winter (3 fascicles), 512 px: the page shows the same digest
  // (tests/browser/textures.test.mjs).
  TreeLook pine = Look(LeafShape::kNeedle, Season::kWinter, AutumnColour::kEvergreen);
  pine.leaf_spray = 3;
  EXPECT_EQ(ImageDigest(MakeLeafTexture(pine)), "3bd6c76cb188dd1c");
}

}  // namespace
}  // namespace niwa
