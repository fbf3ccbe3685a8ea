#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <exception>
#include <functional>
#include <numbers>
#include <ostream>
#include <string>
#include <vector>

#include "mink/error.hpp"
#include "mink/geometry/convex_hull.hpp"
#include "mink/geometry/divide_conquer.hpp"
#include "mink/geometry/orientation.hpp"
#include "mink/geometry/point_sets.hpp"
#include "test_support.hpp"

namespace {

using mink::Vec2;
using mink_test::format_point;
using mink_test::format_points;

// One way to build a hull, named for failure messages.
struct HullBuilder {
  std::string name;
  std::function<mink::ConvexHull(std::span<const Vec2>)> build;
  bool is_jarvis = false;
};

std::vector<HullBuilder> every_hull_builder() {
  std::vector<HullBuilder> builders;
  for (mink::HullAlgorithm algorithm : mink::all_hull_algorithms()) {
    for (bool prefilter : {false, true}) {
      builders.push_back(
          {std::string(mink::to_string(algorithm)) + (prefilter ? " with prefilter" : ""),
           [algorithm, prefilter](std::span<const Vec2> points) {
             return mink::build_hull(points, algorithm, mink::HullOptions{prefilter});
           },
           algorithm == mink::HullAlgorithm::jarvis});
    }
  }
  for (std::size_t leaf_size : {1, 2, 3, 7}) {
    builders.push_back({"divide-conquer with leaf size " + std::to_string(leaf_size),
                        [leaf_size](std::span<const Vec2> points) {
                          return mink::divide_conquer_hull(points,
                                                           mink::DivideConquerOptions{leaf_size});
                        }});
  }
  return builders;
}

// Gift wrapping costs n h orientation tests; beyond this it would dominate the suite.
constexpr double kJarvisWorkLimit = 3e8;

// Invariants checked without CGAL: strictly convex and CCW, canonical start, vertices drawn
// from the input, and (when affordable) every input point inside or on the hull.
::testing::AssertionResult satisfies_hull_invariants(std::span<const Vec2> points,
                                                     std::span<const Vec2> hull) {
  if (!mink::is_strictly_convex_ccw(hull)) {
    return ::testing::AssertionFailure() << "not strictly convex CCW: " << format_points(hull);
  }
  const Vec2 lowest = *std::min_element(points.begin(), points.end(), mink::lex_less);
  if (hull[0] != lowest) {
    return ::testing::AssertionFailure()
           << "starts at " << format_point(hull[0]) << ", not at the lowest (x, y) input point "
           << format_point(lowest);
  }
  std::vector<Vec2> sorted(points.begin(), points.end());
  std::sort(sorted.begin(), sorted.end(), mink::lex_less);
  for (const Vec2& v : hull) {
    if (!std::binary_search(sorted.begin(), sorted.end(), v, mink::lex_less)) {
      return ::testing::AssertionFailure() << "vertex " << format_point(v) << " is no input point";
    }
  }
  if (static_cast<double>(points.size()) * static_cast<double>(hull.size()) <= 2e7) {
    for (const Vec2& p : points) {
      for (std::size_t i = 0; i < hull.size(); ++i) {
        if (mink::orient2d(hull[i], hull[(i + 1) % hull.size()], p) < 0) {
          return ::testing::AssertionFailure()
                 << "input point " << format_point(p) << " is outside edge " << i << " "
                 << format_point(hull[i]) << " -> " << format_point(hull[(i + 1) % hull.size()]);
        }
      }
    }
  }
  return ::testing::AssertionSuccess();
}

struct OracleCase {
  mink::PointDistribution distribution;
  std::size_t size;
  std::uint64_t seed_count;  // seeds 1 .. seed_count
};

// ctest shows parameters through PrintTo; the default would be a byte dump.
void PrintTo(const OracleCase& param, std::ostream* out) {
  *out << mink::to_string(param.distribution) << ", " << param.size << " points, "
       << param.seed_count << " seeds";
}

std::string case_name(const testing::TestParamInfo<OracleCase>& info) {
  std::string name(mink::to_string(info.param.distribution));
  std::replace(name.begin(), name.end(), '-', '_');
  // Appending piece by piece: GCC 12 warns falsely (-Wrestrict) about "literal" + to_string.
  name.append("_n").append(std::to_string(info.param.size));
  if (info.param.seed_count > 1) {
    name.append("_").append(std::to_string(info.param.seed_count)).append("seeds");
  }
  return name;
}

std::vector<OracleCase> oracle_cases() {
  struct SizeAndSeeds {
    std::size_t size;
    std::uint64_t seeds;
  };
  // Small sets are cheap, so many seeds hit many degenerate configurations.
  const std::vector<SizeAndSeeds> sizes = {{3, 300},    {4, 300},     {5, 300},
                                           {10, 200},   {100, 20},    {1'000, 3},
                                           {10'000, 1}, {100'000, 1}, {1'000'000, 1}};
  // The sanitizer pass only needs to see every code path, not the largest sets.
  const std::size_t largest = mink_test::kSanitizedBuild ? 100'000 : 1'000'000;
  std::vector<OracleCase> cases;
  for (mink::PointDistribution distribution : mink::all_point_distributions()) {
    for (const SizeAndSeeds& s : sizes) {
      if (s.size <= largest) cases.push_back({distribution, s.size, s.seeds});
    }
  }
  return cases;
}

class HullOracle : public testing::TestWithParam<OracleCase> {};

TEST_P(HullOracle, EveryAlgorithmMatchesCgal) {
  const OracleCase& param = GetParam();
  const std::vector<HullBuilder> builders = every_hull_builder();
  int failures = 0;
  constexpr int kMaxFailures = 5;  // enough to see a pattern without flooding the log
  for (std::uint64_t seed = 1; seed <= param.seed_count && failures < kMaxFailures; ++seed) {
    const auto points = mink::generate_points(param.distribution, param.size, seed);
    const auto expected = mink_test::reference_hull(points);
    const double jarvis_work =
        static_cast<double>(points.size()) * static_cast<double>(expected.size());
    bool invariants_checked = false;
    for (const HullBuilder& builder : builders) {
      if (builder.is_jarvis && jarvis_work > kJarvisWorkLimit) continue;
      const std::string context = builder.name + ", seed " + std::to_string(seed) +
                                  (points.size() <= 10 ? ", points " + format_points(points) : "");
      try {
        const mink::ConvexHull hull = builder.build(points);
        if (expected.size() < 3) {
          ADD_FAILURE() << context << ": CGAL finds no area (" << format_points(expected)
                        << ") but got the hull " << format_points(hull.vertices());
          ++failures;
          continue;
        }
        const auto same = mink_test::same_ring(expected, hull.vertices());
        if (!same) {
          ADD_FAILURE() << context << ": " << same.message();
          ++failures;
          continue;
        }
        if (!invariants_checked) {
          invariants_checked = true;
          const auto valid = satisfies_hull_invariants(points, hull.vertices());
          if (!valid) {
            ADD_FAILURE() << context << ": " << valid.message();
            ++failures;
          }
        }
      } catch (const mink::DegenerateInputError& error) {
        if (expected.size() >= 3) {
          ADD_FAILURE() << context << ": threw DegenerateInputError (" << error.what()
                        << ") but CGAL's hull is " << format_points(expected);
          ++failures;
        }
      } catch (const std::exception& error) {
        ADD_FAILURE() << context << ": threw " << error.what();
        ++failures;
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllDistributions, HullOracle, testing::ValuesIn(oracle_cases()),
                         case_name);

// Sets built to hit the algorithms' special cases, beyond what the distributions produce.
struct ShapedCase {
  std::string name;
  std::vector<Vec2> points;
};

std::vector<ShapedCase> shaped_cases() {
  std::vector<ShapedCase> cases;
  {
    // Square with many points on every edge, duplicated corners, and the centre.
    std::vector<Vec2> points;
    for (int i = 0; i <= 20; ++i) {
      const double step = i;
      points.insert(points.end(),
                    {{step, 0.0}, {20.0, step}, {20.0 - step, 20.0}, {0.0, 20.0 - step}});
    }
    points.push_back({10, 10});
    cases.push_back({"square_with_collinear_edges", points});
  }
  {
    // Two vertical columns: the lowest-x and highest-x vertices share x with many points.
    std::vector<Vec2> points;
    for (int i = 0; i < 50; ++i) points.insert(points.end(), {{-1.0, i + 0.0}, {1.0, -i - 0.0}});
    cases.push_back({"two_vertical_columns", points});
  }
  {
    // Triangle with one point repeated many times and a vertical left edge.
    std::vector<Vec2> points(100, Vec2(0, 0));
    points.insert(points.end(), {{0.0, 5.0}, {3.0, 1.0}, {0.0, 2.0}, {0.0, 5.0}, {1.5, 3.0}});
    cases.push_back({"repeated_points_and_vertical_edge", points});
  }
  {
    // Points on a parabola: all of them are hull vertices.
    std::vector<Vec2> points;
    for (int i = -500; i <= 500; ++i) points.push_back({i + 0.0, double(i) * i});
    cases.push_back({"parabola_all_vertices", points});
  }
  {
    // A line with one point a single ulp off it, at both ends and in the middle.
    std::vector<Vec2> points;
    for (int i = 0; i < 64; ++i) points.push_back({i + 0.0, 0.1 + 0.3 * i});
    points.push_back({31.5, std::nextafter(0.1 + 0.3 * 31.5, 100.0)});
    cases.push_back({"line_with_one_point_an_ulp_off", points});
  }
  {
    // Points on the circle of radius 2^26 with integer coordinates (Pythagorean-like
    // rounding), sorted by angle, so the input order is itself a convex ring.
    std::vector<Vec2> points;
    for (int i = 0; i < 4096; ++i) {
      const double angle = 2 * std::numbers::pi * i / 4096;
      points.push_back(
          {std::round(0x1p26 * std::cos(angle)), std::round(0x1p26 * std::sin(angle))});
    }
    cases.push_back({"integer_circle_in_angle_order", points});
  }
  {
    // Every point twice, in a scrambled order (stride 1031, coprime to the count): Chan's
    // rounds up to m = 256 fail, and its last round merges rings holding duplicates.
    std::vector<Vec2> points;
    constexpr int kCount = 4096;
    for (int k = 0; k < 2 * kCount; ++k) {
      const int i = (k * 1031) % kCount;
      const double angle = 2 * std::numbers::pi * i / kCount;
      points.push_back(
          {std::round(0x1p20 * std::cos(angle)), std::round(0x1p20 * std::sin(angle))});
    }
    cases.push_back({"integer_circle_scrambled_twice", points});
  }
  {
    // A fan from the lowest point: a parabola's points and, on the ray to each, the points at
    // half and a quarter of the way. Those on the first and last rays lie on hull edges, so
    // the polar order's ties at both ends decide what survives.
    std::vector<Vec2> points{{0, 0}};
    for (int x = 1; x <= 400; ++x) {
      const double far_x = (x * 617) % 400 + 1;  // scrambled
      const Vec2 far(far_x, far_x * far_x);
      points.insert(points.end(), {far / 2, far, far / 4});
    }
    cases.push_back({"parabola_fan_with_ray_ties", points});
  }
  {
    // A parabola so flat that every polar key, and every difference of two, is subnormal:
    // no key order can be scaled or trusted, so the exact comparisons order everything.
    std::vector<Vec2> points;
    for (int i = 40; i >= 0; --i) points.push_back({i + 0.0, std::ldexp(double(i) * i, -1060)});
    cases.push_back({"subnormal_parabola", points});
  }
  {
    // Negative and positive zero, which compare equal.
    cases.push_back({"signed_zeros", {{-0.0, 0.0}, {0.0, -0.0}, {1, 0}, {0, 1}, {-0.0, 1}}});
  }
  return cases;
}

void PrintTo(const ShapedCase& param, std::ostream* out) {
  *out << param.name << ", " << param.points.size() << " points";
}

class ShapedHull : public testing::TestWithParam<ShapedCase> {};

TEST_P(ShapedHull, EveryAlgorithmMatchesCgal) {
  const auto& points = GetParam().points;
  const auto expected = mink_test::reference_hull(points);
  ASSERT_GE(expected.size(), 3u);
  for (const HullBuilder& builder : every_hull_builder()) {
    SCOPED_TRACE(builder.name);
    // Orders that differ from generation order catch order-dependent shortcuts.
    const std::vector<Vec2> reversed(points.rbegin(), points.rend());
    for (const std::vector<Vec2>* input : {&points, &reversed}) {
      try {
        const mink::ConvexHull hull = builder.build(*input);
        EXPECT_TRUE(mink_test::same_ring(expected, hull.vertices()));
        EXPECT_TRUE(satisfies_hull_invariants(*input, hull.vertices()));
      } catch (const std::exception& error) {
        ADD_FAILURE() << "threw " << error.what();
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Shapes, ShapedHull, testing::ValuesIn(shaped_cases()),
                         [](const testing::TestParamInfo<ShapedCase>& info) {
                           return info.param.name;
                         });

TEST(HullAlgorithmNames, RoundTripThroughParse) {
  ASSERT_EQ(mink::all_hull_algorithms().size(), 5u);
  for (mink::HullAlgorithm algorithm : mink::all_hull_algorithms()) {
    EXPECT_EQ(mink::parse_hull_algorithm(mink::to_string(algorithm)), algorithm);
  }
  EXPECT_EQ(mink::to_string(mink::HullAlgorithm::divide_conquer), "divide-conquer");
  EXPECT_EQ(mink::to_string(mink::HullAlgorithm::monotone_chain), "monotone-chain");
  try {
    mink::parse_hull_algorithm("quickhull");
    ADD_FAILURE() << "no exception for an unknown algorithm";
  } catch (const mink::InvalidArgumentError& error) {
    EXPECT_NE(std::string(error.what()).find("quickhull"), std::string::npos) << error.what();
  }
}

TEST(PointDistributions, SameSeedSamePointsAndRightCounts) {
  for (mink::PointDistribution distribution : mink::all_point_distributions()) {
    SCOPED_TRACE(mink::to_string(distribution));
    const auto first = mink::generate_points(distribution, 1'000, 42);
    EXPECT_EQ(first.size(), 1'000u);
    EXPECT_EQ(first, mink::generate_points(distribution, 1'000, 42));
    EXPECT_NE(first, mink::generate_points(distribution, 1'000, 43));
    for (const Vec2& p : first) ASSERT_TRUE(p.allFinite()) << format_point(p);
  }
  const auto [set_a, set_b] = mink::paper_point_sets(2013, 500);
  EXPECT_EQ(set_a.size(), 500u);
  EXPECT_EQ(set_b.size(), 500u);
  for (const auto* set : {&set_a, &set_b}) {
    for (const Vec2& p : *set) {
      ASSERT_TRUE(p.x() >= 0 && p.x() <= 400 && p.y() >= 0 && p.y() <= 400) << format_point(p);
    }
  }
}

}  // namespace
