// Unit tests of core/image/png: 16- and 8-bit round trips, a hand-built PNG (stored deflate) read
// back, exact bytes of a tiny 16-bit image, tEXt chunks, and bad input as one-line Status errors.
#include "image/png.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "image/image.h"

namespace niwa::image {
namespace {

using Bytes = std::vector<unsigned char>;

void PutBe32(Bytes* out, uint32_t v) {
  for (int s = 24; s >= 0; s -= 8) out->push_back(static_cast<unsigned char>(v >> s));
}

void PutChunk(Bytes* out, const char* type, const Bytes& data) {
  PutBe32(out, static_cast<uint32_t>(data.size()));
  Bytes body(type, type + 4);
  body.insert(body.end(), data.begin(), data.end());
  out->insert(out->end(), body.begin(), body.end());
  PutBe32(out, Crc32(body.data(), body.size()));
}

// A PNG built by hand, independently of the encoder under test: filter 0 on every row and one
// stored (uncompressed) deflate block in a zlib stream with its Adler-32 (RFC 1950/1951).
Bytes HandBuiltPng(int width, int height, int bit_depth, int colour_type, const Bytes& samples) {
  const std::size_t row = samples.size() / static_cast<std::size_t>(height);
  Bytes raw;
  for (int y = 0; y < height; ++y) {
    raw.push_back(0);
    raw.insert(raw.end(), samples.begin() + static_cast<long>(row * static_cast<std::size_t>(y)),
               samples.begin() + static_cast<long>(row * static_cast<std::size_t>(y + 1)));
  }
  Bytes z = {0x78, 0x01, 0x01};  // zlib header; final stored block
  const uint16_t len = static_cast<uint16_t>(raw.size());
  z.push_back(static_cast<unsigned char>(len & 0xFF));
  z.push_back(static_cast<unsigned char>(len >> 8));
  z.push_back(static_cast<unsigned char>(~len & 0xFF));
  z.push_back(static_cast<unsigned char>((~len >> 8) & 0xFF));
  z.insert(z.end(), raw.begin(), raw.end());
  uint32_t a = 1, b = 0;
  for (unsigned char c : raw) {
    a = (a + c) % 65521u;
    b = (b + a) % 65521u;
  }
  PutBe32(&z, (b << 16) | a);
  Bytes png = {0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A};
  Bytes ihdr;
  PutBe32(&ihdr, static_cast<uint32_t>(width));
  PutBe32(&ihdr, static_cast<uint32_t>(height));
  ihdr.insert(ihdr.end(), {static_cast<unsigned char>(bit_depth),
                           static_cast<unsigned char>(colour_type), 0, 0, 0});
  PutChunk(&png, "IHDR", ihdr);
  PutChunk(&png, "IDAT", z);
  PutChunk(&png, "IEND", {});
  return png;
}

Gray16Image Ramp16(int width, int height) {
  Gray16Image image = MakeGray16(width, height);
  uint32_t state = 12345u;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      state = state * 1664525u + 1013904223u;  // LCG: noise on a slope, both ends of the range
      const uint32_t slope = static_cast<uint32_t>(x * 997 + y * 313) % 65536u;
      image.At(x, y) = static_cast<uint16_t>((slope + (state >> 24)) & 0xFFFFu);
    }
  }
  image.At(0, 0) = 0;
  image.At(width - 1, height - 1) = 65535;
  return image;
}

void ExpectOneLine(const Status& status, const std::string& part) {
  EXPECT_FALSE(status.ok());
  EXPECT_NE(status.Line().find(part), std::string::npos) << status.Line();
  EXPECT_EQ(status.Line().find('\n'), std::string::npos) << status.Line();
}

TEST(Crc32, MatchesTheStandardCheckValues) {
  const std::string check = "123456789";
  EXPECT_EQ(Crc32(reinterpret_cast<const unsigned char*>(check.data()), check.size()), 0xCBF43926u);
  const unsigned char iend[4] = {'I', 'E', 'N', 'D'};
  EXPECT_EQ(Crc32(iend, 4), 0xAE426082u);  // every PNG ends with these bytes
  // Chained over two pieces = over the whole.
  const auto* p = reinterpret_cast<const unsigned char*>(check.data());
  EXPECT_EQ(Crc32(p + 4, 5, Crc32(p, 4)), 0xCBF43926u);
}

TEST(Image, MakeAndFill) {
  Rgba8Image rgba = MakeRgba8(3, 2, 10, 20, 30);
  ASSERT_TRUE(rgba.consistent());
  EXPECT_EQ(rgba.pixels.size(), 24u);
  EXPECT_EQ(rgba.At(2, 1)[0], 10);
  EXPECT_EQ(rgba.At(2, 1)[3], 255);
  Fill(&rgba, 1, 2, 3, 4);
  EXPECT_EQ(rgba.At(1, 1)[3], 4);
  rgba.At(1, 0)[1] = 99;
  EXPECT_EQ(rgba.pixels[4 * 1 + 1], 99);
  Gray16Image grey = MakeGray16(4, 3, 7);
  grey.At(3, 2) = 65535;
  EXPECT_EQ(grey.pixels.back(), 65535);
  EXPECT_EQ(grey.At(0, 1), 7);
  EXPECT_TRUE(MakeGray16(0, 5).empty());
  EXPECT_TRUE(MakeRgba8(5, -1).pixels.empty());
}

// The sRGB image's mean in linear values: white and black average to 0.5 (not sRGB 128's
// 0.2158), sRGB 128 alone is 0.2158, alpha is ignored, an empty image is black.
TEST(Image, MeanLinearRgbAveragesAfterTheTransferFunction) {
  Rgba8Image two = MakeRgba8(2, 1, 0, 128, 255, 7);
  two.At(1, 0)[0] = 255;
  const std::array<double, 3> m = MeanLinearRgb(two);
  EXPECT_DOUBLE_EQ(m[0], 0.5);
  EXPECT_NEAR(m[1], 0.21586, 1e-5);
  EXPECT_DOUBLE_EQ(m[2], 1.0);
  EXPECT_NEAR(MeanLinearRgb(MakeRgba8(1, 1, 10, 10, 10))[0], 10 / 255.0 / 12.92, 1e-12);
  EXPECT_EQ(MeanLinearRgb(Rgba8Image{})[0], 0.0);
}

TEST(Png, Gray16RoundTripKeepsEverySample) {
  for (auto [w, h] : {std::pair{1, 1}, std::pair{37, 23}, std::pair{256, 3}}) {
    const Gray16Image image = Ramp16(w, h);
    Result<Bytes> png = EncodeGray16Png(image);
    ASSERT_TRUE(png.ok()) << png.status().Line();
    PngInfo info;
    Result<Gray16Image> back = DecodeGray16Png(png->data(), png->size(), &info);
    ASSERT_TRUE(back.ok()) << back.status().Line();
    EXPECT_EQ(back->width, w);
    EXPECT_EQ(back->height, h);
    EXPECT_EQ(back->pixels, image.pixels);
    EXPECT_EQ(info.bit_depth, 16);
    EXPECT_EQ(info.colour_type, 0);
    // Same image, same bytes.
    EXPECT_EQ(*EncodeGray16Png(image), *png);
  }
}

TEST(Png, Gray16TinyImageHasTheHandCheckedBytes) {
  Gray16Image image = MakeGray16(2, 2);
  image.pixels = {0x0000, 0x1234, 0xFFFF, 0x8001};
  Result<Bytes> png = EncodeGray16Png(image, {{{"k", "v"}}});
  ASSERT_TRUE(png.ok()) << png.status().Line();
  // Signature, IHDR (2 x 2, depth 16, grey) and tEXt "k\0v" with their CRCs, and the IEND chunk, as
  // computed by hand with Python's struct and zlib.crc32 from the PNG spec's layout.
  const Bytes head = {0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a,  // signature
                      0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52, 0x00, 0x00, 0x00, 0x02,
                      0x00, 0x00, 0x00, 0x02, 0x10, 0x00, 0x00, 0x00, 0x00, 0x07, 0x4d, 0x8e,
                      0xbb,  // IHDR
                      0x00, 0x00, 0x00, 0x03, 0x74, 0x45, 0x58, 0x74, 0x6b, 0x00, 0x76, 0xcb,
                      0x04, 0xf3, 0x90};  // tEXt
  const Bytes tail = {0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
  ASSERT_GT(png->size(), head.size() + tail.size());
  EXPECT_EQ(Bytes(png->begin(), png->begin() + static_cast<long>(head.size())), head);
  EXPECT_EQ(Bytes(png->end() - static_cast<long>(tail.size()), png->end()), tail);
  // The IDAT between them: a zlib stream of the filtered rows "00 0000 1234" and "03 ffff f868"
  // (None, then Average: the least sum of |signed byte|, worked by hand), checked with Python's
  // zlib.decompress and zlib.crc32 when this test was written, and decoded by stb below.
  const Bytes idat = {0x00, 0x00, 0x00, 0x12, 0x49, 0x44, 0x41, 0x54, 0x78, 0x5e,
                      0x63, 0x60, 0x60, 0x10, 0x32, 0x61, 0xfe, 0xff, 0xff, 0x47,
                      0x06, 0x00, 0x0b, 0x20, 0x03, 0xa8, 0x31, 0x9e, 0xf5, 0xf5};
  EXPECT_EQ(Bytes(png->begin() + static_cast<long>(head.size()),
                  png->end() - static_cast<long>(tail.size())),
            idat);
  PngInfo info;
  Result<Gray16Image> back = DecodeGray16Png(png->data(), png->size(), &info);
  ASSERT_TRUE(back.ok()) << back.status().Line();
  EXPECT_EQ(back->pixels, image.pixels);
  ASSERT_EQ(info.text.size(), 1u);
  EXPECT_EQ(info.text[0].keyword, "k");
  EXPECT_EQ(info.text[0].text, "v");
}

TEST(Png, ReadsAHandBuilt16BitAnd8BitGreyPngAndSaysWhichItIs) {
  // 16-bit: samples big-endian, as written by hand.
  const Bytes png16 = HandBuiltPng(3, 1, 16, 0, {0x00, 0x01, 0x80, 0x00, 0xff, 0xff});
  PngInfo info;
  Result<Gray16Image> a = DecodeGray16Png(png16.data(), png16.size(), &info);
  ASSERT_TRUE(a.ok()) << a.status().Line();
  EXPECT_EQ(a->pixels, (std::vector<uint16_t>{1, 0x8000, 0xFFFF}));
  EXPECT_EQ(info.bit_depth, 16);
  // 8-bit grey: scaled to 16 bits by 257 (255 -> 65535), bit_depth 8.
  const Bytes png8 = HandBuiltPng(2, 2, 8, 0, {0, 1, 128, 255});
  Result<Gray16Image> b = DecodeGray16Png(png8.data(), png8.size(), &info);
  ASSERT_TRUE(b.ok()) << b.status().Line();
  EXPECT_EQ(b->pixels, (std::vector<uint16_t>{0, 257, 128 * 257, 65535}));
  EXPECT_EQ(info.bit_depth, 8);
  EXPECT_EQ(info.width, 2);
  // The same 8-bit grey file as RGBA: grey in r, g, b, opaque.
  Result<Rgba8Image> c = DecodeRgba8Png(png8.data(), png8.size(), &info);
  ASSERT_TRUE(c.ok()) << c.status().Line();
  EXPECT_EQ(c->At(0, 1)[0], 128);
  EXPECT_EQ(c->At(0, 1)[2], 128);
  EXPECT_EQ(c->At(0, 1)[3], 255);
  // A 16-bit file as RGBA keeps the high byte.
  Result<Rgba8Image> d = DecodeRgba8Png(png16.data(), png16.size());
  ASSERT_TRUE(d.ok()) << d.status().Line();
  EXPECT_EQ(d->At(1, 0)[0], 0x80);
  // Our 16-bit writer and the hand-built file decode to the same samples.
  Gray16Image same = MakeGray16(3, 1);
  same.pixels = {1, 0x8000, 0xFFFF};
  Result<Bytes> ours = EncodeGray16Png(same);
  ASSERT_TRUE(ours.ok());
  EXPECT_EQ(DecodeGray16Png(ours->data(), ours->size())->pixels, a->pixels);
}

TEST(Png, Rgba8RoundTripWithTextChunks) {
  Rgba8Image image = MakeRgba8(5, 4);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    image.pixels[i] = static_cast<unsigned char>((i * 37 + 11) % 256);
  }
  Result<Bytes> plain = EncodeRgba8Png(image);
  ASSERT_TRUE(plain.ok()) << plain.status().Line();
  const std::string sidecar = R"({"hmin": 12.5, "hmax": 300})";
  Result<Bytes> png = EncodeRgba8Png(image, {{{"niwa", sidecar}, {"Software", "niwa"}}});
  ASSERT_TRUE(png.ok()) << png.status().Line();
  PngInfo info;
  Result<Rgba8Image> back = DecodeRgba8Png(png->data(), png->size(), &info);
  ASSERT_TRUE(back.ok()) << back.status().Line();
  EXPECT_EQ(back->pixels, image.pixels);
  EXPECT_EQ(info.colour_type, 6);
  EXPECT_EQ(info.bit_depth, 8);
  ASSERT_EQ(info.text.size(), 2u);
  EXPECT_EQ(info.text[0].keyword, "niwa");
  EXPECT_EQ(info.text[0].text, sidecar);
  EXPECT_EQ(info.text[1].keyword, "Software");
  // The text chunks are the only difference from the plain file.
  EXPECT_EQ(png->size(), plain->size() + (12 + 5 + sidecar.size()) + (12 + 9 + 4));
  EXPECT_EQ(DecodeRgba8Png(plain->data(), plain->size())->pixels, image.pixels);
  // A colour PNG is not a heightmap.
  ExpectOneLine(DecodeGray16Png(png->data(), png->size()).status(), "not greyscale");
}

// stb's lowest zlib effort (level 5, the bark maps') writes other bytes than its default 8, and
// both decode to the same pixels; the default stays stb's (the level is restored after a call).
TEST(Png, AFasterLevelDecodesToTheSamePixels) {
  Rgba8Image image = MakeRgba8(256, 96);
  Gray16Image grey = MakeGray16(256, 96);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      // Repeats at many distances, so the matcher has more candidates than level 5 keeps.
      const uint32_t v = static_cast<uint32_t>((x * 7 + (y / 3) * 13) % 29 + ((x ^ y) & 12) * 3);
      unsigned char* p = image.At(x, y);
      p[0] = static_cast<unsigned char>(v * 5);
      p[1] = static_cast<unsigned char>(v * 3 + y);
      p[2] = static_cast<unsigned char>((x / 4) * 9);
      p[3] = 255;
      grey.At(x, y) = static_cast<uint16_t>(v * 1000 + (x / 8) * 7);
    }
  const Result<Bytes> before = EncodeRgba8Png(image);
  PngWriteOptions fast;
  fast.level = kMinPngLevel;
  const Result<Bytes> rgba5 = EncodeRgba8Png(image, fast);
  const Result<Bytes> rgba8 = EncodeRgba8Png(image);
  ASSERT_TRUE(before.ok() && rgba5.ok() && rgba8.ok());
  EXPECT_EQ(*rgba8, *before);
  EXPECT_NE(*rgba5, *rgba8);
  EXPECT_EQ(DecodeRgba8Png(rgba5->data(), rgba5->size())->pixels, image.pixels);
  EXPECT_EQ(DecodeRgba8Png(rgba8->data(), rgba8->size())->pixels, image.pixels);
  const Result<Bytes> grey5 = EncodeGray16Png(grey, fast);
  const Result<Bytes> grey8 = EncodeGray16Png(grey);
  ASSERT_TRUE(grey5.ok() && grey8.ok());
  EXPECT_NE(*grey5, *grey8);
  EXPECT_EQ(DecodeGray16Png(grey5->data(), grey5->size())->pixels, grey.pixels);
  EXPECT_EQ(DecodeGray16Png(grey8->data(), grey8->size())->pixels, grey.pixels);
  // Below stb's floor is stb's floor.
  PngWriteOptions lowest;
  lowest.level = 1;
  EXPECT_EQ(*EncodeRgba8Png(image, lowest), *rgba5);
}

TEST(Png, BadInputIsAOneLineStatus) {
  const Bytes good = *EncodeGray16Png(Ramp16(9, 7));
  // Every truncation is an error, never a crash.
  for (std::size_t n = 0; n < good.size(); ++n) {
    Result<Gray16Image> cut = DecodeGray16Png(good.data(), n);
    ASSERT_FALSE(cut.ok()) << n;
    EXPECT_EQ(cut.status().Line().find('\n'), std::string::npos);
    EXPECT_FALSE(DecodeRgba8Png(good.data(), n).ok()) << n;
  }
  ExpectOneLine(DecodeGray16Png(good.data(), good.size() - 12).status(), "truncated PNG");
  const std::string text = "P2 2 2 255 not a png at all";
  ExpectOneLine(
      DecodeGray16Png(reinterpret_cast<const unsigned char*>(text.data()), text.size()).status(),
      "not a PNG file");
  ExpectOneLine(DecodeRgba8Png(nullptr, 0).status(), "not a PNG file");
  Bytes flipped = good;
  flipped[40] ^= 0x10;  // inside IDAT
  ExpectOneLine(DecodeGray16Png(flipped.data(), flipped.size()).status(), "CRC mismatch");
  // A corrupt zlib stream with valid CRCs: stb's error, still one line.
  Bytes bad_zlib = HandBuiltPng(2, 1, 8, 0, {1, 2});
  bad_zlib[8 + 25 + 8] = 0x00;  // first zlib header byte: not deflate
  {
    // Recompute the IDAT CRC so only the zlib stream is wrong.
    const std::size_t idat = 8 + 25;
    const uint32_t length = (uint32_t{bad_zlib[idat + 2]} << 8) | bad_zlib[idat + 3];
    const uint32_t crc = Crc32(bad_zlib.data() + idat + 4, 4 + length);
    for (int k = 0; k < 4; ++k) {
      bad_zlib[idat + 8 + length + static_cast<std::size_t>(k)] =
          static_cast<unsigned char>(crc >> (24 - 8 * k));
    }
  }
  ExpectOneLine(DecodeGray16Png(bad_zlib.data(), bad_zlib.size()).status(), "corrupt PNG");
  // Encoder input.
  ExpectOneLine(EncodeGray16Png(Gray16Image{}).status(), "image: 0 x 0 pixels");
  Gray16Image short_pixels = MakeGray16(4, 4);
  short_pixels.pixels.pop_back();
  ExpectOneLine(EncodeGray16Png(short_pixels).status(), "must be 16");
  ExpectOneLine(EncodeRgba8Png(MakeRgba8(70000, 1)).status(), "[1, 65535]");
  ExpectOneLine(EncodeRgba8Png(MakeRgba8(2, 2), {{{"", "x"}}}).status(), "tEXt keyword");
  ExpectOneLine(EncodeGray16Png(MakeGray16(2, 2), {{{" lead", "x"}}}).status(), "tEXt keyword");
  ExpectOneLine(EncodeGray16Png(MakeGray16(2, 2), {{{"k", std::string("a\0b", 3)}}}).status(),
                "NUL");
  // A header claiming a huge image is refused before decoding.
  const Bytes huge = HandBuiltPng(1, 1, 8, 0, {0});
  Bytes claim = huge;
  claim[16] = 0x00;
  claim[17] = 0x01;  // width 65536 + 1 ... then fix the CRC
  const uint32_t crc = Crc32(claim.data() + 12, 17);
  for (int k = 0; k < 4; ++k)
    claim[29 + static_cast<std::size_t>(k)] = static_cast<unsigned char>(crc >> (24 - 8 * k));
  ExpectOneLine(DecodeGray16Png(claim.data(), claim.size()).status(), "[1, 65535]");
}

}  // namespace
}  // namespace niwa::image
