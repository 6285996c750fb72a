// Construction and fill of the core's images.
#include "image/image.h"

#include <algorithm>

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

}  // namespace niwa::image
