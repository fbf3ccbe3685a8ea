// The renderer's fills against the slow, obviously correct twin: a pixel is inside a convex
// polygon when its centre is left of every edge. Pixels within a pixel of an edge may go
// either way (rasterisation rules, float rounding) and are not compared.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "mink/geometry/convex_hull.hpp"
#include "mink/geometry/point_sets.hpp"
#include "render_test_support.hpp"

namespace {

using mink::Vec2;
using mink_test::to_rgba;

enum class Coverage { inside, outside, edge };

// Classifies a pixel centre against a CCW polygon given in pixel coordinates with y down (so
// the polygon winds clockwise numerically): signed distances to every edge line.
Coverage classify(const std::vector<Vec2>& polygon, const Vec2& centre) {
  double nearest = INFINITY;
  bool inside = true;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec2& a = polygon[i];
    const Vec2& b = polygon[(i + 1) % polygon.size()];
    const Vec2 edge = b - a;
    // Positive on the interior side for a numerically clockwise ring.
    const double distance =
        (edge.x() * (centre.y() - a.y()) - edge.y() * (centre.x() - a.x())) / edge.norm() * -1.0;
    inside &= distance > 0;
    nearest = std::min(nearest, std::abs(distance));
  }
  if (nearest < 1.0) return Coverage::edge;
  return inside ? Coverage::inside : Coverage::outside;
}

class RasterOracleTest : public testing::TestWithParam<mink::GlBackend> {};

TEST_P(RasterOracleTest, FilledHullsCoverExactlyTheirInteriorPixels) {
  mink_test::Headless frame(GetParam(), 128, 96);
  mink::Renderer& r = *frame.renderer;
  r.camera().fit(Vec2(-1.2, -1.2), Vec2(1.2, 1.2), 4);
  const mink::Color background{0, 0, 0, 1};
  const mink::Color fill{0.2f, 0.8f, 0.4f, 1};
  const int cases = 12;
  long compared = 0;
  for (int seed = 0; seed < cases; ++seed) {
    const auto points = mink::generate_points(mink::PointDistribution::uniform_disk,
                                              6 + static_cast<std::size_t>(seed) * 5,
                                              static_cast<std::uint64_t>(seed) + 100);
    const mink::ConvexHull hull = mink::build_hull(points, mink::HullAlgorithm::graham);
    r.begin_frame(background);
    r.draw_polygon(hull.vertices(), fill, mink::Color{0, 0, 0, 0});
    r.end_frame();
    const mink::Image image = r.read_pixels();
    std::vector<Vec2> on_screen;
    for (const Vec2& v : hull.vertices()) on_screen.push_back(r.camera().world_to_pixel(v));
    for (int y = 0; y < image.height; ++y) {
      for (int x = 0; x < image.width; ++x) {
        const Coverage expected = classify(on_screen, Vec2(x + 0.5, y + 0.5));
        if (expected == Coverage::edge) continue;
        ++compared;
        ASSERT_EQ(image.at(x, y), to_rgba(expected == Coverage::inside ? fill : background))
            << "seed " << seed << ", pixel " << x << ", " << y;
      }
    }
  }
  EXPECT_GT(compared, cases * 128 * 96 * 8 / 10);
}

// The two-fan drawing of opaque outlined polygons against the band it replaces.
TEST_P(RasterOracleTest, OpaqueOutlineFastPathPaintsTheSamePixelsAsTheBand) {
  mink::RendererOptions slow_options;
  slow_options.opaque_outline_fast_path = false;
  slow_options.line_width_pixels = 3;
  mink::RendererOptions fast_options = slow_options;
  fast_options.opaque_outline_fast_path = true;
  mink_test::Headless slow(GetParam(), 160, 120, slow_options);
  mink_test::Headless fast(GetParam(), 160, 120, fast_options);
  const auto draw = [](mink::Renderer& r, int seed) {
    r.camera().fit(Vec2(-1.2, -1.2), Vec2(1.2, 1.2), 4);
    r.begin_frame(mink::Color{0, 0, 0, 1});
    // Hulls from large to smaller than the line width, so both branches of the fast path run.
    for (int k = 0; k < 6; ++k) {
      const double scale = std::pow(0.45, k);
      auto points = mink::generate_points(mink::PointDistribution::uniform_disk, 12,
                                          static_cast<std::uint64_t>(seed * 10 + k));
      for (Vec2& p : points) p = p * scale + Vec2(-0.6 + 0.3 * k, 0.2 * (k % 3) - 0.2);
      const mink::ConvexHull hull = mink::build_hull(points, mink::HullAlgorithm::graham);
      r.draw_polygon(hull.vertices(), mink::Color{0.9f, 0.6f, 0.2f, 1},
                     mink::Color{0.2f, 0.3f, 1, 1});
    }
    r.end_frame();
    return r.read_pixels();
  };
  for (int seed = 0; seed < 10; ++seed) {
    const mink::Image expected = draw(*slow.renderer, seed);
    const mink::Image actual = draw(*fast.renderer, seed);
    EXPECT_LT(fast.renderer->triangle_count(), slow.renderer->triangle_count());
    int differing = 0;
    for (int y = 0; y < expected.height; ++y) {
      for (int x = 0; x < expected.width; ++x) differing += expected.at(x, y) != actual.at(x, y);
    }
    EXPECT_EQ(differing, 0) << "seed " << seed;
  }
}

INSTANTIATE_TEST_SUITE_P(Backends, RasterOracleTest,
                         testing::Values(mink::GlBackend::osmesa, mink::GlBackend::egl),
                         mink_test::backend_name);

}  // namespace
