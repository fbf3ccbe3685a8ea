#include "gjk_crosscheck.hpp"

#include "box2d_distance.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <ostream>

#include "mink/error.hpp"
#include "mink/geometry/convex_hull.hpp"
#include "mink/narrowphase/gjk_distance.hpp"
#include "mink/narrowphase/gjk_overlap.hpp"
#include "mink/narrowphase/penetration.hpp"

namespace mink::cli {

namespace {

// The hull of `points` float-valued points near an ellipse about `centre`; a degenerate draw
// (collinear) is replaced by a new one.
std::vector<Vec2> random_float_hull(std::mt19937_64& rng, std::size_t points, const Vec2& centre) {
  std::uniform_real_distribution<double> angle(0, 2 * std::numbers::pi);
  std::uniform_real_distribution<double> unit(0, 1);
  std::uniform_real_distribution<double> size(0.2, 1.5);
  for (;;) {
    const double sx = size(rng);
    const double sy = size(rng);
    const double turn = angle(rng);
    std::vector<Vec2> cloud;
    for (std::size_t i = 0; i < points; ++i) {
      // Points near an ellipse, so most of them are hull vertices even for large counts.
      const double t = angle(rng);
      const double r = points > 8 ? 1 : 0.3 + 0.7 * unit(rng);
      const Vec2 local(sx * r * std::cos(t), sy * r * std::sin(t));
      const Vec2 world(centre.x() + std::cos(turn) * local.x() - std::sin(turn) * local.y(),
                       centre.y() + std::sin(turn) * local.x() + std::cos(turn) * local.y());
      cloud.emplace_back(static_cast<float>(world.x()), static_cast<float>(world.y()));
    }
    try {
      const ConvexHull hull = build_hull(cloud, HullAlgorithm::monotone_chain);
      return {hull.vertices().begin(), hull.vertices().end()};
    } catch (const Error&) {
    }
  }
}

}  // namespace

double signed_gap(const DistanceResult& d, const PreparedHull& a, const Pose& pose_a,
                  const PreparedHull& b, const Pose& pose_b) {
  return d.overlap ? -penetration(a, pose_a, b, pose_b, d.simplex).depth : d.distance;
}

CrosscheckPair random_crosscheck_pair(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> small(3, 8);
  std::uniform_int_distribution<int> large_exponent(4, 10);
  std::uniform_real_distribution<double> offset(-1.6, 1.6);
  auto count = [&] {
    return rng() % 10 == 0 ? std::size_t{1} << large_exponent(rng)
                           : static_cast<std::size_t>(small(rng));
  };
  CrosscheckPair pair;
  const std::size_t na = count();
  const std::size_t nb = count();
  pair.a = random_float_hull(rng, na, Vec2(0, 0));
  pair.b = random_float_hull(rng, nb, Vec2(offset(rng), offset(rng)));
  if (rng() % 8 == 0) {
    // Slide b along x to where it just leaves a (bisection on the exact verdict), then round
    // to floats again: the gap ends up within float rounding of touching, either side.
    double lo = -8;
    double hi = 8;
    auto shifted = [&](double dx) {
      std::vector<Vec2> moved = pair.b;
      for (Vec2& v : moved) v.x() += dx;
      return moved;
    };
    while (hi - lo > 1e-12) {
      const double mid = 0.5 * (lo + hi);
      (hulls_overlap_exact(pair.a, shifted(mid)) ? lo : hi) = mid;
    }
    std::vector<Vec2> moved = shifted(hi);
    for (Vec2& v : moved) v = Vec2(static_cast<float>(v.x()), static_cast<float>(v.y()));
    // No retry: rounding again all but never makes the hull collinear, and a fresh draw would
    // lose the slide.
    const ConvexHull slid = build_hull(moved, HullAlgorithm::monotone_chain);
    pair.b.assign(slid.vertices().begin(), slid.vertices().end());
  }
  return pair;
}

namespace {

const char* verdict(bool overlap) {
  return overlap ? "overlap" : "apart";
}

}  // namespace

CrosscheckReport run_gjk_crosscheck(std::uint64_t pairs, std::uint64_t seed, double band,
                                    std::ostream& out) {
  std::mt19937_64 rng(seed);
  CrosscheckReport report;
  char line[512];
  const Pose identity{};
  const auto started = std::chrono::steady_clock::now();
  for (std::uint64_t k = 0; k < pairs; ++k) {
    const CrosscheckPair pair = random_crosscheck_pair(rng);
    const PreparedHull a(ConvexHull::from_ccw_vertices(pair.a));
    const PreparedHull b(ConvexHull::from_ccw_vertices(pair.b));
    const DistanceResult ours = gjk_distance(a, identity, b, identity);
    const double gap = signed_gap(ours, a, identity, b, identity);
    const interop::Box2dDistance theirs = interop::box2d_distance(pair.a, pair.b);
    ++report.pairs;
    report.overlapping += ours.overlap;
    if (ours.overlap != theirs.overlap) {
      ++report.verdict_differs;
      const bool outside = std::abs(gap) > band;
      report.verdict_outside_band += outside;
      std::snprintf(line, sizeof line,
                    "pair %llu (%zu and %zu vertices): mink %s, Box2D %s (distance %.9g, %d "
                    "iterations), exact %s; distance to touching %.3g, %s the %.0e band\n",
                    static_cast<unsigned long long>(k), pair.a.size(), pair.b.size(),
                    verdict(ours.overlap), verdict(theirs.overlap), theirs.distance,
                    theirs.iterations, verdict(hulls_overlap_exact(pair.a, pair.b)), std::abs(gap),
                    outside ? "OUTSIDE" : "inside", band);
      out << line;
      continue;
    }
    if (ours.overlap) continue;
    // Box2D computes in float: its distance carries errors of a few float ulps of the
    // coordinates (up to about 4 here, ulp 4.8e-7).
    const double error = std::abs(theirs.distance - ours.distance);
    report.worst_distance_error = std::max(report.worst_distance_error, error);
    if (error > 1e-5 + 1e-5 * ours.distance) {
      ++report.distance_differs;
      std::snprintf(line, sizeof line,
                    "pair %llu (%zu and %zu vertices): distance mink %.17g, Box2D %.9g (%d "
                    "iterations), difference %.3g\n",
                    static_cast<unsigned long long>(k), pair.a.size(), pair.b.size(), ours.distance,
                    theirs.distance, theirs.iterations, error);
      out << line;
    }
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  std::snprintf(
      line, sizeof line,
      "gjk crosscheck: %llu pairs (seed %llu) in %.1f s, %llu overlapping; verdicts "
      "differ on %llu (%llu outside the %.0e band of touching); distances differ beyond "
      "float precision on %llu; largest distance difference %.3g\n",
      static_cast<unsigned long long>(report.pairs), static_cast<unsigned long long>(seed), seconds,
      static_cast<unsigned long long>(report.overlapping),
      static_cast<unsigned long long>(report.verdict_differs),
      static_cast<unsigned long long>(report.verdict_outside_band), band,
      static_cast<unsigned long long>(report.distance_differs), report.worst_distance_error);
  out << line;
  return report;
}

}  // namespace mink::cli
