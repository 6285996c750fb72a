// PNG encoding (stb_image_write for 8-bit RGBA; a 16-bit greyscale writer over stbi_zlib_compress)
// and decoding (stb_image, after a chunk and CRC walk of our own that also reads tEXt; JPEG through
// stb_image alone).
#include "image/png.h"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <cstring>
#include <limits>

#define STB_IMAGE_WRITE_STATIC
#define STBI_WRITE_NO_STDIO
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

#define STB_IMAGE_STATIC
#define STBI_NO_STDIO
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>

namespace niwa::image {
namespace {

constexpr unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A};

uint32_t ReadBe32(const unsigned char* p) {
  return (uint32_t{p[0]} << 24) | (uint32_t{p[1]} << 16) | (uint32_t{p[2]} << 8) | uint32_t{p[3]};
}

void AppendBe32(std::vector<unsigned char>* out, uint32_t v) {
  out->push_back(static_cast<unsigned char>(v >> 24));
  out->push_back(static_cast<unsigned char>(v >> 16));
  out->push_back(static_cast<unsigned char>(v >> 8));
  out->push_back(static_cast<unsigned char>(v));
}

// One chunk: length, type, data, CRC over type and data (PNG spec 5.3).
void AppendChunk(std::vector<unsigned char>* out, const char type[4], const unsigned char* data,
                 std::size_t size) {
  AppendBe32(out, static_cast<uint32_t>(size));
  const std::size_t start = out->size();
  out->insert(out->end(), type, type + 4);
  if (size > 0) out->insert(out->end(), data, data + size);
  AppendBe32(out, Crc32(out->data() + start, 4 + size));
}

Status CheckSize(int width, int height, std::size_t stored, std::size_t per_pixel) {
  const bool sides = width >= 1 && height >= 1 && width <= kMaxPngSide && height <= kMaxPngSide;
  const std::size_t pixels =
      sides ? static_cast<std::size_t>(width) * static_cast<std::size_t>(height) : 0;
  if (!sides || pixels > kMaxPngPixels) {
    return Status::Error("image", std::to_string(width) + " x " + std::to_string(height) +
                                      " pixels; width and height must be in [1, 65535] with at "
                                      "most 2^26 pixels");
  }
  if (stored != pixels * per_pixel) {
    return Status::Error("image", std::to_string(stored) + " samples for " + std::to_string(width) +
                                      " x " + std::to_string(height) + " pixels; must be " +
                                      std::to_string(pixels * per_pixel));
  }
  return Status::Ok();
}

Status CheckText(const std::vector<PngText>& text) {
  for (const PngText& t : text) {
    bool ok = !t.keyword.empty() && t.keyword.size() <= 79 && t.keyword.front() != ' ' &&
              t.keyword.back() != ' ' && t.keyword.find("  ") == std::string::npos;
    for (char c : t.keyword) ok = ok && c >= 32 && c <= 126;
    if (!ok) {
      return Status::Error("tEXt keyword", "'" + t.keyword +
                                               "' must be 1-79 printable ASCII characters with "
                                               "no leading, trailing or double spaces");
    }
    if (t.text.find('\0') != std::string::npos) {
      return Status::Error("tEXt " + t.keyword, "text must not contain NUL bytes");
    }
  }
  return Status::Ok();
}

void AppendTextChunks(std::vector<unsigned char>* out, const std::vector<PngText>& text) {
  for (const PngText& t : text) {
    std::vector<unsigned char> data(t.keyword.begin(), t.keyword.end());
    data.push_back(0);
    data.insert(data.end(), t.text.begin(), t.text.end());
    AppendChunk(out, "tEXt", data.data(), data.size());
  }
}

void AppendBytes(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<unsigned char>*>(context);
  const auto* bytes = static_cast<const unsigned char*>(data);
  out->insert(out->end(), bytes, bytes + size);
}

// Paeth predictor (PNG spec 9.4).
int Paeth(int a, int b, int c) {
  const int p = a + b - c;
  const int pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
  if (pa <= pb && pa <= pc) return a;
  return pb <= pc ? b : c;
}

// Filters one scanline with type `filter` (PNG spec 9.2); `bpp` bytes per pixel.
void FilterRow(int filter, const unsigned char* row, const unsigned char* prior, std::size_t n,
               std::size_t bpp, unsigned char* out) {
  for (std::size_t i = 0; i < n; ++i) {
    const int a = i >= bpp ? row[i - bpp] : 0;
    const int b = prior != nullptr ? prior[i] : 0;
    const int c = i >= bpp && prior != nullptr ? prior[i - bpp] : 0;
    int predicted = 0;
    switch (filter) {
      case 1:
        predicted = a;
        break;
      case 2:
        predicted = b;
        break;
      case 3:
        predicted = (a + b) / 2;
        break;
      case 4:
        predicted = Paeth(a, b, c);
        break;
      default:
        predicted = 0;
        break;
    }
    out[i] = static_cast<unsigned char>((row[i] - predicted) & 0xFF);
  }
}

// stb_image's RGBA8 decode of a PNG or JPEG whose header was checked; `kind` ("PNG", "JPEG")
// names the format in the error.
Result<Rgba8Image> StbDecodeRgba8(const unsigned char* data, std::size_t size, const char* kind) {
  int w = 0, h = 0, channels = 0;
  stbi_uc* pixels = stbi_load_from_memory(data, static_cast<int>(size), &w, &h, &channels, 4);
  if (pixels == nullptr) {
    return Status::Error("", std::string("corrupt ") + kind + " (" + stbi_failure_reason() + ")");
  }
  Rgba8Image image;
  image.width = w;
  image.height = h;
  image.pixels.assign(pixels,
                      pixels + 4 * static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  stbi_image_free(pixels);
  return image;
}

}  // namespace

uint32_t Crc32(const unsigned char* data, std::size_t size, uint32_t crc) {
  static const std::array<uint32_t, 256> kTable = [] {
    std::array<uint32_t, 256> table{};
    for (uint32_t n = 0; n < 256; ++n) {
      uint32_t c = n;
      for (int k = 0; k < 8; ++k) c = (c & 1u) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      table[n] = c;
    }
    return table;
  }();
  uint32_t c = crc ^ 0xFFFFFFFFu;
  for (std::size_t i = 0; i < size; ++i) c = kTable[(c ^ data[i]) & 0xFFu] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

Result<std::vector<unsigned char>> EncodeRgba8Png(const Rgba8Image& image,
                                                  const PngWriteOptions& options) {
  NIWA_RETURN_IF_ERROR(CheckSize(image.width, image.height, image.pixels.size(), 4));
  NIWA_RETURN_IF_ERROR(CheckText(options.text));
  std::vector<unsigned char> png;
  // stb reads its effort from a global: set for this call, restored after (PNG encoding runs on
  // one thread).
  const int saved_level = stbi_write_png_compression_level;
  stbi_write_png_compression_level = std::max(kMinPngLevel, std::min(8, options.level));
  const int ok = stbi_write_png_to_func(AppendBytes, &png, image.width, image.height, 4,
                                        image.pixels.data(), 4 * image.width);
  stbi_write_png_compression_level = saved_level;
  if (!ok || png.size() < 33) {
    return Status::Error("image", "PNG encoding failed");
  }
  if (options.text.empty()) return png;
  // stb writes the signature (8 bytes) and IHDR (25 bytes) first: the text goes right after.
  std::vector<unsigned char> out(png.begin(), png.begin() + 33);
  AppendTextChunks(&out, options.text);
  out.insert(out.end(), png.begin() + 33, png.end());
  return out;
}

Result<std::vector<unsigned char>> EncodeGray16Png(const Gray16Image& image,
                                                   const PngWriteOptions& options) {
  NIWA_RETURN_IF_ERROR(CheckSize(image.width, image.height, image.pixels.size(), 1));
  NIWA_RETURN_IF_ERROR(CheckText(options.text));
  const std::size_t width = static_cast<std::size_t>(image.width);
  const std::size_t height = static_cast<std::size_t>(image.height);
  const std::size_t row_bytes = 2 * width;
  if ((row_bytes + 1) * height > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
    return Status::Error("image", "too large for one zlib stream (more than 2^31 bytes)");
  }
  // Big-endian samples, then per row the filter with the least sum of |signed byte| (the
  // heuristic of PNG spec 12.8 and stb_image_write), so heightmaps compress well.
  std::vector<unsigned char> raw(row_bytes * height);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    raw[2 * i] = static_cast<unsigned char>(image.pixels[i] >> 8);
    raw[2 * i + 1] = static_cast<unsigned char>(image.pixels[i] & 0xFF);
  }
  std::vector<unsigned char> filtered((row_bytes + 1) * height);
  std::vector<unsigned char> trial(row_bytes);
  for (std::size_t y = 0; y < height; ++y) {
    const unsigned char* row = raw.data() + y * row_bytes;
    const unsigned char* prior = y > 0 ? row - row_bytes : nullptr;
    unsigned char* out = filtered.data() + y * (row_bytes + 1);
    long best_cost = std::numeric_limits<long>::max();
    for (int filter = 0; filter < 5; ++filter) {
      FilterRow(filter, row, prior, row_bytes, 2, trial.data());
      long cost = 0;
      for (unsigned char v : trial) cost += std::abs(static_cast<int>(static_cast<signed char>(v)));
      if (cost < best_cost) {
        best_cost = cost;
        out[0] = static_cast<unsigned char>(filter);
        std::memcpy(out + 1, trial.data(), row_bytes);
      }
    }
  }
  int zlib_size = 0;
  unsigned char* zlib =
      stbi_zlib_compress(filtered.data(), static_cast<int>(filtered.size()), &zlib_size,
                         std::max(kMinPngLevel, std::min(8, options.level)));
  if (zlib == nullptr) return Status::Error("image", "zlib compression failed");

  std::vector<unsigned char> png(kSignature, kSignature + 8);
  unsigned char ihdr[13];
  const uint32_t w = static_cast<uint32_t>(image.width), h = static_cast<uint32_t>(image.height);
  for (int k = 0; k < 4; ++k) {
    ihdr[k] = static_cast<unsigned char>(w >> (24 - 8 * k));
    ihdr[4 + k] = static_cast<unsigned char>(h >> (24 - 8 * k));
  }
  ihdr[8] = 16;                        // bit depth
  ihdr[9] = 0;                         // colour type: greyscale
  ihdr[10] = ihdr[11] = ihdr[12] = 0;  // deflate, adaptive filtering, no interlace
  AppendChunk(&png, "IHDR", ihdr, sizeof ihdr);
  AppendTextChunks(&png, options.text);
  AppendChunk(&png, "IDAT", zlib, static_cast<std::size_t>(zlib_size));
  STBIW_FREE(zlib);
  AppendChunk(&png, "IEND", nullptr, 0);
  return png;
}

Result<PngInfo> ReadPngInfo(const unsigned char* data, std::size_t size) {
  if (data == nullptr || size < 8 || std::memcmp(data, kSignature, 8) != 0) {
    return Status::Error("", "not a PNG file (no PNG signature)");
  }
  if (size > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
    return Status::Error("", "PNG of " + std::to_string(size) + " bytes; at most 2^31 - 1");
  }
  PngInfo info;
  bool have_header = false, have_data = false;
  std::size_t at = 8;
  while (true) {
    if (size - at < 12) return Status::Error("", "truncated PNG (it ends before IEND)");
    const uint32_t length = ReadBe32(data + at);
    if (length > 0x7FFFFFFFu || size - at - 12 < length) {
      return Status::Error("", "truncated PNG (a chunk runs past the end of the file)");
    }
    const unsigned char* type = data + at + 4;
    const unsigned char* body = type + 4;
    if (Crc32(type, 4 + std::size_t{length}) != ReadBe32(body + length)) {
      return Status::Error("", "corrupt PNG (CRC mismatch in a " +
                                   std::string(reinterpret_cast<const char*>(type), 4) + " chunk)");
    }
    const std::string name(reinterpret_cast<const char*>(type), 4);
    if (!have_header) {
      if (name != "IHDR" || length != 13) {
        return Status::Error("", "corrupt PNG (the first chunk is not a 13-byte IHDR)");
      }
      const uint32_t w = ReadBe32(body), h = ReadBe32(body + 4);
      info.bit_depth = body[8];
      info.colour_type = body[9];
      if (w == 0 || h == 0 || w > static_cast<uint32_t>(kMaxPngSide) ||
          h > static_cast<uint32_t>(kMaxPngSide) ||
          std::size_t{w} * std::size_t{h} > kMaxPngPixels) {
        return Status::Error("", "PNG of " + std::to_string(w) + " x " + std::to_string(h) +
                                     " pixels; width and height must be in [1, 65535] with at "
                                     "most 2^26 pixels");
      }
      info.width = static_cast<int>(w);
      info.height = static_cast<int>(h);
      have_header = true;
    } else if (name == "IDAT") {
      have_data = true;
    } else if (name == "tEXt") {
      const unsigned char* nul =
          static_cast<const unsigned char*>(std::memchr(body, 0, std::size_t{length}));
      if (nul != nullptr) {
        info.text.push_back({std::string(body, nul), std::string(nul + 1, body + length)});
      }
    } else if (name == "IEND") {
      break;
    }
    at += 12 + std::size_t{length};
  }
  if (!have_data) return Status::Error("", "corrupt PNG (no image data)");
  return info;
}

Result<Gray16Image> DecodeGray16Png(const unsigned char* data, std::size_t size, PngInfo* info) {
  Result<PngInfo> header = ReadPngInfo(data, size);
  if (!header.ok()) return header.status();
  if (!header->is_grey()) {
    return Status::Error("", "PNG colour type " + std::to_string(header->colour_type) +
                                 " is not greyscale; a heightmap must be a grey PNG (type 0 or 4)");
  }
  int w = 0, h = 0, channels = 0;
  stbi_us* samples = stbi_load_16_from_memory(data, static_cast<int>(size), &w, &h, &channels, 1);
  if (samples == nullptr) {
    return Status::Error("", std::string("corrupt PNG (") + stbi_failure_reason() + ")");
  }
  Gray16Image image;
  image.width = w;
  image.height = h;
  image.pixels.assign(samples, samples + static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  stbi_image_free(samples);
  if (info != nullptr) *info = std::move(header).value();
  return image;
}

Result<Rgba8Image> DecodeRgba8Png(const unsigned char* data, std::size_t size, PngInfo* info) {
  Result<PngInfo> header = ReadPngInfo(data, size);
  if (!header.ok()) return header.status();
  Result<Rgba8Image> image = StbDecodeRgba8(data, size, "PNG");
  if (image.ok() && info != nullptr) *info = std::move(header).value();
  return image;
}

ImageFormat SniffImageFormat(const unsigned char* data, std::size_t size) {
  if (size >= 8 && std::memcmp(data, kSignature, 8) == 0) return ImageFormat::kPng;
  if (size >= 3 && data[0] == 0xFF && data[1] == 0xD8 && data[2] == 0xFF) return ImageFormat::kJpeg;
  if (size >= 12 && std::memcmp(data, "RIFF", 4) == 0 && std::memcmp(data + 8, "WEBP", 4) == 0)
    return ImageFormat::kWebp;
  static const unsigned char kKtx2[12] = {0xAB, 'K',  'T',  'X',  ' ',  '2',
                                          '0',  0xBB, 0x0D, 0x0A, 0x1A, 0x0A};
  if (size >= 12 && std::memcmp(data, kKtx2, 12) == 0) return ImageFormat::kKtx2;
  return ImageFormat::kUnknown;
}

Result<ImageSize> ReadImageSize(const unsigned char* data, std::size_t size) {
  const ImageFormat format = SniffImageFormat(data, size);
  if (format != ImageFormat::kPng && format != ImageFormat::kJpeg) {
    return Status::Error("", "not a PNG or JPEG image");
  }
  if (format == ImageFormat::kPng) {
    // IHDR first (PNG spec 5.2, 11.2.2): its width and height as declared, read before stb_image,
    // which refuses large sizes with "too large" and no numbers.
    if (size < 8 + 8 + 13 || std::memcmp(data + 12, "IHDR", 4) != 0 || ReadBe32(data + 8) != 13) {
      return Status::Error("", "corrupt PNG (no IHDR chunk first)");
    }
    const uint32_t w = ReadBe32(data + 16), h = ReadBe32(data + 20);
    if (w > static_cast<uint32_t>(std::numeric_limits<int>::max()) ||
        h > static_cast<uint32_t>(std::numeric_limits<int>::max())) {
      return Status::Error("", "corrupt PNG (width or height over 2^31)");
    }
    return ImageSize{static_cast<int>(w), static_cast<int>(h)};
  }
  const char* kind = "JPEG";
  if (size > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
    return Status::Error("", std::string("corrupt ") + kind + " (over 2 GiB)");
  }
  int w = 0, h = 0, channels = 0;
  if (stbi_info_from_memory(data, static_cast<int>(size), &w, &h, &channels) == 0) {
    return Status::Error("", std::string("corrupt ") + kind + " (" + stbi_failure_reason() + ")");
  }
  return ImageSize{w, h};
}

Result<Rgba8Image> DecodeRgba8PngOrJpeg(const unsigned char* data, std::size_t size,
                                        std::size_t max_pixels) {
  Result<ImageSize> declared = ReadImageSize(data, size);
  if (!declared.ok()) return declared.status();
  const bool sides = declared->width >= 1 && declared->height >= 1 &&
                     declared->width <= kMaxPngSide && declared->height <= kMaxPngSide;
  if (!sides ||
      static_cast<std::size_t>(declared->width) * static_cast<std::size_t>(declared->height) >
          max_pixels) {
    return Status::Error("", std::to_string(declared->width) + " x " +
                                 std::to_string(declared->height) +
                                 " pixels; width and height must be in [1, 65535] with at most " +
                                 std::to_string(max_pixels) + " pixels");
  }
  return StbDecodeRgba8(data, size,
                        SniffImageFormat(data, size) == ImageFormat::kPng ? "PNG" : "JPEG");
}

}  // namespace niwa::image
