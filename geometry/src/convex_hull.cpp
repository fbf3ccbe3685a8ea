#include "mink/geometry/convex_hull.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>

#include "mink/error.hpp"
#include "mink/geometry/akl_toussaint.hpp"
#include "mink/geometry/chan.hpp"
#include "mink/geometry/divide_conquer.hpp"
#include "mink/geometry/graham.hpp"
#include "mink/geometry/hull_input.hpp"
#include "mink/geometry/jarvis.hpp"
#include "mink/geometry/monotone_chain.hpp"
#include "mink/geometry/orientation.hpp"

namespace mink {

namespace detail {
ConvexHull hull_from_ccw_ring(std::vector<Vec2> ring) {
  const auto start = std::min_element(ring.begin(), ring.end(), lex_less);
  std::rotate(ring.begin(), start, ring.end());
  return ConvexHull(std::move(ring));
}
}  // namespace detail

bool is_strictly_convex_ccw(std::span<const Vec2> ring) {
  const std::size_t n = ring.size();
  if (n < 3) return false;
  for (std::size_t i = 0; i < n; ++i) {
    if (orient2d(ring[i], ring[(i + 1) % n], ring[(i + 2) % n]) <= 0) return false;
  }
  // Left turns everywhere still allow a ring that winds around more than once (a star
  // polygon); a convex ring has exactly one vertex below both neighbours in (x, y) order.
  std::size_t local_minima = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& previous = ring[(i + n - 1) % n];
    const Vec2& next = ring[(i + 1) % n];
    if (lex_less(ring[i], previous) && lex_less(ring[i], next)) ++local_minima;
  }
  return local_minima == 1;
}

ConvexHull ConvexHull::from_ccw_vertices(std::vector<Vec2> vertices) {
  require_finite(vertices);
  if (vertices.size() < 3) {
    throw DegenerateInputError("a convex hull needs at least 3 vertices, got " +
                               std::to_string(vertices.size()));
  }
  const std::size_t n = vertices.size();
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    if (orient2d(vertices[i], vertices[j], vertices[(i + 2) % n]) <= 0) {
      throw DegenerateInputError("vertex " + std::to_string(j) +
                                 " is not a strict counter-clockwise turn");
    }
  }
  if (!is_strictly_convex_ccw(vertices)) {
    throw DegenerateInputError("the vertices wind around more than once");
  }
  return detail::hull_from_ccw_ring(std::move(vertices));
}

namespace {
constexpr std::array<HullAlgorithm, 5> kAlgorithms = {
    HullAlgorithm::chan, HullAlgorithm::divide_conquer, HullAlgorithm::graham,
    HullAlgorithm::jarvis, HullAlgorithm::monotone_chain};
}  // namespace

std::string_view to_string(HullAlgorithm algorithm) noexcept {
  switch (algorithm) {
    case HullAlgorithm::chan:
      return "chan";
    case HullAlgorithm::divide_conquer:
      return "divide-conquer";
    case HullAlgorithm::graham:
      return "graham";
    case HullAlgorithm::jarvis:
      return "jarvis";
    case HullAlgorithm::monotone_chain:
      return "monotone-chain";
  }
  return "unknown";
}

HullAlgorithm parse_hull_algorithm(std::string_view name) {
  for (HullAlgorithm algorithm : kAlgorithms) {
    if (to_string(algorithm) == name) return algorithm;
  }
  throw InvalidArgumentError("unknown hull algorithm '" + std::string(name) +
                             "' (expected chan, divide-conquer, graham, jarvis or "
                             "monotone-chain)");
}

std::span<const HullAlgorithm> all_hull_algorithms() noexcept {
  return kAlgorithms;
}

ConvexHull build_hull(std::span<const Vec2> points, HullAlgorithm algorithm, HullOptions options) {
  std::optional<std::vector<Vec2>> survivors;
  if (options.prefilter) {
    survivors = akl_toussaint_filter_if_worthwhile(points);  // keeps every hull vertex
    if (survivors) points = *survivors;
  }
  switch (algorithm) {
    case HullAlgorithm::chan:
      return chan_hull(points);
    case HullAlgorithm::divide_conquer:
      return divide_conquer_hull(points);
    case HullAlgorithm::graham:
      return graham_hull(points);
    case HullAlgorithm::jarvis:
      return jarvis_hull(points);
    case HullAlgorithm::monotone_chain:
      return monotone_chain_hull(points);
  }
  throw InvalidArgumentError("unknown hull algorithm");
}

}  // namespace mink
