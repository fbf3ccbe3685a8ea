#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <vector>

#include "mink/error.hpp"
#include "mink/render/bitmap_font.hpp"
#include "mink/render/png_file.hpp"
#include "mink/render/render_error.hpp"
#include "render_test_support.hpp"

namespace {

using mink::Color;
using mink::GlBackend;
using mink::Vec2;
using mink_test::describe;
using mink_test::Headless;
using mink_test::Rgba;
using mink_test::to_rgba;

// Channels that are whole multiples of 1/255, so GL's conversion and ours agree exactly.
constexpr Color kBackground{0.2f, 0.4f, 0.6f, 1};
constexpr Color kRed{1, 0, 0, 1};
constexpr Color kGreen{0, 1, 0, 1};
constexpr Color kWhite{1, 1, 1, 1};
constexpr Color kNone{0, 0, 0, 0};

Rgba pixel(const mink::Image& image, const Vec2& at) {
  return image.at(static_cast<int>(std::floor(at.x())), static_cast<int>(std::floor(at.y())));
}

class RendererTest : public testing::TestWithParam<GlBackend> {
 protected:
  // A 160 x 120 frame looking at the world box [0, 16] x [0, 12] with no margin: 10 pixels
  // per unit, world (0, 12) at the top-left corner.
  RendererTest() : frame_(GetParam(), 160, 120) {
    renderer().camera().fit(Vec2(0, 0), Vec2(16, 12), 0);
  }
  mink::Renderer& renderer() { return *frame_.renderer; }
  mink::Image draw(auto&& drawing) {
    renderer().begin_frame(kBackground);
    drawing(renderer());
    renderer().end_frame();
    return renderer().read_pixels();
  }

  Headless frame_;
};

TEST_P(RendererTest, ClearsEveryPixelToTheBackground) {
  const mink::Image image = draw([](mink::Renderer&) {});
  ASSERT_EQ(image.width, 160);
  ASSERT_EQ(image.height, 120);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      ASSERT_EQ(image.at(x, y), to_rgba(kBackground)) << "pixel " << x << ", " << y;
    }
  }
}

TEST_P(RendererTest, FillsAPolygonWithItsColourAtTheCentre) {
  const std::vector<Vec2> square = {{4, 3}, {8, 3}, {8, 7}, {4, 7}};
  const mink::Image image = draw([&](mink::Renderer& r) { r.draw_polygon(square, kRed, kGreen); });
  const Vec2 centre = renderer().camera().world_to_pixel(Vec2(6, 5));
  EXPECT_EQ(pixel(image, centre), to_rgba(kRed)) << describe(pixel(image, centre));
  // The outline is centred on the boundary: the pixel just inside the left edge is green.
  const Vec2 edge = renderer().camera().world_to_pixel(Vec2(4, 5)) + Vec2(0.5, 0);
  EXPECT_EQ(pixel(image, edge), to_rgba(kGreen));
  // Outside, a few pixels away, the background.
  EXPECT_EQ(pixel(image, renderer().camera().world_to_pixel(Vec2(3, 5))), to_rgba(kBackground));
  EXPECT_EQ(pixel(image, renderer().camera().world_to_pixel(Vec2(6, 8))), to_rgba(kBackground));
}

TEST_P(RendererTest, ClockwisePolygonsFillAndOutlineTheSame) {
  const std::vector<Vec2> ccw = {{4, 3}, {8, 3}, {8, 7}, {4, 7}};
  const std::vector<Vec2> cw(ccw.rbegin(), ccw.rend());
  const mink::Image a = draw([&](mink::Renderer& r) { r.draw_polygon(ccw, kRed, kGreen); });
  const mink::Image b = draw([&](mink::Renderer& r) { r.draw_polygon(cw, kRed, kGreen); });
  EXPECT_TRUE(a == b);
}

TEST_P(RendererTest, DrawsASegmentsPixelsAndNothingBeside) {
  // A horizontal segment along y = 6: pixel row 60 and 59 (2 pixels wide, centred on y=60).
  const mink::Image image =
      draw([](mink::Renderer& r) { r.draw_segment(Vec2(2, 6), Vec2(14, 6), kWhite); });
  for (int x = 25; x < 135; ++x) {
    ASSERT_EQ(image.at(x, 59), to_rgba(kWhite)) << "x = " << x;
    ASSERT_EQ(image.at(x, 60), to_rgba(kWhite)) << "x = " << x;
    ASSERT_EQ(image.at(x, 58), to_rgba(kBackground)) << "x = " << x;
    ASSERT_EQ(image.at(x, 61), to_rgba(kBackground)) << "x = " << x;
  }
  EXPECT_EQ(image.at(10, 60), to_rgba(kBackground));   // before the start at x = 20
  EXPECT_EQ(image.at(150, 60), to_rgba(kBackground));  // after the end at x = 140
}

TEST_P(RendererTest, SomethingAtTheTopOfTheWorldIsInTheTopRowsOfTheImageAndPng) {
  // A bar across the top unit of the world (y from 11 to 12): pixel rows 0..9.
  const std::vector<Vec2> bar = {{0, 11}, {16, 11}, {16, 12}, {0, 12}};
  const mink::Image image = draw([&](mink::Renderer& r) { r.draw_polygon(bar, kRed, kNone); });
  for (int y : {0, 5, 9}) EXPECT_EQ(image.at(80, y), to_rgba(kRed)) << "row " << y;
  for (int y : {10, 60, 119}) EXPECT_EQ(image.at(80, y), to_rgba(kBackground)) << "row " << y;
  // And the PNG keeps that order.
  const auto path =
      mink_test::temp_path("mink_row_order_" + std::string(mink::to_string(GetParam())) + ".png");
  mink::write_png(path, image);
  const mink::Image read = mink::read_png(path);
  std::filesystem::remove(path);
  EXPECT_EQ(read.at(80, 0), to_rgba(kRed));
  EXPECT_EQ(read.at(80, 119), to_rgba(kBackground));
  EXPECT_TRUE(read == image);
}

TEST_P(RendererTest, RgbReadbackMatchesRgba) {
  const std::vector<Vec2> triangle = {{1, 1}, {15, 2}, {7, 11}};
  const mink::Image rgba = draw([&](mink::Renderer& r) { r.draw_polygon(triangle, kRed, kWhite); });
  const mink::Image rgb = renderer().read_pixels(3);
  ASSERT_EQ(rgb.channels, 3);
  for (int y = 0; y < rgb.height; y += 7) {
    for (int x = 0; x < rgb.width; x += 5) {
      const Rgba a = rgba.at(x, y);
      const Rgba b = rgb.at(x, y);
      ASSERT_EQ((Rgba{a[0], a[1], a[2], 255}), b);
    }
  }
}

TEST_P(RendererTest, TextOverlayLightsExactlyTheGlyphPixels) {
  const std::string text = "step 12\nt=0.20s";
  const mink::Image image = draw([&](mink::Renderer& r) { r.draw_overlay(text, kWhite); });
  long expected = 0;
  for (char c : text) {
    if (c == '\n') continue;
    for (int y = 0; y < mink::BitmapFont::glyph_height; ++y) {
      for (int x = 0; x < mink::BitmapFont::glyph_width; ++x) {
        expected += mink::BitmapFont::pixel(c, x, y) ? 1 : 0;
      }
    }
  }
  const int scale = renderer().options().text_scale;
  expected *= scale * scale;
  long white = 0;
  int lowest_row = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      if (image.at(x, y) == to_rgba(kWhite)) {
        ++white;
        lowest_row = y;
      }
    }
  }
  EXPECT_GT(expected, 100);
  EXPECT_EQ(white, expected);
  // Two lines at the top-left: nothing below the second line.
  EXPECT_LT(lowest_row, 2 * mink::BitmapFont::line_height * scale + 3 * scale);
  // The backing darkens the background behind the text.
  const Rgba backing = image.at(1, 1);
  EXPECT_LT(backing[2], to_rgba(kBackground)[2]);
  EXPECT_EQ(image.at(159, 119), to_rgba(kBackground));
}

TEST_P(RendererTest, TranslucentFillBlendsOverWhatIsBelow) {
  const std::vector<Vec2> square = {{4, 3}, {8, 3}, {8, 7}, {4, 7}};
  const mink::Image image = draw([&](mink::Renderer& r) {
    r.draw_polygon(square, Color{1, 1, 1, 0.5f}, kNone);
  });
  const Rgba p = pixel(image, renderer().camera().world_to_pixel(Vec2(6, 5)));
  const Rgba b = to_rgba(kBackground);
  for (int c = 0; c < 3; ++c) {
    const double expected = b[static_cast<std::size_t>(c)] * 0.5 + 255 * 0.5;
    EXPECT_NEAR(p[static_cast<std::size_t>(c)], expected, 1.5) << "channel " << c;
  }
  EXPECT_EQ(p[3], 255);
}

TEST_P(RendererTest, LaterCallsPaintOverEarlierOnes) {
  const std::vector<Vec2> big = {{2, 2}, {14, 2}, {14, 10}, {2, 10}};
  const std::vector<Vec2> small = {{6, 4}, {10, 4}, {10, 8}, {6, 8}};
  const mink::Image image = draw([&](mink::Renderer& r) {
    r.draw_polygon(big, kRed, kNone);
    r.draw_polygon(small, kGreen, kNone);
  });
  EXPECT_EQ(pixel(image, renderer().camera().world_to_pixel(Vec2(8, 6))), to_rgba(kGreen));
  EXPECT_EQ(pixel(image, renderer().camera().world_to_pixel(Vec2(3, 3))), to_rgba(kRed));
}

TEST_P(RendererTest, PointsAndCirclesLandWhereTheCameraPutsThem) {
  const mink::Image image = draw([](mink::Renderer& r) {
    r.draw_point(Vec2(3, 3), 8, kGreen);
    r.draw_circle(Vec2(10, 6), 3, kWhite);
  });
  EXPECT_EQ(pixel(image, renderer().camera().world_to_pixel(Vec2(3, 3))), to_rgba(kGreen));
  // The circle is a ring: its rim is white, its centre is not.
  EXPECT_EQ(pixel(image, renderer().camera().world_to_pixel(Vec2(13, 6)) - Vec2(0.5, 0.5)),
            to_rgba(kWhite));
  EXPECT_EQ(pixel(image, renderer().camera().world_to_pixel(Vec2(10, 9)) + Vec2(0.5, 0.5)),
            to_rgba(kWhite));
  EXPECT_EQ(pixel(image, renderer().camera().world_to_pixel(Vec2(10, 6))), to_rgba(kBackground));
}

TEST_P(RendererTest, WorldLabelsDrawAtTheirAnchor) {
  const mink::Image image = draw([](mink::Renderer& r) { r.draw_text(Vec2(8, 6), "H", kWhite); });
  // 'H' has its left column lit on every row; the anchor is at pixel (80, 60), the glyph
  // centred on it vertically: rows 53..66 at text scale 2.
  EXPECT_EQ(image.at(80, 55), to_rgba(kWhite));
  EXPECT_EQ(image.at(81, 65), to_rgba(kWhite));
  EXPECT_EQ(image.at(78, 60), to_rgba(kBackground));
  EXPECT_EQ(image.at(80, 50), to_rgba(kBackground));
}

TEST_P(RendererTest, RejectsBadInputNamingIt) {
  mink::Renderer& r = renderer();
  r.begin_frame(kBackground);
  const std::vector<Vec2> two = {{0, 0}, {1, 1}};
  EXPECT_THROW(r.draw_polygon(two, kRed, kRed), mink::InvalidArgumentError);
  const std::vector<Vec2> bad = {{0, 0}, {1, 0}, {1, NAN}};
  try {
    r.draw_polygon(bad, kRed, kRed);
    FAIL() << "a NaN vertex was accepted";
  } catch (const mink::NonFiniteInputError& error) {
    EXPECT_EQ(error.index(), 2u);
  }
  EXPECT_THROW(r.draw_segment(Vec2(0, 0), Vec2(1, 1), Color{2, 0, 0, 1}),
               mink::InvalidArgumentError);
  EXPECT_THROW(r.draw_point(Vec2(0, 0), -1, kRed), mink::InvalidArgumentError);
  EXPECT_THROW(r.draw_circle(Vec2(0, 0), INFINITY, kRed), mink::InvalidArgumentError);
  EXPECT_THROW(r.draw_text(Vec2(0, 0), "tab\there", kRed), mink::InvalidArgumentError);
  EXPECT_THROW(r.read_pixels(2), mink::InvalidArgumentError);
  // Nothing was recorded by the failed calls.
  EXPECT_EQ(r.triangle_count(), 0u);
}

TEST_P(RendererTest, MultisampledFramesKeepInteriorColours) {
  mink::RendererOptions options;
  options.samples = 4;
  Headless smooth(GetParam(), 160, 120, options);
  smooth.renderer->camera().fit(Vec2(0, 0), Vec2(16, 12), 0);
  const std::vector<Vec2> square = {{4, 3}, {8, 3}, {8, 7}, {4, 7}};
  smooth.renderer->begin_frame(kBackground);
  smooth.renderer->draw_polygon(square, kRed, kNone);
  smooth.renderer->end_frame();
  const mink::Image image = smooth.renderer->read_pixels();
  EXPECT_EQ(image.at(60, 50), to_rgba(kRed));
  EXPECT_EQ(image.at(10, 10), to_rgba(kBackground));
  // An edge pixel half covered is a blend, not either colour: the samples were resolved.
  const Vec2 slanted[] = {{2, 2}, {14, 3}, {8, 11}};
  smooth.renderer->begin_frame(kBackground);
  smooth.renderer->draw_polygon(slanted, kWhite, kNone);
  smooth.renderer->end_frame();
  const mink::Image soft = smooth.renderer->read_pixels();
  int blended = 0;
  for (int y = 0; y < soft.height; ++y) {
    for (int x = 0; x < soft.width; ++x) {
      const Rgba p = soft.at(x, y);
      if (p != to_rgba(kWhite) && p != to_rgba(kBackground)) ++blended;
    }
  }
  EXPECT_GT(blended, 50);
}

INSTANTIATE_TEST_SUITE_P(Backends, RendererTest, testing::Values(GlBackend::osmesa, GlBackend::egl),
                         mink_test::backend_name);

// A scene with every kind of draw call, for comparing the backends.
mink::Image reference_scene(GlBackend backend) {
  Headless frame(backend, 200, 150);
  mink::Renderer& r = *frame.renderer;
  r.camera().fit(Vec2(-5, -4), Vec2(5, 4), 10);
  r.begin_frame(kBackground);
  const std::vector<Vec2> hexagon = {{-3, -1}, {-1, -3}, {2, -2.5}, {3, 0}, {1, 2.5}, {-2, 2}};
  r.draw_polygon(hexagon, Color{0.9f, 0.5f, 0.1f, 0.7f}, kWhite);
  r.draw_segment(Vec2(-4, -3), Vec2(4, 3.5), kGreen);
  r.draw_circle(Vec2(2, 1), 1.5, Color{0.2f, 0.6f, 1, 1});
  r.draw_point(Vec2(0, 0), 6, kRed);
  r.draw_text(Vec2(-4.5, 3.5), "GJK: overlap", kWhite);
  r.draw_overlay("step 7");
  r.end_frame();
  return r.read_pixels();
}

TEST(BackendAgreement, OsMesaAndEglDrawTheSameImage) {
  // Both run Mesa's llvmpipe rasteriser here, so the images agree to the bit.
  const mink::Image osmesa = reference_scene(GlBackend::osmesa);
  const mink::Image egl = reference_scene(GlBackend::egl);
  ASSERT_EQ(osmesa.pixels.size(), egl.pixels.size());
  std::size_t differing = 0;
  for (std::size_t i = 0; i < osmesa.pixels.size(); ++i)
    differing += osmesa.pixels[i] != egl.pixels[i];
  EXPECT_EQ(differing, 0u);
}

TEST(GlBackendNames, ParseAndPrintRoundTrip) {
  for (GlBackend backend : mink::all_gl_backends()) {
    EXPECT_EQ(mink::parse_gl_backend(mink::to_string(backend)), backend);
  }
  try {
    mink::parse_gl_backend("vulkan");
    FAIL() << "an unknown backend was accepted";
  } catch (const mink::InvalidArgumentError& error) {
    EXPECT_NE(std::string(error.what()).find("vulkan"), std::string::npos);
  }
}

TEST(OffscreenContext, RejectsImpossibleSizes) {
  EXPECT_THROW(mink::make_offscreen_context(GlBackend::osmesa, 0, 10), mink::InvalidArgumentError);
  EXPECT_THROW(mink::make_offscreen_context(GlBackend::egl, 10, 20000), mink::InvalidArgumentError);
}

}  // namespace
