// Figures 12 and 13: the transformed hulls get the right verdict, and in the drawn Minkowski
// difference the origin marker sits inside the difference's fill when the hulls overlap and
// on the background when they are apart.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mink/narrowphase/gjk_overlap.hpp"
#include "paper_figures.hpp"
#include "render_test_support.hpp"

namespace {

using mink::Vec2;
using mink_test::Headless;
using mink_test::to_rgba;

constexpr mink::Color kWhite{1, 1, 1, 1};

struct Ring {
  int fill = 0;
  int background = 0;
  int samples = 0;
};

// Pixels on a circle of `radius` pixels around `center`, by colour.
Ring ring_around(const mink::Image& image, const Vec2& center, double radius) {
  Ring ring;
  for (int k = 0; k < 72; ++k) {
    const double angle = k * 2 * std::numbers::pi / 72;
    const int x = static_cast<int>(std::floor(center.x() + radius * std::cos(angle)));
    const int y = static_cast<int>(std::floor(center.y() + radius * std::sin(angle)));
    if (x < 0 || y < 0 || x >= image.width || y >= image.height) continue;
    ++ring.samples;
    ring.fill += image.at(x, y) == to_rgba(mink::cli::kDifferenceFill);
    ring.background += image.at(x, y) == to_rgba(kWhite);
  }
  return ring;
}

class GjkFigure : public testing::TestWithParam<mink::GlBackend> {};

TEST_P(GjkFigure, OriginMarkerInsideTheDifferenceExactlyWhenTheHullsOverlap) {
  Headless frame(GetParam(), 600, 500);
  mink::cli::PaperSettings settings;
  for (const bool apart : {false, true}) {
    const mink::cli::GjkPicture picture = mink::cli::gjk_picture(settings, apart);
    // The verdict agrees with the exact edge test, and is the one asked for.
    const bool overlap = mink::hulls_overlap_exact(picture.hull_a, picture.hull_b);
    EXPECT_EQ(overlap, !apart);
    EXPECT_EQ(picture.gjk.overlap, overlap);
    frame.renderer->begin_frame(kWhite);
    mink::cli::draw_difference_panel(*frame.renderer, 1, 0, picture);
    frame.renderer->end_frame();
    const mink::Image image = frame.renderer->read_pixels();
    const Vec2 origin = frame.renderer->camera().world_to_pixel(Vec2(0, 0));
    ASSERT_GE(origin.x(), 0);
    ASSERT_GE(origin.y(), 0);
    ASSERT_LT(origin.x(), image.width);
    ASSERT_LT(origin.y(), image.height);
    // The marker is drawn at the origin...
    EXPECT_EQ(image.at(static_cast<int>(origin.x()), static_cast<int>(origin.y())),
              to_rgba(mink::cli::kOriginMarker))
        << (apart ? "apart" : "overlapping");
    // ...and just around it is the difference's fill, or the background. The simplex's edges
    // may cross the ring, so most (not all) samples must agree.
    const Ring ring = ring_around(image, origin, mink::cli::kOriginMarkerPixels / 2 + 4);
    ASSERT_GT(ring.samples, 60);
    if (apart) {
      EXPECT_EQ(ring.fill, 0);
      EXPECT_GT(ring.background, ring.samples * 3 / 4);
    } else {
      EXPECT_EQ(ring.background, 0);
      EXPECT_GT(ring.fill, ring.samples * 3 / 4);
    }
    // The difference really is drawn: its fill covers a good part of the frame.
    const int fill = mink_test::count_pixels(image, to_rgba(mink::cli::kDifferenceFill));
    EXPECT_GT(fill, image.width * image.height / 20);
  }
}

TEST(GjkFigure, FinalSimplexContainsTheOriginWhenOverlapping) {
  const mink::cli::GjkPicture picture = mink::cli::gjk_picture(mink::cli::PaperSettings{}, false);
  ASSERT_EQ(picture.simplex.count, 3);
  // The origin is on the inner side of every edge of the CCW-or-CW triangle.
  const auto& v = picture.simplex.vertices;
  const auto cross = [](const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); };
  const double s0 = cross(v[1].point - v[0].point, -v[0].point);
  const double s1 = cross(v[2].point - v[1].point, -v[1].point);
  const double s2 = cross(v[0].point - v[2].point, -v[2].point);
  EXPECT_TRUE((s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0));
  // Every simplex vertex is a difference of the hulls' vertices it names.
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(v[i].point, picture.hull_a[v[i].index_a] - picture.hull_b[v[i].index_b]);
  }
}

INSTANTIATE_TEST_SUITE_P(Backends, GjkFigure,
                         testing::Values(mink::GlBackend::osmesa, mink::GlBackend::egl),
                         mink_test::backend_name);

}  // namespace
