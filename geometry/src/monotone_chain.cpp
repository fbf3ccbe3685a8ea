#include "mink/geometry/monotone_chain.hpp"

#include <algorithm>

#include "mink/geometry/hull_input.hpp"
#include "mink/geometry/orientation.hpp"

namespace mink {

ConvexHull monotone_chain_hull(std::span<const Vec2> points) {
  validate_hull_input(points);
  std::vector<Vec2> sorted(points.begin(), points.end());
  std::sort(sorted.begin(), sorted.end(), lex_less);
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());

  const std::size_t n = sorted.size();
  std::vector<Vec2> ring(2 * n);
  std::size_t k = 0;
  for (std::size_t i = 0; i < n; ++i) {  // lower chain, left to right
    while (k >= 2 && orient2d(ring[k - 2], ring[k - 1], sorted[i]) <= 0) --k;
    ring[k++] = sorted[i];
  }
  const std::size_t lower_size = k + 1;
  for (std::size_t i = n - 1; i-- > 0;) {  // upper chain, right to left
    while (k >= lower_size && orient2d(ring[k - 2], ring[k - 1], sorted[i]) <= 0) --k;
    ring[k++] = sorted[i];
  }
  ring.resize(k - 1);  // the last point repeats the first
  return detail::hull_from_ccw_ring(std::move(ring));
}

}  // namespace mink
