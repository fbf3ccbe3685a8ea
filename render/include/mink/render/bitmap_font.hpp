#pragma once

#include <cstdint>
#include <string_view>

namespace mink {

/// @brief Minkowski's own 5 x 7 pixel font for ASCII 32..126, drawn on a 6 x 9 cell (one column and
/// two rows of spacing), for labels and the on-screen overlay.
struct BitmapFont {
  static constexpr int glyph_width = 5;   ///< pixels of a glyph across
  static constexpr int glyph_height = 7;  ///< pixels of a glyph down
  static constexpr int advance = 6;       ///< pixels from one character to the next
  static constexpr int line_height = 9;   ///< pixels from one line to the next
  static constexpr char first = 32;       ///< first character drawn (space)
  static constexpr char last = 126;       ///< last character drawn ('~')

  /// @brief Row r of glyph c (r = 0 is the top), bit 4 the leftmost pixel.
  /// @throws InvalidArgumentError for a character outside first..last, or r outside 0..6.
  static std::uint8_t row(char c, int r);
  /// @brief True when pixel (x, y) of glyph c is set (y = 0 the top row); throws like row().
  static bool pixel(char c, int x, int y) { return (row(c, y) >> (glyph_width - 1 - x)) & 1u; }

  /// Size in font pixels of `text` as drawn ('\n' starts a new line): the widest line's
  /// advance and the number of lines times line_height. Throws like row() for any character
  /// other than '\n' outside first..last.
  static int text_width(std::string_view text);
  /// @brief Height in font pixels of `text`: its line count times line_height.
  static int text_height(std::string_view text);
};

}  // namespace mink
