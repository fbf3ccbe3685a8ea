#pragma once

#include <cstdint>
#include <string_view>

namespace mink {

// Minkowski's own 5 x 7 pixel font for ASCII 32..126, drawn on a 6 x 9 cell (one column and
// two rows of spacing), for labels and the on-screen overlay.
struct BitmapFont {
  static constexpr int glyph_width = 5;
  static constexpr int glyph_height = 7;
  static constexpr int advance = 6;
  static constexpr int line_height = 9;
  static constexpr char first = 32;
  static constexpr char last = 126;

  // Row r of glyph c (r = 0 is the top), bit 4 the leftmost pixel. Throws
  // InvalidArgumentError for a character outside first..last, or r outside 0..6.
  static std::uint8_t row(char c, int r);
  static bool pixel(char c, int x, int y) { return (row(c, y) >> (glyph_width - 1 - x)) & 1u; }

  // Size in font pixels of `text` as drawn ('\n' starts a new line): the widest line's
  // advance and the number of lines times line_height. Throws like row() for any character
  // other than '\n' outside first..last.
  static int text_width(std::string_view text);
  static int text_height(std::string_view text);
};

}  // namespace mink
