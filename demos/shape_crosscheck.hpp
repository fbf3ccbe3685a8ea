#pragma once

#include <array>
#include <cstdint>
#include <iosfwd>

namespace mink::cli {

// The four Box2D 2.4.1 collide functions the shapes cross-check compares with, and the pair of
// our shape kinds each stands for (Box2D's polygons and edges carry a skin of b2_polygonRadius:
// they are our rounded polygons and capsules of that radius).
enum class ShapePair : int { circles, polygon_circle, edge_circle, edge_polygon };
inline constexpr int kShapePairCount = 4;

struct ShapePairReport {
  std::uint64_t pairs = 0;
  std::uint64_t touching = 0;              // by our verdict
  std::uint64_t verdict_differs = 0;       // all of them, inside the band or not
  std::uint64_t verdict_outside_band = 0;  // not explained by hysteresis: failures
  std::uint64_t hysteresis = 0;  // edge-polygon misses of Box2D explained by its axis hysteresis
  double worst_separation_difference = 0;  // where both touch and the point counts agree
};

struct ShapeCrosscheckReport {
  std::uint64_t pairs = 0;
  std::array<ShapePairReport, kShapePairCount> by_pair{};
  std::uint64_t verdict_outside_band = 0;  // over all pairs
};

// Compares our touching verdict (collide_shapes with no speculative margin: points with
// separation <= 0) with Box2D's (pointCount > 0 with a separation <= 0) on `pairs` random pairs
// with float coordinates, cycling through the four pair kinds; one pair in four is slid to
// within 1e-5 of touching. Writes one line per disagreement (with its distance to touching)
// and a summary per pair kind to `out`. A disagreement farther than `band` from touching fails
// the check, unless it is an edge-polygon pair Box2D misses because of its reference-axis
// hysteresis (counted and printed apart; see the source).
ShapeCrosscheckReport run_shape_crosscheck(std::uint64_t pairs, std::uint64_t seed, double band,
                                           std::ostream& out);

}  // namespace mink::cli
