// Construction and fill of the core's images.
#include "image/image.h"

#include <algorithm>
#include <cmath>

namespace niwa::image {

Rgba8Image MakeRgba8(int width, int height, unsigned char r, unsigned char g, unsigned char b,
                     unsigned char a) {
  Rgba8Image image;
  if (width <= 0 || height <= 0) return image;
  image.width = width;
  image.height = height;
  image.pixels.resize(4 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  Fill(&image, r, g, b, a);
  return image;
}

Gray16Image MakeGray16(int width, int height, uint16_t value) {
  Gray16Image image;
  if (width <= 0 || height <= 0) return image;
  image.width = width;
  image.height = height;
  image.pixels.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), value);
  return image;
}

void Fill(Rgba8Image* image, unsigned char r, unsigned char g, unsigned char b, unsigned char a) {
  for (std::size_t i = 0; i + 3 < image->pixels.size(); i += 4) {
    image->pixels[i] = r;
    image->pixels[i + 1] = g;
    image->pixels[i + 2] = b;
    image->pixels[i + 3] = a;
  }
}

void Fill(Gray16Image* image, uint16_t value) {
  std::fill(image->pixels.begin(), image->pixels.end(), value);
}

std::array<double, 3> MeanLinearRgb(const Rgba8Image& image) {
  std::array<double, 3> mean = {0, 0, 0};
  const std::size_t n = image.pixels.size() / 4;
  if (n == 0) return mean;
  double linear[256];
  for (int v = 0; v < 256; ++v) {  // the sRGB transfer function (IEC 61966-2-1)
    const double c = v / 255.0;
    linear[v] = c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
  }
  // Per-byte counts, then the sums: exact and the same in any order.
  std::array<std::array<uint64_t, 256>, 3> counts{};
  for (std::size_t p = 0; p < n; ++p)
    for (int k = 0; k < 3; ++k) ++counts[k][image.pixels[4 * p + k]];
  for (int k = 0; k < 3; ++k) {
    for (int v = 0; v < 256; ++v) mean[k] += static_cast<double>(counts[k][v]) * linear[v];
    mean[k] /= static_cast<double>(n);
  }
  return mean;
}

}  // namespace niwa::image
