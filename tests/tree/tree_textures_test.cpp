// Unit tests of the tree's procedural material textures: determinism, leaf/flower alpha, bark
// tiling, PNG.
#include "tree/tree_textures.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "image/png.h"

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

TEST(TexturesTest, SizesAndPixelCounts) {
  Rgba8Image bark = MakeBarkTexture();
  EXPECT_EQ(bark.width, 128);
  EXPECT_EQ(bark.height, 256);
  EXPECT_EQ(bark.pixels.size(), 4u * 128u * 256u);
  Rgba8Image leaf = MakeLeafTexture();
  EXPECT_EQ(leaf.width, 128);
  EXPECT_EQ(leaf.height, 128);
  EXPECT_EQ(leaf.pixels.size(), 4u * 128u * 128u);
  Rgba8Image flower = MakeFlowerTexture(32);
  EXPECT_EQ(flower.pixels.size(), 4u * 32u * 32u);
  EXPECT_TRUE(MakeBarkTexture(0, 16).pixels.empty());
  EXPECT_FALSE(image::EncodeRgba8Png(Rgba8Image{}).ok());
}

TEST(TexturesTest, DeterministicPixelsAndPngBytes) {
  EXPECT_EQ(MakeBarkTexture().pixels, MakeBarkTexture().pixels);
  EXPECT_EQ(MakeLeafTexture().pixels, MakeLeafTexture().pixels);
  EXPECT_EQ(MakeFlowerTexture().pixels, MakeFlowerTexture().pixels);
  EXPECT_EQ(*image::EncodeRgba8Png(MakeBarkTexture()), *image::EncodeRgba8Png(MakeBarkTexture()));
  EXPECT_EQ(*image::EncodeRgba8Png(MakeLeafTexture()), *image::EncodeRgba8Png(MakeLeafTexture()));
  EXPECT_EQ(*image::EncodeRgba8Png(MakeFlowerTexture()),
            *image::EncodeRgba8Png(MakeFlowerTexture()));
}

TEST(TexturesTest, PngHeaderMatchesTheImage) {
  Rgba8Image leaf = MakeLeafTexture();
  std::vector<unsigned char> png = *image::EncodeRgba8Png(leaf);
  ASSERT_TRUE(HasPngMagic(png));
  ASSERT_GT(png.size(), 33u);
  EXPECT_EQ(std::string(png.begin() + 12, png.begin() + 16), "IHDR");
  EXPECT_EQ(ReadBigEndian(png, 16), 128u);  // width
  EXPECT_EQ(ReadBigEndian(png, 20), 128u);  // height
  EXPECT_EQ(png[24], 8);                    // bit depth
  EXPECT_EQ(png[25], 6);                    // colour type RGBA
  EXPECT_EQ(std::string(png.end() - 8, png.end() - 4), "IEND");
  EXPECT_TRUE(HasPngMagic(*image::EncodeRgba8Png(MakeBarkTexture())));
  EXPECT_TRUE(HasPngMagic(*image::EncodeRgba8Png(MakeFlowerTexture())));
}

TEST(TexturesTest, LeafIsOpaqueInsideAndTransparentOutside) {
  Rgba8Image leaf = MakeLeafTexture();
  const int w = leaf.width - 1, h = leaf.height - 1;
  for (auto [x, y] : {std::pair{0, 0}, {w, 0}, {0, h}, {w, h}}) {
    EXPECT_EQ(leaf.At(x, y)[3], 0) << x << "," << y;
  }
  for (int y = 0; y <= h; ++y) {  // the quad's sides are outside the blade
    EXPECT_EQ(leaf.At(0, y)[3], 0) << y;
    EXPECT_EQ(leaf.At(w, y)[3], 0) << y;
  }
  const unsigned char* centre = leaf.At(leaf.width / 2, leaf.height / 2);
  EXPECT_EQ(centre[3], 255);
  const unsigned char* blade = leaf.At(leaf.width / 2 - 20, leaf.height / 2);
  EXPECT_EQ(blade[3], 255);
  EXPECT_GT(blade[1], blade[0]);  // green
  EXPECT_GT(blade[1], blade[2]);
  int opaque = 0;
  for (std::size_t i = 3; i < leaf.pixels.size(); i += 4) opaque += leaf.pixels[i] >= 128;
  double coverage = static_cast<double>(opaque) / (leaf.width * leaf.height);
  EXPECT_GT(coverage, 0.35);
  EXPECT_LT(coverage, 0.8);
}

TEST(TexturesTest, FlowerHasPetalsWithAlpha) {
  Rgba8Image flower = MakeFlowerTexture();
  const int n = flower.width - 1;
  EXPECT_EQ(flower.At(0, 0)[3], 0);
  EXPECT_EQ(flower.At(n, n)[3], 0);
  EXPECT_EQ(flower.At(flower.width / 2, flower.height / 2)[3], 255);
  // A petal tip direction (angle 0: +u) reaches further than the gap between petals (angle 36°).
  const unsigned char* petal =
      flower.At(flower.width / 2 + flower.width * 4 / 10, flower.height / 2);
  EXPECT_GT(petal[3], 128);
  EXPECT_GT(petal[0], petal[1]);  // pink
  int transparent = 0;
  for (std::size_t i = 3; i < flower.pixels.size(); i += 4) transparent += flower.pixels[i] < 128;
  EXPECT_GT(transparent, flower.width * flower.height / 4);
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

}  // namespace
}  // namespace niwa
