// Images of the core: Rgba8Image (textures) and Gray16Image (heightmaps), row-major, row 0 first.
// Does not: encode or decode files (image/png.h), resample, or know what the pixels mean (a tree's
// bark, a terrain's height); no GL, no JS.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace niwa::image {

// RGBA, 8 bits per channel, 4 bytes per pixel; row 0 is the top row (glTF texture v = 0).
struct Rgba8Image {
  int width = 0;
  int height = 0;
  std::vector<unsigned char> pixels;  // 4 * width * height bytes

  // Pixel (x, y): 4 bytes r, g, b, a. No bounds check (as operator[]).
  const unsigned char* At(int x, int y) const { return pixels.data() + 4 * Offset(x, y); }
  unsigned char* At(int x, int y) { return pixels.data() + 4 * Offset(x, y); }
  bool empty() const { return width <= 0 || height <= 0; }
  // True when the pixel buffer holds exactly width * height pixels.
  bool consistent() const {
    return width >= 0 && height >= 0 &&
           pixels.size() == 4 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  }
  std::size_t Offset(int x, int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
           static_cast<std::size_t>(x);
  }
};

// Greyscale, 16 bits per sample (0..65535), one sample per pixel; row 0 is the top row (for a
// terrain heightmap: north).
struct Gray16Image {
  int width = 0;
  int height = 0;
  std::vector<uint16_t> pixels;  // width * height samples

  uint16_t At(int x, int y) const { return pixels[Offset(x, y)]; }
  uint16_t& At(int x, int y) { return pixels[Offset(x, y)]; }
  bool empty() const { return width <= 0 || height <= 0; }
  bool consistent() const {
    return width >= 0 && height >= 0 &&
           pixels.size() == static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  }
  std::size_t Offset(int x, int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
           static_cast<std::size_t>(x);
  }
};

// A width × height image filled with one colour / value (empty when width or height <= 0).
Rgba8Image MakeRgba8(int width, int height, unsigned char r = 0, unsigned char g = 0,
                     unsigned char b = 0, unsigned char a = 255);
Gray16Image MakeGray16(int width, int height, uint16_t value = 0);

// Sets every pixel.
void Fill(Rgba8Image* image, unsigned char r, unsigned char g, unsigned char b, unsigned char a);
void Fill(Gray16Image* image, uint16_t value);

// The mean colour of an sRGB image's pixels (alpha aside) in linear values (the sRGB transfer
// function per byte, then the mean): what a renderer sampling it as an sRGB texture averages to.
// {0, 0, 0} for an empty image.
std::array<double, 3> MeanLinearRgb(const Rgba8Image& image);

}  // namespace niwa::image
