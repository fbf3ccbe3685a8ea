#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace mink {

/// @brief An 8-bit image in memory.
/// 8-bit pixels, rows top to bottom, each row left to right, channels interleaved (RGB or
/// RGBA), no padding between rows.
struct Image {
  int width = 0;                     ///< pixels
  int height = 0;                    ///< pixels
  int channels = 4;                  ///< 3 (RGB) or 4 (RGBA)
  std::vector<std::uint8_t> pixels;  ///< width * height * channels bytes

  /// @brief An empty 0 x 0 image.
  Image() = default;
  /// @brief A zero-filled image.
  /// @throws InvalidArgumentError for a negative size or channels other than 3 or 4.
  Image(int width, int height, int channels);

  /// @brief Channels of pixel (x, y), y = 0 the top row; alpha is 255 for RGB images.
  /// @throws InvalidArgumentError outside the image.
  std::array<std::uint8_t, 4> at(int x, int y) const;
  bool operator==(const Image&) const = default;
};

}  // namespace mink
