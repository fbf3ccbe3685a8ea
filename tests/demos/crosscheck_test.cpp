#include <gtest/gtest.h>

#include <string>

#include "brute_force_support.hpp"
#include "cli_test_support.hpp"
#include "exact_overlap_oracle.hpp"
#include "gjk_crosscheck.hpp"
#include "mink/geometry/convex_hull.hpp"
#include "mink/narrowphase/gjk_distance.hpp"
#include "mink/narrowphase/gjk_overlap.hpp"

namespace {

using namespace mink_test;

#ifdef MINK_SANITIZED_BUILD
constexpr int kBox2dPairs = 3000;
constexpr int kExactPairs = 300;
#else
constexpr int kBox2dPairs = 30000;
constexpr int kExactPairs = 3000;
#endif

TEST(Crosscheck, AgreesWithBox2dOutsideTheBand) {
  const std::string pairs = std::to_string(kBox2dPairs);
  const CliResult r = run_cli({"crosscheck", "gjk", "--pairs", pairs, "--seed", "99"});
  EXPECT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("gjk crosscheck: " + pairs + " pairs (seed 99)"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("(0 outside the 1e-06 band of touching)"), std::string::npos);
}

TEST(Crosscheck, ReportsDisagreementsAndFailsOutsideATinyBand) {
  // With a band far below float precision, Box2D's float answers near touching must show up
  // as failures: the check can fail.
  const CliResult r = run_cli({"crosscheck", "gjk", "--pairs", "5000", "--band", "1e-15"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.out.find("OUTSIDE the 1e-15 band"), std::string::npos) << r.out;
}

TEST(Crosscheck, ShapesAgreeWithBox2dOutsideTheBand) {
  const std::string pairs = std::to_string(kBox2dPairs);
  const CliResult r = run_cli({"crosscheck", "shapes", "--pairs", pairs, "--seed", "7"});
  EXPECT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("shapes crosscheck: " + pairs + " pairs (seed 7)"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("1e-06 band of touching, unexplained, on 0"), std::string::npos) << r.out;
  // Every Box2D function was exercised, with contacts.
  for (const char* function : {"b2CollideCircles", "b2CollidePolygonAndCircle",
                               "b2CollideEdgeAndCircle", "b2CollideEdgeAndPolygon"}) {
    EXPECT_NE(r.out.find(function), std::string::npos) << function;
  }
  EXPECT_EQ(r.out.find(" 0 touching"), std::string::npos) << r.out;
}

TEST(Crosscheck, ShapesReportDisagreementsAndFailOutsideATinyBand) {
  // Box2D's float separations near touching differ from ours by more than 1e-15: with that
  // band the check must fail.
  const CliResult r =
      run_cli({"crosscheck", "shapes", "--pairs", "20000", "--seed", "3", "--band", "1e-15"});
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find("OUTSIDE the 1e-15 band"), std::string::npos) << r.out;
}

// The same kind of pairs against CGAL's exact predicates: our verdicts are right except, at
// most, within rounding of touching; distances match a brute-force scan.
TEST(Crosscheck, VerdictsAgreeWithTheExactOracle) {
  std::mt19937_64 rng(2024);
  const mink::Pose identity{};
  int near_touching = 0;
  for (int k = 0; k < kExactPairs; ++k) {
    const mink::cli::CrosscheckPair pair = mink::cli::random_crosscheck_pair(rng);
    const mink::PreparedHull a(mink::ConvexHull::from_ccw_vertices(pair.a));
    const mink::PreparedHull b(mink::ConvexHull::from_ccw_vertices(pair.b));
    const bool exact = exact_overlap(cgal_hull(pair.a), cgal_hull(pair.b));
    const mink::OverlapResult boolean = mink::gjk_overlap(a, identity, b, identity);
    const mink::DistanceResult distance = mink::gjk_distance(a, identity, b, identity);
    const Real gap = exact ? brute_depth(pair.a, pair.b).depth : scan_distance(pair.a, pair.b);
    if (gap < 1e-12) {
      ++near_touching;
      continue;
    }
    ASSERT_EQ(boolean.overlap, exact) << "pair " << k << ", gap " << gap;
    ASSERT_EQ(distance.overlap, exact) << "pair " << k << ", gap " << gap;
    if (!exact) {
      EXPECT_NEAR(distance.distance, gap, 1e-9 * std::max<Real>(1, gap));
    }
  }
  EXPECT_LT(near_touching, kExactPairs / 20);
}

}  // namespace
