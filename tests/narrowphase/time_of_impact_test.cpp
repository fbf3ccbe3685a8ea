// Time of impact: closed forms, and every pair kind against a brute-force sampled sweep.

#include "mink/narrowphase/time_of_impact.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <numbers>

#include "sweep_cases.hpp"

namespace {

using namespace mink_test;
using mink::TimeOfImpactInput;
using mink::TimeOfImpactOutput;
using mink::ToiState;

Sweep still(Real x, Real y, Real angle = 0) {
  Sweep s;
  s.center0 = s.center1 = Vec2(x, y);
  s.angle0 = s.angle1 = angle;
  return s;
}

Sweep moving(Vec2 from, Vec2 to, Real angle0 = 0, Real angle1 = 0) {
  Sweep s;
  s.center0 = from;
  s.center1 = to;
  s.angle0 = angle0;
  s.angle1 = angle1;
  return s;
}

TimeOfImpactOutput toi(const ShapeGeometry& a, const Sweep& sa, const ShapeGeometry& b,
                       const Sweep& sb, Real target = kSlop) {
  TimeOfImpactInput in;
  in.shape_a = &a;
  in.sweep_a = sa;
  in.shape_b = &b;
  in.sweep_b = sb;
  in.target = target;
  in.tolerance = kTolerance;
  return time_of_impact(in);
}

TEST(TimeOfImpact, SweepTurnsAboutItsLocalCentre) {
  Sweep s = moving(Vec2(1, 2), Vec2(3, 2), 0, std::numbers::pi);
  s.local_center = Vec2(0.5, 0);
  const Pose start = s.pose_at(0);
  EXPECT_NEAR((start.apply(s.local_center) - Vec2(1, 2)).norm(), 0, 1e-15);
  const Pose half = s.pose_at(0.5);
  EXPECT_NEAR((half.apply(s.local_center) - Vec2(2, 2)).norm(), 0, 1e-15);
  EXPECT_NEAR(half.rotation.angle(), std::numbers::pi / 2, 1e-15);
  // Half a turn about the centre of mass puts the origin on its other side.
  EXPECT_NEAR((s.pose_at(1).position - Vec2(3.5, 2)).norm(), 0, 1e-15);
}

TEST(TimeOfImpact, CirclesHeadOnHitWhenTheGapReachesTarget) {
  const ShapeGeometry a = mink::Circle{Vec2(0, 0), 0.5};
  const ShapeGeometry b = mink::Circle{Vec2(0, 0), 0.25};
  // B from x = 4 to x = -4: the centres are 0.75 + target apart at t = (4 - 0.755) / 8.
  const TimeOfImpactOutput out = toi(a, still(0, 0), b, moving(Vec2(4, 0), Vec2(-4, 0)));
  ASSERT_EQ(out.state, ToiState::hit);
  EXPECT_NEAR(out.fraction, (4 - 0.75 - kSlop) / 8, kTolerance / 8);
  EXPECT_NEAR(out.separation, kSlop, kTolerance);
  EXPECT_NEAR((out.normal - Vec2(1, 0)).norm(), 0, 1e-12);
  EXPECT_NEAR((out.point_a - Vec2(0.5, 0)).norm(), 0, 1e-12);
  EXPECT_NEAR(out.point_b.x() - out.point_a.x(), out.separation, 1e-12);
  EXPECT_LE(out.iterations, 3);  // pure translation of points: exact in one step
}

TEST(TimeOfImpact, FastSmallBoxHitsAThinWall) {
  // A 0.1 box at 480 m/s over a 1/60 s step (8 m) against a wall 0.02 thick.
  const ShapeGeometry wall = mink::RoundedPolygon{box(0.01, 1), 0};
  const ShapeGeometry bullet = mink::RoundedPolygon{box(0.05, 0.05), 0};
  const TimeOfImpactOutput out =
      toi(wall, still(0, 0), bullet, moving(Vec2(-4, 0.3), Vec2(4, 0.3), 0, 0));
  ASSERT_EQ(out.state, ToiState::hit);
  // The box's right face reaches x = -0.01 - target.
  EXPECT_NEAR(out.fraction, (4 - 0.05 - 0.01 - kSlop) / 8, kTolerance / 8);
  EXPECT_NEAR((out.normal - Vec2(-1, 0)).norm(), 0, 1e-12);
}

TEST(TimeOfImpact, SpinningRodSweepsAPoint) {
  // A rod of half length 1 turning about its middle; a circle of radius 0.1 at (0, 0.5). The
  // rod's distance to the circle's centre is 0.5 cos(angle) while it points within 60 degrees
  // of the x axis, so it hits at angle acos((0.1 + target) / 0.5).
  const ShapeGeometry rod = mink::Segment{Vec2(-1, 0), Vec2(1, 0)};
  const ShapeGeometry ball = mink::Circle{Vec2(0, 0), 0.1};
  const Real turn = 2 * std::numbers::pi;  // one turn a step
  const TimeOfImpactOutput out =
      toi(rod, moving(Vec2(0, 0), Vec2(0, 0), 0, turn), ball, still(0, 0.5));
  ASSERT_EQ(out.state, ToiState::hit);
  const Real angle = std::acos((0.1 + kSlop) / 0.5);
  // The separation is within tolerance, and so is the time, mapped through the distance's slope
  // 0.5 sin(angle) * turn.
  EXPECT_NEAR(out.separation, kSlop, kTolerance);
  EXPECT_GE(out.fraction * turn, angle - kTolerance / (0.5 * std::sin(angle)));
  EXPECT_LE(out.fraction * turn, angle + 1e-9);
}

TEST(TimeOfImpact, StatesBesideHit) {
  const ShapeGeometry a = mink::Circle{Vec2(0, 0), 0.5};
  const ShapeGeometry b = mink::Capsule{Vec2(-0.5, 0), Vec2(0.5, 0), 0.1};
  // Moving apart: the bound proves it at once.
  TimeOfImpactOutput out = toi(a, still(0, 0), b, moving(Vec2(2, 0), Vec2(5, 0)));
  EXPECT_EQ(out.state, ToiState::separated);
  EXPECT_EQ(out.fraction, 1);
  EXPECT_EQ(out.iterations, 1);
  // Passing by at a distance.
  out = toi(a, still(0, 0), b, moving(Vec2(-5, 1), Vec2(5, 1)));
  EXPECT_EQ(out.state, ToiState::separated);
  // Already overlapping.
  out = toi(a, still(0, 0), b, moving(Vec2(0.5, 0), Vec2(5, 0)));
  EXPECT_EQ(out.state, ToiState::overlapped);
  EXPECT_EQ(out.fraction, 0);
  // Within the tolerance at 0: a hit at 0, not an overlap.
  out = toi(a, still(0, 0), b, moving(Vec2(1.1 + kSlop, 0), Vec2(-5, 0)));
  EXPECT_EQ(out.state, ToiState::hit);
  EXPECT_EQ(out.fraction, 0);
  // A hit past max_fraction is not reported.
  TimeOfImpactInput in;
  in.shape_a = &a;
  in.sweep_a = still(0, 0);
  in.shape_b = &b;
  in.sweep_b = moving(Vec2(5, 0), Vec2(-5, 0));
  in.max_fraction = 0.3;
  out = time_of_impact(in);
  EXPECT_EQ(out.state, ToiState::separated);
  EXPECT_EQ(out.fraction, 0.3);
  in.max_fraction = 0.4;
  EXPECT_EQ(time_of_impact(in).state, ToiState::hit);
}

TEST(TimeOfImpact, GivesUpAtTheCapWithASafeTime) {
  // A spinning rod near a point needs many small steps; with a cap of 3 it stops early, at a
  // time still before the hit.
  const ShapeGeometry rod = mink::Segment{Vec2(-1, 0), Vec2(1, 0)};
  const ShapeGeometry ball = mink::Circle{Vec2(0, 0), 0.1};
  TimeOfImpactInput in;
  in.shape_a = &rod;
  in.sweep_a = moving(Vec2(0, 0), Vec2(0, 0), 0, 2 * std::numbers::pi);
  in.shape_b = &ball;
  in.sweep_b = still(0, 0.5);
  in.max_iterations = 3;
  const TimeOfImpactOutput out = time_of_impact(in);
  ASSERT_EQ(out.state, ToiState::gave_up);
  EXPECT_EQ(out.iterations, 3);
  EXPECT_GT(out.fraction, 0);
  EXPECT_LT(out.fraction * 2 * std::numbers::pi, std::acos((0.1 + kSlop) / 0.5));
  EXPECT_GT(out.separation, in.target + in.tolerance);
  in.max_iterations = 500;
  EXPECT_EQ(time_of_impact(in).state, ToiState::hit);
}

TEST(TimeOfImpact, RejectsBadInputNamingIt) {
  const ShapeGeometry a = mink::RoundedPolygon{box(0.5, 0.5), 0};
  const ShapeGeometry b = mink::Circle{Vec2(0, 0), 0.1};
  TimeOfImpactInput good;
  good.shape_a = &a;
  good.shape_b = &b;
  good.sweep_b = still(3, 0);
  EXPECT_NO_THROW(time_of_impact(good));
  auto message = [](const TimeOfImpactInput& in) {
    return invalid_argument_message([&] { time_of_impact(in); });
  };
  TimeOfImpactInput in = good;
  in.shape_a = nullptr;
  EXPECT_NE(message(in).find("shape_a"), std::string::npos);
  in = good;
  in.shape_b = nullptr;
  EXPECT_NE(message(in).find("shape_b"), std::string::npos);
  in = good;
  in.sweep_b.angle1 = std::nan("");
  EXPECT_NE(message(in).find("sweep_b"), std::string::npos);
  in = good;
  in.sweep_a.center1.x() = INFINITY;
  EXPECT_NE(message(in).find("sweep_a"), std::string::npos);
  in = good;
  in.max_fraction = 1.5;
  EXPECT_NE(message(in).find("max_fraction"), std::string::npos);
  in = good;
  in.tolerance = 0;
  EXPECT_NE(message(in).find("tolerance"), std::string::npos);
  in = good;
  in.target = -0.1;  // the cores would have to overlap: radii are 0.1
  EXPECT_NE(message(in).find("target"), std::string::npos);
  in = good;
  in.max_iterations = 0;
  EXPECT_NE(message(in).find("max_iterations"), std::string::npos);
  EXPECT_THROW(mink::slop_target(a, b, 0), mink::InvalidArgumentError);
}

TEST(TimeOfImpact, SlopTargetLetsRoundShapesSinkBySlop) {
  const ShapeGeometry sharp = mink::RoundedPolygon{box(0.5, 0.5), 0};
  const ShapeGeometry ball = mink::Circle{Vec2(0, 0), 0.1};
  const ShapeGeometry speck = mink::Circle{Vec2(0, 0), 0.002};
  EXPECT_EQ(mink::slop_target(sharp, sharp, kSlop), kSlop);
  EXPECT_NEAR(mink::slop_target(sharp, ball, kSlop), -kSlop, 1e-15);
  // Radii below two slops: the cores stop one slop apart.
  EXPECT_NEAR(mink::slop_target(sharp, speck, kSlop), kSlop - 0.002, 1e-15);
}

// ---- every pair kind against the sampled sweep ------------------------------------------------

struct PairKind {
  ShapeKind a;
  ShapeKind b;
};

std::vector<PairKind> all_pair_kinds() {
  std::vector<PairKind> pairs;
  for (int i = 0; i < 5; ++i)
    for (int j = i; j < 5; ++j) pairs.push_back({ShapeKind(i), ShapeKind(j)});
  return pairs;
}

std::string pair_name(const PairKind& p) {
  return std::string(kind_name(p.a)) + "_" + kind_name(p.b);
}

// The adaptive sweep against a plain one of 10^4 even samples: wherever an even sample is
// below the threshold by more than the adaptive sweep's resolution allows it to miss, the
// adaptive sweep has found a crossing no later. The even sweep stops at its first sample below,
// so the scans (right while the cores are apart) serve it; one that jumps from above straight
// into overlap only goes unjudged.
TEST(TimeOfImpact, AdaptiveOracleCatchesWhatAnEvenSweepSees) {
  std::mt19937_64 rng(6999);
  constexpr int kCases = 600 / kScale;
  constexpr int kSamples = 10000;
  const std::vector<PairKind> pairs = all_pair_kinds();
  int crossings = 0;
  for (int k = 0; k < kCases; ++k) {
    const PairKind kinds = pairs[static_cast<std::size_t>(k) % pairs.size()];
    const Family family = Family(k % 3);
    const SweepCase c = random_sweep_case(rng, kinds.a, kinds.b, family);
    const SweptShape sa(c.a, c.sweep_a), sb(c.b, c.sweep_b);
    const SweepOracle oracle(sa, sb);
    const Real threshold = mink::slop_target(c.a, c.b, kSlop) - kTolerance;
    const Real resolution = kTolerance / 8;
    if (oracle.exact_separation(0) < threshold) continue;
    const Crossing adaptive = oracle.first_below(threshold, 0, 1, resolution);
    for (int i = 1; i <= kSamples; ++i) {
      const Real t = Real(i) / kSamples;
      if (oracle.scan_separation(t) < threshold - resolution / 2 - 1e-12) {
        ++crossings;
        ASSERT_TRUE(adaptive.found) << pair_name(kinds) << " case " << k << " at " << t;
        ASSERT_LE(adaptive.time, t) << pair_name(kinds) << " case " << k;
        break;
      }
    }
  }
  EXPECT_GT(crossings, kCases / 5);
}

class TimeOfImpactOracle : public testing::TestWithParam<PairKind> {};

TEST_P(TimeOfImpactOracle, AgreesWithTheSampledSweep) {
  const PairKind kinds = GetParam();
  std::mt19937_64 rng(7000 + 10 * static_cast<int>(kinds.a) + static_cast<int>(kinds.b));
  constexpr int kCases = 100000 / kScale;
  Agreement by_family[3];
  for (int k = 0; k < kCases; ++k) {
    // Three in five ordinary, one fast spinning, one thin and fast.
    const Family family =
        k % 5 < 3 ? Family::ordinary : (k % 5 == 3 ? Family::fast_spin : Family::thin_fast);
    const SweepCase c = random_sweep_case(rng, kinds.a, kinds.b, family);
    TimeOfImpactInput in;
    in.shape_a = &c.a;
    in.sweep_a = c.sweep_a;
    in.shape_b = &c.b;
    in.sweep_b = c.sweep_b;
    in.max_fraction = c.max_fraction;
    in.target = mink::slop_target(c.a, c.b, kSlop);
    in.tolerance = kTolerance;
    Agreement& agreement = by_family[static_cast<int>(family)];
    const auto start = std::chrono::steady_clock::now();
    const TimeOfImpactOutput out = time_of_impact(in);
    agreement.seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const Reported reported{out.state,   out.fraction, out.separation, out.point_a,
                            out.point_b, out.normal,   out.iterations};
    const std::string error = check_against_oracle(c, in.target, in.tolerance, reported, agreement);
    ASSERT_EQ(error, "") << pair_name(kinds) << ", " << family_name(family) << " case " << k;
  }
  for (int f = 0; f < 3; ++f) {
    const Agreement& a = by_family[f];
    a.print(pair_name(kinds) + " " + family_name(Family(f)));
    // Both outcomes are well represented, so the agreement means something.
    EXPECT_GT(a.hits, a.cases / 10) << family_name(Family(f));
    EXPECT_GT(a.separated, a.cases / 10) << family_name(Family(f));
    // The cap is met rarely, if at all: at most one case in ten thousand.
    EXPECT_LE(a.gave_up, a.cases / 10000) << family_name(Family(f));
  }
}

INSTANTIATE_TEST_SUITE_P(PairKinds, TimeOfImpactOracle, testing::ValuesIn(all_pair_kinds()),
                         [](const testing::TestParamInfo<PairKind>& info) {
                           return pair_name(info.param);
                         });

}  // namespace
