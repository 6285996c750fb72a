// PNG files of the core's images: 8-bit RGBA write (textures), 16-bit greyscale write (heightmaps),
// optional tEXt chunks (a heightmap's JSON sidecar), and decoding of 8- and 16-bit PNGs that says
// what the file held. Bytes are deterministic: the same image gives the same PNG
// bytes natively and in WASM (integer-only filtering and zlib).
// Also decodes baseline and progressive JPEG to 8-bit RGBA (a glTF texture's other format).
// Does not: read or write files (callers pass bytes; native_cli writes them atomically), write
// 8-bit grey or palette PNGs, write JPEG, decode WebP or KTX2, keep colour profiles, gamma or any
// chunk but tEXt.
//
// Libraries (why these): stb (Debian libstb-dev, header-only, builds for both targets). stb_image
// decodes (stbi_load_16_from_memory keeps 16 bits); stb_image_write encodes 8-bit RGBA (the tree
// textures' bytes are stb's, unchanged). stb_image_write cannot write 16-bit, so the 16-bit writer
// here is ~60 lines over stb's own stbi_zlib_compress plus a CRC-32 (PNG spec 5.5). Debian's
// liblodepng-dev and libspng-dev (both do 16-bit both ways) ship only compiled .so files, no
// sources, so neither can be built for WASM. This file holds the project's one
// STB_IMAGE_IMPLEMENTATION and one STB_IMAGE_WRITE_IMPLEMENTATION (both static: no symbol clash).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "base/status.h"
#include "image/image.h"

namespace niwa::image {

// One tEXt chunk (PNG spec 11.3.4.3): keyword 1-79 printable ASCII characters without leading,
// trailing or double spaces; text without NUL (e.g. a JSON sidecar).
struct PngText {
  std::string keyword;
  std::string text;
};

struct PngWriteOptions {
  std::vector<PngText> text;  // written after IHDR, in this order
  // stb's zlib effort, kMinPngLevel..8 (stb keeps 2·level match candidates per hash; lower is
  // faster, the file a little larger, the decoded pixels the same). 8 is stb's default, the
  // bytes every texture had before the option.
  int level = 8;
};
constexpr int kMinPngLevel = 5;  // stb raises anything lower to 5

// What a PNG file holds, from its IHDR (PNG spec 11.2.2) and tEXt chunks.
struct PngInfo {
  int width = 0;
  int height = 0;
  int bit_depth = 0;    // 1, 2, 4, 8 or 16 as stored
  int colour_type = 0;  // 0 grey, 2 RGB, 3 palette, 4 grey + alpha, 6 RGBA
  std::vector<PngText> text;
  bool is_grey() const { return colour_type == 0 || colour_type == 4; }
};

// Largest image encoded or decoded: each side in [1, kMaxPngSide], at most kMaxPngPixels pixels.
constexpr int kMaxPngSide = 65535;
constexpr std::size_t kMaxPngPixels = std::size_t{1} << 26;

// 8-bit RGBA PNG (stb_image_write; tEXt chunks spliced in after IHDR).
Result<std::vector<unsigned char>> EncodeRgba8Png(const Rgba8Image& image,
                                                  const PngWriteOptions& options = {});

// 16-bit greyscale PNG (colour type 0, bit depth 16, samples big-endian as the spec says).
Result<std::vector<unsigned char>> EncodeGray16Png(const Gray16Image& image,
                                                   const PngWriteOptions& options = {});

// Checks the signature and every chunk's length and CRC up to IEND; reads IHDR and tEXt.
// Errors: "not a PNG file (...)", "truncated PNG (...)", "corrupt PNG (...)"; no field (the
// caller adds the file name with Status::Within).
Result<PngInfo> ReadPngInfo(const unsigned char* data, std::size_t size);

// A greyscale PNG (colour type 0 or 4; alpha dropped) as 16-bit samples: 16-bit files as stored,
// lower depths scaled to 0..65535 (v * 65535 / (2^depth - 1): 8-bit 255 -> 65535). `info`, when
// given, says what the file held (bit_depth 8 or 16 ...). Colour PNGs are an error.
Result<Gray16Image> DecodeGray16Png(const unsigned char* data, std::size_t size,
                                    PngInfo* info = nullptr);

// Any PNG (grey, palette, RGB, with or without alpha, 8 or 16 bits: 16-bit samples keep their
// high byte) as 8-bit RGBA. `info` as above.
Result<Rgba8Image> DecodeRgba8Png(const unsigned char* data, std::size_t size,
                                  PngInfo* info = nullptr);

// What an encoded image's first bytes say it is (PNG signature, JPEG SOI marker, RIFF....WEBP,
// the KTX 2 identifier); kUnknown otherwise.
enum class ImageFormat { kUnknown, kPng, kJpeg, kWebp, kKtx2 };
ImageFormat SniffImageFormat(const unsigned char* data, std::size_t size);

// The width and height a PNG or JPEG declares, read from its header without decoding (a PNG's
// IHDR as stored, 0 included; a JPEG's frame header through stb_image's info): "not a PNG or JPEG
// image", "corrupt PNG (...)", "corrupt JPEG (...)"; no field.
struct ImageSize {
  int width = 0;
  int height = 0;
};
Result<ImageSize> ReadImageSize(const unsigned char* data, std::size_t size);

// A PNG or JPEG as 8-bit RGBA: its declared size checked first (each side 1 .. kMaxPngSide, at
// most max_pixels pixels: "W x H pixels; ..."), then decoded. Errors have no field.
Result<Rgba8Image> DecodeRgba8PngOrJpeg(const unsigned char* data, std::size_t size,
                                        std::size_t max_pixels);

// CRC-32 of PNG chunks (ISO 3309, as PNG spec annex D); exposed for tests.
uint32_t Crc32(const unsigned char* data, std::size_t size, uint32_t crc = 0);

}  // namespace niwa::image
