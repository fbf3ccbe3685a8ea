#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace mink {

// 8-bit pixels, rows top to bottom, each row left to right, channels interleaved (RGB or
// RGBA), no padding between rows.
struct Image {
  int width = 0;
  int height = 0;
  int channels = 4;
  std::vector<std::uint8_t> pixels;

  Image() = default;
  // Zero-filled. Throws InvalidArgumentError for a negative size or channels other than 3 or 4.
  Image(int width, int height, int channels);

  // Channels of pixel (x, y), y = 0 the top row; alpha is 255 for RGB images. Throws
  // InvalidArgumentError outside the image.
  std::array<std::uint8_t, 4> at(int x, int y) const;
  bool operator==(const Image&) const = default;
};

}  // namespace mink
