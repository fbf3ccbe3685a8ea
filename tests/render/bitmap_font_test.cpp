#include "mink/render/bitmap_font.hpp"

#include <gtest/gtest.h>

#include <array>
#include <set>

#include "mink/error.hpp"

namespace {

using mink::BitmapFont;

std::array<std::uint8_t, 7> glyph(char c) {
  std::array<std::uint8_t, 7> rows{};
  for (int r = 0; r < BitmapFont::glyph_height; ++r)
    rows[static_cast<std::size_t>(r)] = BitmapFont::row(c, r);
  return rows;
}

TEST(BitmapFont, EveryPrintableCharacterHasItsOwnGlyph) {
  std::set<std::array<std::uint8_t, 7>> seen;
  for (char c = BitmapFont::first; c <= BitmapFont::last; ++c) {
    const auto rows = glyph(c);
    for (std::uint8_t row : rows) EXPECT_LT(row, 32) << "glyph '" << c << "' is wider than 5";
    int lit = 0;
    for (std::uint8_t row : rows) lit += __builtin_popcount(row);
    if (c == ' ') {
      EXPECT_EQ(lit, 0);
    } else {
      EXPECT_GT(lit, 0) << "glyph '" << c << "' is empty";
    }
    EXPECT_TRUE(seen.insert(rows).second) << "glyph '" << c << "' repeats an earlier one";
  }
  EXPECT_EQ(seen.size(), 95u);
}

TEST(BitmapFont, GlyphsLookLikeTheirLetters) {
  // 'T': a full top bar, then the middle column alone.
  EXPECT_EQ(BitmapFont::row('T', 0), 0b11111);
  for (int r = 1; r < 7; ++r) EXPECT_EQ(BitmapFont::row('T', r), 0b00100);
  // 'L': the left column, then a full bottom bar.
  for (int r = 0; r < 6; ++r) EXPECT_EQ(BitmapFont::row('L', r), 0b10000);
  EXPECT_EQ(BitmapFont::row('L', 6), 0b11111);
  EXPECT_TRUE(BitmapFont::pixel('L', 0, 0));
  EXPECT_FALSE(BitmapFont::pixel('L', 4, 0));
}

TEST(BitmapFont, MeasuresTextInFontPixels) {
  EXPECT_EQ(BitmapFont::text_width(""), 0);
  EXPECT_EQ(BitmapFont::text_height(""), 0);
  EXPECT_EQ(BitmapFont::text_width("abc"), 18);
  EXPECT_EQ(BitmapFont::text_width("abc\nde\nfghi"), 24);
  EXPECT_EQ(BitmapFont::text_height("abc\nde\nfghi"), 27);
}

TEST(BitmapFont, RejectsCharactersItHasNoGlyphFor) {
  EXPECT_THROW(BitmapFont::row('\t', 0), mink::InvalidArgumentError);
  EXPECT_THROW(BitmapFont::row(static_cast<char>(127), 0), mink::InvalidArgumentError);
  EXPECT_THROW(BitmapFont::row(static_cast<char>(-61), 0), mink::InvalidArgumentError);
  EXPECT_THROW(BitmapFont::row('A', 7), mink::InvalidArgumentError);
  EXPECT_THROW(BitmapFont::text_width("caf\xc3\xa9"), mink::InvalidArgumentError);
}

}  // namespace
