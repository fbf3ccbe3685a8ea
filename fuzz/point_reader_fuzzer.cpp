// The point reader of `mink hull` on any bytes: it returns points or throws ParseError, never
// anything else. What it reads is hulled by every algorithm, with and without the
// Akl-Toussaint prefilter; all of them must give the same canonical hull (or the same typed
// error), a strictly convex one that contains every point read.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <span>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "mink/error.hpp"
#include "mink/geometry/convex_hull.hpp"
#include "mink/geometry/orientation.hpp"
#include "point_reader.hpp"

namespace {

[[noreturn]] void fail(const char* what) {
  std::fprintf(stderr, "fuzz_point_reader: %s\n", what);
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // Hulls cost n log n per algorithm; big inputs only slow the search down.
  if (size > 4096) return 0;
  std::istringstream input(std::string(reinterpret_cast<const char*>(data), size));
  std::vector<mink::Vec2> points;
  try {
    points = mink::cli::read_points(input);
  } catch (const mink::cli::ParseError&) {
    return 0;
  }
  for (const mink::Vec2& p : points) {
    if (!std::isfinite(p.x()) || !std::isfinite(p.y())) fail("a non-finite point was read");
  }

  std::optional<mink::ConvexHull> first;
  std::optional<std::string> first_error;
  bool have_first = false;
  for (const bool prefilter : {false, true}) {
    for (const mink::HullAlgorithm algorithm : mink::all_hull_algorithms()) {
      mink::HullOptions options;
      options.prefilter = prefilter;
      std::optional<mink::ConvexHull> hull;
      std::optional<std::string> error;
      try {
        hull = mink::build_hull(points, algorithm, options);
      } catch (const mink::DegenerateInputError&) {
        error = "degenerate";
      } catch (const mink::NonFiniteInputError&) {
        error = "non-finite";
      }
      if (!have_first) {
        first = hull;
        first_error = error;
        have_first = true;
      } else if (first_error != error || (hull && !(*hull == *first))) {
        fail("hull algorithms disagree");
      }
    }
  }
  if (!first) return 0;
  const std::span<const mink::Vec2> ring = first->vertices();
  if (!mink::is_strictly_convex_ccw(ring))
    fail("hull is not strictly convex and counter-clockwise");
  // Every point is on or left of every edge (exact predicate).
  for (const mink::Vec2& p : points) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const mink::Vec2& a = ring[i];
      const mink::Vec2& b = ring[(i + 1) % ring.size()];
      if (mink::orient2d(a, b, p) < 0) fail("a point lies outside the hull");
    }
  }
  return 0;
}
