#include "mink/render/image.hpp"

#include <string>

#include "mink/error.hpp"

namespace mink {

Image::Image(int width_pixels, int height_pixels, int channel_count)
    : width(width_pixels), height(height_pixels), channels(channel_count) {
  if (width_pixels < 0 || height_pixels < 0) {
    throw InvalidArgumentError("image size " + std::to_string(width_pixels) + " x " +
                               std::to_string(height_pixels) + " is negative");
  }
  if (channel_count != 3 && channel_count != 4) {
    throw InvalidArgumentError("image channels " + std::to_string(channel_count) +
                               " must be 3 (RGB) or 4 (RGBA)");
  }
  pixels.assign(static_cast<std::size_t>(width_pixels) * static_cast<std::size_t>(height_pixels) *
                    static_cast<std::size_t>(channel_count),
                0);
}

std::array<std::uint8_t, 4> Image::at(int x, int y) const {
  if (x < 0 || y < 0 || x >= width || y >= height) {
    throw InvalidArgumentError("pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                               ") is outside the " + std::to_string(width) + " x " +
                               std::to_string(height) + " image");
  }
  const std::size_t offset = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                              static_cast<std::size_t>(x)) *
                             static_cast<std::size_t>(channels);
  return {pixels[offset], pixels[offset + 1], pixels[offset + 2],
          channels == 4 ? pixels[offset + 3] : std::uint8_t{255}};
}

}  // namespace mink
