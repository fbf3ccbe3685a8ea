#include "mink/render/png_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "mink/error.hpp"
#include "mink/render/render_error.hpp"
#include "render_test_support.hpp"

namespace {

using mink_test::temp_path;

mink::Image pattern(int width, int height, int channels) {
  mink::Image image(width, height, channels);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    image.pixels[i] = static_cast<std::uint8_t>((i * 2654435761u) >> 13);
  }
  return image;
}

TEST(PngFile, RgbaRoundTripsExactly) {
  const mink::Image image = pattern(37, 21, 4);
  const auto path = temp_path("mink_rgba.png");
  mink::write_png(path, image);
  const mink::Image read = mink::read_png(path);
  std::filesystem::remove(path);
  EXPECT_TRUE(read == image);
}

TEST(PngFile, RgbReadsBackOpaque) {
  const mink::Image image = pattern(8, 5, 3);
  const auto path = temp_path("mink_rgb.png");
  mink::write_png(path, image);
  const mink::Image read = mink::read_png(path);
  std::filesystem::remove(path);
  ASSERT_EQ(read.channels, 4);
  ASSERT_EQ(read.width, 8);
  ASSERT_EQ(read.height, 5);
  for (int y = 0; y < 5; ++y) {
    for (int x = 0; x < 8; ++x) EXPECT_EQ(read.at(x, y), image.at(x, y));
  }
}

TEST(PngFile, ReportsFilesItCannotWriteOrRead) {
  const mink::Image image = pattern(4, 4, 4);
  try {
    mink::write_png("/nonexistent-directory/out.png", image);
    FAIL() << "wrote into a missing directory";
  } catch (const mink::OutputError& error) {
    EXPECT_NE(std::string(error.what()).find("/nonexistent-directory/out.png"), std::string::npos);
  }
  EXPECT_THROW(mink::read_png(temp_path("mink_missing.png")), mink::OutputError);
  const auto not_png = temp_path("mink_not.png");
  std::ofstream(not_png) << "plain text";
  EXPECT_THROW(mink::read_png(not_png), mink::OutputError);
  std::filesystem::remove(not_png);
  mink::Image broken = image;
  broken.pixels.pop_back();
  EXPECT_THROW(mink::write_png(temp_path("mink_broken.png"), broken), mink::InvalidArgumentError);
}

}  // namespace
