#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

#include "mink/error.hpp"
#include "mink/geometry/akl_toussaint.hpp"
#include "mink/geometry/chan.hpp"
#include "mink/geometry/convex_hull.hpp"
#include "mink/geometry/divide_conquer.hpp"
#include "mink/geometry/graham.hpp"
#include "mink/geometry/hull_input.hpp"
#include "mink/geometry/jarvis.hpp"
#include "mink/geometry/monotone_chain.hpp"
#include "test_support.hpp"

namespace {

using mink::Vec2;
using mink_test::format_points;

struct Builder {
  std::string name;
  std::function<void(std::span<const Vec2>)> build;
};

// Every entry point that validates hull input: build_hull with and without the prefilter,
// each algorithm's own function, the divide-and-conquer leaf sizes, the filter and the
// validator itself.
std::vector<Builder> every_builder() {
  std::vector<Builder> builders;
  for (mink::HullAlgorithm algorithm : mink::all_hull_algorithms()) {
    std::string name(mink::to_string(algorithm));
    std::replace(name.begin(), name.end(), '-', '_');
    for (bool prefilter : {false, true}) {
      builders.push_back({"build_hull_" + name + (prefilter ? "_prefilter" : ""),
                          [algorithm, prefilter](std::span<const Vec2> points) {
                            mink::build_hull(points, algorithm, mink::HullOptions{prefilter});
                          }});
    }
  }
  builders.push_back({"chan_hull", [](std::span<const Vec2> p) { mink::chan_hull(p); }});
  builders.push_back({"graham_hull", [](std::span<const Vec2> p) { mink::graham_hull(p); }});
  builders.push_back({"jarvis_hull", [](std::span<const Vec2> p) { mink::jarvis_hull(p); }});
  builders.push_back(
      {"monotone_chain_hull", [](std::span<const Vec2> p) { mink::monotone_chain_hull(p); }});
  for (std::size_t leaf_size : {0, 1, 2, 3, 7}) {
    builders.push_back({"divide_conquer_hull_leaf" + std::to_string(leaf_size),
                        [leaf_size](std::span<const Vec2> p) {
                          mink::divide_conquer_hull(p, mink::DivideConquerOptions{leaf_size});
                        }});
  }
  builders.push_back(
      {"akl_toussaint_filter", [](std::span<const Vec2> p) { mink::akl_toussaint_filter(p); }});
  builders.push_back(
      {"validate_hull_input", [](std::span<const Vec2> p) { mink::validate_hull_input(p); }});
  return builders;
}

// ctest shows parameters through PrintTo; the default would be a byte dump.
void PrintTo(const Builder& builder, std::ostream* out) {
  *out << builder.name;
}

class HullErrors : public testing::TestWithParam<Builder> {
 protected:
  // Expects DegenerateInputError whose message contains `phrase`.
  void expect_degenerate(const std::vector<Vec2>& points, const std::string& phrase) {
    try {
      GetParam().build(points);
      ADD_FAILURE() << "no exception for " << format_points(points);
    } catch (const mink::DegenerateInputError& error) {
      EXPECT_NE(std::string(error.what()).find(phrase), std::string::npos)
          << "message '" << error.what() << "' lacks '" << phrase << "' for "
          << format_points(points);
    } catch (const std::exception& error) {
      ADD_FAILURE() << "wrong exception '" << error.what() << "' for " << format_points(points);
    }
  }

  void expect_non_finite(const std::vector<Vec2>& points, std::size_t index) {
    try {
      GetParam().build(points);
      ADD_FAILURE() << "no exception for " << format_points(points);
    } catch (const mink::NonFiniteInputError& error) {
      EXPECT_EQ(error.index(), index) << format_points(points);
      const std::string message = error.what();
      EXPECT_NE(message.find("point " + std::to_string(index) + " "), std::string::npos) << message;
      EXPECT_NE(message.find("non-finite"), std::string::npos) << message;
    } catch (const std::exception& error) {
      ADD_FAILURE() << "wrong exception '" << error.what() << "' for " << format_points(points);
    }
  }
};

TEST_P(HullErrors, FewerThanThreePoints) {
  expect_degenerate({}, "at least 3 points, got 0");
  expect_degenerate({{1, 2}}, "at least 3 points, got 1");
  expect_degenerate({{1, 2}, {3, 5}}, "at least 3 points, got 2");
}

TEST_P(HullErrors, AllPointsIdentical) {
  expect_degenerate({{1.5, -2}, {1.5, -2}, {1.5, -2}}, "same point");
  expect_degenerate(std::vector<Vec2>(1000, Vec2(-0.0, 1e300)), "same point");
}

TEST_P(HullErrors, AllPointsCollinear) {
  expect_degenerate({{0, 0}, {1, 1}, {2, 2}}, "one line");
  expect_degenerate({{3, 3}, {0, 0}, {2, 2}, {1, 1}, {-7, -7}}, "one line");
  // Vertical and horizontal lines, where the lowest-x point is not unique.
  expect_degenerate({{5, 0}, {5, 3}, {5, -2}, {5, 1}}, "one line");
  expect_degenerate({{0, 4}, {-3, 4}, {9, 4}}, "one line");
  // Exact integers far beyond where the naive determinant is exact.
  expect_degenerate({{0x1p52 + 1, 3}, {0x1p52 + 3, 7}, {0x1p52 + 2, 5}, {1, -0x1p53 + 3}},
                    "one line");
}

TEST_P(HullErrors, CollinearWithDuplicates) {
  expect_degenerate({{1, 1}, {0, 0}, {1, 1}, {3, 3}, {2, 2}, {0, 0}, {3, 3}}, "one line");
  // The first point repeated before the line shows up.
  expect_degenerate({{2, 4}, {2, 4}, {2, 4}, {2, 4}, {0, 0}, {1, 2}, {2, 4}, {3, 6}}, "one line");
  expect_degenerate({{0, 1}, {0, 1}, {0, 2}, {0, 1}, {0, -1}, {0, 2}}, "one line");
  // Two distinct points, each repeated: a segment.
  expect_degenerate({{0, 0}, {1, 2}, {0, 0}, {1, 2}}, "one line");
}

TEST_P(HullErrors, NonFiniteCoordinateAnywhere) {
  const std::vector<Vec2> valid = {{0, 0}, {4, 0}, {4, 3}, {0, 3}, {2, 1}, {1, 2}};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (double bad : {nan, inf, -inf}) {
    for (std::size_t index : {std::size_t{0}, std::size_t{2}, valid.size() - 1}) {
      for (int axis : {0, 1}) {
        std::vector<Vec2> points = valid;
        points[index][axis] = bad;
        expect_non_finite(points, index);
      }
    }
  }
  // The first offending point is the one named.
  std::vector<Vec2> two_bad = valid;
  two_bad[4].y() = inf;
  two_bad[1].x() = nan;
  expect_non_finite(two_bad, 1);
}

TEST_P(HullErrors, NonFiniteCoordinateInAnOtherwiseDegenerateSet) {
  // Whether a set with a NaN is degenerate is unknowable; the NaN is the problem to report.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  expect_non_finite({{0, 0}, {1, 1}, {nan, 2}}, 2);
  expect_non_finite({{std::numeric_limits<double>::infinity(), 0}}, 0);
  expect_non_finite({{1, 1}, {1, 1}, {1, nan}, {1, 1}}, 2);
}

TEST_P(HullErrors, NearlyCollinearIsNotDegenerate) {
  // One ulp above the diagonal is a genuine left turn.
  const std::vector<Vec2> points = {{0, 0}, {1, 1}, {2, std::nextafter(2.0, 3.0)}};
  EXPECT_NO_THROW(GetParam().build(points));
}

INSTANTIATE_TEST_SUITE_P(EveryEntryPoint, HullErrors, testing::ValuesIn(every_builder()),
                         [](const testing::TestParamInfo<Builder>& info) {
                           return info.param.name;
                         });

TEST(HullErrors, NearlyCollinearTriangleHasAllThreeVertices) {
  const double above_two = std::nextafter(2.0, 3.0);
  const std::vector<Vec2> points = {{2, above_two}, {1, 1}, {0, 0}};
  // (2, 2 + ulp) is left of (0, 0) -> (1, 1), so the CCW ring visits (1, 1) first.
  const std::vector<Vec2> expected = {{0, 0}, {1, 1}, {2, above_two}};
  ASSERT_TRUE(mink_test::same_ring(expected, mink_test::reference_hull(points)));
  for (mink::HullAlgorithm algorithm : mink::all_hull_algorithms()) {
    SCOPED_TRACE(mink::to_string(algorithm));
    EXPECT_TRUE(mink_test::same_ring(expected, mink::build_hull(points, algorithm).vertices()));
  }
}

TEST(HullErrors, ErrorsShareTheBaseClass) {
  // Callers may catch mink::Error for every problem the library reports.
  EXPECT_THROW(mink::build_hull(std::vector<Vec2>{}, mink::HullAlgorithm::chan), mink::Error);
  EXPECT_THROW(mink::parse_hull_algorithm("nope"), mink::Error);
  const mink::NonFiniteInputError error(7);
  EXPECT_EQ(error.index(), 7u);
}

}  // namespace
