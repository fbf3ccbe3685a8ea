// Shape casts: closed forms, and every pair kind against the brute-force sampled sweep.

#include "mink/narrowphase/shape_cast.hpp"

#include <gtest/gtest.h>

#include <chrono>

#include "sweep_cases.hpp"

namespace {

using namespace mink_test;
using mink::ShapeCastInput;
using mink::ShapeCastOutput;
using mink::ToiState;

ShapeCastInput cast(const ShapeGeometry& shape, const Pose& pose, const Vec2& translation,
                    const ShapeGeometry& obstacle, const Pose& obstacle_pose) {
  ShapeCastInput in;
  in.shape = &shape;
  in.pose = pose;
  in.translation = translation;
  in.obstacle = &obstacle;
  in.obstacle_pose = obstacle_pose;
  in.target = kSlop;
  in.tolerance = kTolerance;
  return in;
}

TEST(ShapeCast, CircleOntoABoxFace) {
  const ShapeGeometry ball = mink::Circle{Vec2(0, 0), 0.25};
  const ShapeGeometry crate = mink::RoundedPolygon{box(0.5, 0.5), 0};
  const ShapeCastOutput out =
      shape_cast(cast(ball, pose_at(-3, 0.2), Vec2(6, 0), crate, pose_at(0, 0)));
  ASSERT_EQ(out.state, ToiState::hit);
  EXPECT_NEAR(out.fraction, (3 - 0.75 - kSlop) / 6, kTolerance / 6);
  EXPECT_NEAR((out.point - Vec2(-0.5, 0.2)).norm(), 0, 1e-12);
  EXPECT_NEAR((out.normal - Vec2(-1, 0)).norm(), 0, 1e-12);
  EXPECT_NEAR(out.separation, kSlop, kTolerance);
  EXPECT_LE(out.iterations, 3);
}

TEST(ShapeCast, BoxCornerOntoATurnedBox) {
  // A box turned 45 degrees cast down onto a flat one: its lowest corner leads.
  const ShapeGeometry crate = mink::RoundedPolygon{box(0.5, 0.5), 0};
  const ShapeGeometry floor = mink::RoundedPolygon{box(5, 0.5), 0};
  const Real corner = 0.5 * std::sqrt(2.0);
  const ShapeCastOutput out = shape_cast(
      cast(crate, pose_at(1, 3, std::numbers::pi / 4), Vec2(0, -4), floor, pose_at(0, 0)));
  ASSERT_EQ(out.state, ToiState::hit);
  EXPECT_NEAR(out.fraction, (3 - corner - 0.5 - kSlop) / 4, kTolerance / 4);
  EXPECT_NEAR((out.point - Vec2(1, 0.5)).norm(), 0, 1e-9);
  EXPECT_NEAR((out.normal - Vec2(0, 1)).norm(), 0, 1e-12);
}

TEST(ShapeCast, MissOverlapAndCutShort) {
  const ShapeGeometry ball = mink::Circle{Vec2(0, 0), 0.25};
  const ShapeGeometry wall = mink::Segment{Vec2(0, -1), Vec2(0, 1)};
  ShapeCastInput in = cast(ball, pose_at(-2, 0), Vec2(4, 0), wall, pose_at(0, 0));
  EXPECT_EQ(shape_cast(in).state, ToiState::hit);
  in.pose = pose_at(-2, 1.5);  // passes above the wall's end
  EXPECT_EQ(shape_cast(in).state, ToiState::separated);
  in.pose = pose_at(-0.1, 0);  // starts on the wall
  EXPECT_EQ(shape_cast(in).state, ToiState::overlapped);
  in.pose = pose_at(-2, 0);
  in.max_fraction = 0.4;  // the hit is at (2 - 0.25 - target) / 4 = 0.436
  const ShapeCastOutput out = shape_cast(in);
  EXPECT_EQ(out.state, ToiState::separated);
  EXPECT_EQ(out.fraction, 0.4);
}

TEST(ShapeCast, RejectsBadInputNamingIt) {
  const ShapeGeometry ball = mink::Circle{Vec2(0, 0), 0.25};
  const ShapeCastInput good = cast(ball, pose_at(-2, 0), Vec2(4, 0), ball, pose_at(0, 0));
  auto message = [](const ShapeCastInput& in) {
    return invalid_argument_message([&] { shape_cast(in); });
  };
  EXPECT_EQ(message(good), "no error");
  ShapeCastInput in = good;
  in.shape = nullptr;
  EXPECT_NE(message(in).find("shape is null"), std::string::npos);
  in = good;
  in.obstacle = nullptr;
  EXPECT_NE(message(in).find("obstacle"), std::string::npos);
  in = good;
  in.translation.y() = std::nan("");
  EXPECT_NE(message(in).find("translation"), std::string::npos);
  in = good;
  in.obstacle_pose.position.x() = INFINITY;
  EXPECT_NE(message(in).find("obstacle_pose"), std::string::npos);
  in = good;
  in.tolerance = -1;
  EXPECT_NE(message(in).find("tolerance"), std::string::npos);
}

// Every pair kind: the obstacle at rest, the moving shape not turning, as the sampled sweep
// sees them.
class ShapeCastOracle : public testing::TestWithParam<ShapeKind> {};

TEST_P(ShapeCastOracle, AgreesWithTheSampledSweep) {
  const ShapeKind obstacle_kind = GetParam();
  std::mt19937_64 rng(8000 + static_cast<int>(obstacle_kind));
  constexpr int kCasesPerKind = 20000 / kScale;
  const ShapeKind kinds[] = {ShapeKind::circle, ShapeKind::capsule, ShapeKind::segment,
                             ShapeKind::chain_segment, ShapeKind::polygon};
  for (ShapeKind moving_kind : kinds) {
    Agreement agreement;
    for (int k = 0; k < kCasesPerKind; ++k) {
      const Family family = k % 2 == 0 ? Family::ordinary : Family::thin_fast;
      SweepCase c = random_sweep_case(rng, obstacle_kind, moving_kind, family, false);
      if (mink::kind_of(c.a) != obstacle_kind) {  // the case came swapped: unswap it
        std::swap(c.a, c.b);
        std::swap(c.sweep_a, c.sweep_b);
      }
      c.sweep_a.center1 = c.sweep_a.center0;
      ShapeCastInput in = cast(c.b, c.sweep_b.pose_at(0), c.sweep_b.center1 - c.sweep_b.center0,
                               c.a, c.sweep_a.pose_at(0));
      in.max_fraction = c.max_fraction;
      in.target = mink::slop_target(c.a, c.b, kSlop);
      const auto start = std::chrono::steady_clock::now();
      const ShapeCastOutput out = shape_cast(in);
      agreement.seconds +=
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const Reported reported{out.state,    out.fraction, out.separation, out.point,
                              std::nullopt, out.normal,   out.iterations};
      const std::string error =
          check_against_oracle(c, in.target, in.tolerance, reported, agreement);
      ASSERT_EQ(error, "") << kind_name(moving_kind) << " onto " << kind_name(obstacle_kind)
                           << " case " << k;
    }
    agreement.print(std::string("cast ") + kind_name(moving_kind) + " onto " +
                    kind_name(obstacle_kind));
    EXPECT_GT(agreement.hits, agreement.cases / 10);
    EXPECT_GT(agreement.separated, agreement.cases / 10);
    EXPECT_EQ(agreement.gave_up, 0);
  }
}

INSTANTIATE_TEST_SUITE_P(ObstacleKinds, ShapeCastOracle,
                         testing::Values(ShapeKind::circle, ShapeKind::capsule, ShapeKind::segment,
                                         ShapeKind::chain_segment, ShapeKind::polygon),
                         [](const testing::TestParamInfo<ShapeKind>& info) {
                           return std::string(kind_name(info.param));
                         });

}  // namespace
