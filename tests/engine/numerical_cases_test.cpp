// Hard numerical cases: large mass ratios, sizes from a millimetre to a kilometre, a hull of a
// million vertices, slivers, exact touching, nearly parallel edges and coordinates near 1e9.
// The engine must never assert, hang or produce NaN on them; what it cannot handle it refuses
// at creation with a typed error.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "mink/error.hpp"
#include "mink/geometry/convex_hull.hpp"
#include "mink/geometry/point_sets.hpp"
#include "mink/narrowphase/gjk_distance.hpp"
#include "mink/narrowphase/manifold.hpp"
#include "mink/narrowphase/prepared_hull.hpp"
#include "test_worlds.hpp"

namespace {

using namespace mink;
using mink::test::add_ground;
using mink::test::finite_state;

using mink::test::all_finite;

BodyId add_box_body(World& world, const Vec2& position, Real hx, Real hy, Real density = 1) {
  BodyDef def;
  def.type = BodyType::dynamic;
  def.position = position;
  const BodyId body = world.create_body(def);
  ShapeDef shape = ShapeDef::box(hx, hy);
  shape.density = density;
  world.create_shape(body, shape);
  return body;
}

// Three 1 m boxes on the ground; those above the bottom one `ratio` times as dense when
// `heavy_on_light`, else the bottom one `ratio` times as dense as those above. After 10 s the
// stack stands: every box upright above the one below, sunk into it by at most `sink` each
// and off centre by at most `sideways`.
void expect_stack_stands(Real ratio, bool heavy_on_light, Real sink, const WorldDef& def = {},
                         Real sideways = 0.01) {
  World world(def);
  add_ground(world);
  std::vector<BodyId> boxes;
  for (int level = 0; level < 3; ++level) {
    const bool heavy = (level == 0) != heavy_on_light;
    boxes.push_back(add_box_body(world, Vec2(0, 0.5 + level), 0.5, 0.5, heavy ? ratio : 1));
  }
  for (int i = 0; i < 600; ++i) {
    world.step();
    ASSERT_TRUE(all_finite(world)) << "ratio " << ratio << ", step " << i;
  }
  for (int level = 0; level < 3; ++level) {
    const Vec2 p = world.position(boxes[level]);
    EXPECT_NEAR(p.x(), 0, sideways) << "ratio " << ratio << ", level " << level;
    EXPECT_NEAR(world.angle(boxes[level]), 0, 0.01) << "ratio " << ratio << ", level " << level;
    // Resting height below the ideal (0.5, 1.5, 2.5) by at most `sink` per contact under it.
    EXPECT_LT(p.y(), 0.5 + level + 1e-3) << "ratio " << ratio << ", level " << level;
    EXPECT_GT(p.y(), 0.5 + level - sink * (level + 1)) << "ratio " << ratio << ", level " << level;
  }
}

// 200 kg boxes on a 1 kg one at the default settings: it stands, the light box squeezed by
// a fraction of a millimetre (solved as one system, as the 1:1000 stack below).
TEST(NumericalCases, StackWithMassRatio100Stands) {
  expect_stack_stands(100, true, 0.001);
  expect_stack_stands(100, false, 0.001);
}

// 1:1000, both ways up, at the default settings (60 Hz contacts, 5 substeps). A light box under
// heavy ones is where one contact at a time fails: the soft contact under 2000 times the box's
// own weight gives way and the stack falls (Box2D v3's middle box sinks through). The contacts
// of a stack of lopsided masses are solved as one system (contact_stack_solver.hpp), and the
// light box is squeezed by its own weight's share, a fraction of a millimetre. Stiffer contacts
// on shorter substeps hold it too.
TEST(NumericalCases, StackWithMassRatio1000Stands) {
  expect_stack_stands(1000, false, 0.001);
  expect_stack_stands(1000, true, 0.001);
  WorldDef stiff;
  stiff.substeps = 20;
  stiff.contact_hertz = 120;
  expect_stack_stands(1000, true, 0.001, stiff);
}

// Boxes of 1 mm, 1 cm, 10 cm, 1 m, 10 m and 100 m side by side on a 1 km ground: each comes to
// rest on it, upright, sunk by less than a tenth of its own size.
TEST(NumericalCases, ShapesFromAMillimetreToAKilometreRestTogether) {
  World world;
  add_ground(world, 500);  // 1 km wide
  std::vector<std::pair<BodyId, Real>> boxes;
  Real x = -400;
  for (const Real size : {0.001, 0.01, 0.1, 1.0, 10.0, 100.0}) {
    x += size / 2;
    boxes.push_back({add_box_body(world, Vec2(x, size), size / 2, size / 2), size});
    x += size / 2 + 10;
  }
  const BodyId grain = test::add_ball(world, Vec2(300, 0.002), 0.0005);  // a 1 mm ball
  for (int i = 0; i < 600; ++i) {
    world.step();
    ASSERT_TRUE(all_finite(world)) << "step " << i;
  }
  for (const auto& [box, size] : boxes) {
    const Vec2 p = world.position(box);
    EXPECT_LT(p.y(), size / 2 + size * 1e-3) << "size " << size;
    EXPECT_GT(p.y(), size / 2 - size * 0.1) << "size " << size;
    EXPECT_NEAR(world.angle(box), 0, 1e-2) << "size " << size;
  }
  EXPECT_GT(world.position(grain).y(), 0.0005 * 0.9);
  EXPECT_LT(world.position(grain).y(), 0.0005 * 1.1);
}

// A hull of 10^6 points on a circle of radius 2 becomes a body whose mass properties are a
// disk's (up to the polygon's deficit), falls onto the ground and rests there.
TEST(NumericalCases, MillionVertexHullIsABodyThatCollides) {
  constexpr std::size_t kPoints = 1'000'000;
  constexpr Real kRadius = 2;
  ShapeDef shape;
  shape.type = ShapeType::polygon;
  shape.points.reserve(kPoints);
  for (std::size_t i = 0; i < kPoints; ++i) {
    const Real angle = 2 * std::numbers::pi * static_cast<Real>(i) / kPoints;
    shape.points.emplace_back(kRadius * std::cos(angle), kRadius * std::sin(angle));
  }
  World world;
  add_ground(world);
  BodyDef def;
  def.type = BodyType::dynamic;
  def.position = Vec2(0, 3);
  const BodyId body = world.create_body(def);
  const ShapeId id = world.create_shape(body, shape);
  EXPECT_GT(world.shape_hull(id).size(), kPoints / 2);
  const Real area = std::numbers::pi * kRadius * kRadius;
  EXPECT_NEAR(world.mass(body), area, area * 1e-9);
  EXPECT_NEAR(world.rotational_inertia(body), area * kRadius * kRadius / 2, area * 1e-8);
  for (int i = 0; i < 180; ++i) {
    world.step();
    ASSERT_TRUE(finite_state(world, body)) << "step " << i;
  }
  EXPECT_NEAR(world.position(body).y(), kRadius, 0.01);
  EXPECT_NEAR(world.position(body).x(), 0, 0.01);
}

// A plank of aspect 1:10^4 (10 m by 1 mm) falls flat onto the ground and a 1 m box lands on it:
// neither passes through, both rest.
TEST(NumericalCases, SliverRestsAndCarriesABox) {
  World world;
  add_ground(world);
  const BodyId sliver = add_box_body(world, Vec2(0, 0.5), 5, 0.0005);
  const BodyId box = add_box_body(world, Vec2(1, 2), 0.5, 0.5);
  // And a sliver standing on its 1 mm end, which must topple, not pass through.
  const BodyId standing = add_box_body(world, Vec2(-20, 5.01), 0.0005, 5);
  for (int i = 0; i < 600; ++i) {
    world.step();
    ASSERT_TRUE(all_finite(world)) << "step " << i;
  }
  EXPECT_GT(world.position(sliver).y(), 0);
  EXPECT_LT(world.position(sliver).y(), 0.0006);
  EXPECT_NEAR(world.angle(sliver), 0, 1e-3);
  EXPECT_NEAR(world.position(box).y(), 0.001 + 0.5, 0.01);
  EXPECT_GT(world.position(standing).y(), 0);
  EXPECT_LT(world.position(standing).y(), 5.01);
}

PreparedHull box_hull(Real hx, Real hy) {
  const std::vector<Vec2> corners = {{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}};
  return PreparedHull(build_hull(corners, HullAlgorithm::monotone_chain));
}

Pose at(const Vec2& position, Real angle = 0) {
  Pose pose;
  pose.position = position;
  pose.rotation = Rotation::from_angle(angle);
  return pose;
}

bool unit_and_finite(const Vec2& n) {
  return std::isfinite(n.x()) && std::isfinite(n.y()) && std::abs(n.norm() - 1) < 1e-12;
}

// Faces touching at exactly zero distance: GJK reports contact at distance 0 and the manifold
// has two points of separation 0 along the shared face's normal.
TEST(NumericalCases, TouchingAtExactlyZeroDistance) {
  const PreparedHull box = box_hull(0.5, 0.5);
  for (const Real x : {0.0, 0.25, 0.9}) {
    const DistanceResult d = gjk_distance(box, at(Vec2(0, 0)), box, at(Vec2(x, 1)));
    EXPECT_EQ(d.distance, 0) << x;
    const Manifold m = collide_hulls(box, at(Vec2(0, 0)), box, at(Vec2(x, 1)), 0.01);
    ASSERT_GE(m.point_count, 1) << x;
    EXPECT_TRUE(unit_and_finite(m.normal)) << x;
    EXPECT_NEAR(m.normal.y(), 1, 1e-12) << x;
    for (int i = 0; i < m.point_count; ++i) EXPECT_EQ(m.points[i].separation, 0) << x;
  }
  // Corner to corner, and two hulls at one pose (all overlap, no preferred direction).
  const Manifold corner = collide_hulls(box, at(Vec2(0, 0)), box, at(Vec2(1, 1)), 0.01);
  EXPECT_TRUE(corner.point_count == 0 || unit_and_finite(corner.normal));
  const Manifold same = collide_hulls(box, at(Vec2(3, 4)), box, at(Vec2(3, 4)), 0.01);
  ASSERT_GE(same.point_count, 1);
  EXPECT_TRUE(unit_and_finite(same.normal));
  for (int i = 0; i < same.point_count; ++i) {
    EXPECT_NEAR(same.points[i].separation, -1, 1e-12);
  }
  // In a world: a box placed exactly on the ground, two balls at one centre, two boxes at one
  // pose. Stepping gives finite states; the coincident pairs are pushed apart.
  World world;
  add_ground(world);
  const BodyId resting = test::add_box(world, Vec2(0, 0.5));
  const BodyId ball_a = test::add_ball(world, Vec2(5, 3), 0.5);
  const BodyId ball_b = test::add_ball(world, Vec2(5, 3), 0.5);
  const BodyId box_a = test::add_box(world, Vec2(-5, 3));
  const BodyId box_b = test::add_box(world, Vec2(-5, 3));
  for (int i = 0; i < 240; ++i) {
    world.step();
    ASSERT_TRUE(all_finite(world)) << "step " << i;
  }
  EXPECT_NEAR(world.position(resting).y(), 0.5, 0.01);
  EXPECT_GT((world.position(ball_a) - world.position(ball_b)).norm(), 0.9);
  EXPECT_GT((world.position(box_a) - world.position(box_b)).norm(), 0.9);
}

// Parallel faces 1e-12 apart, and overlapping by 1e-12: one normal across the gap, two points,
// separations of that size (the rounding of coordinates near 1 is 1e-16).
TEST(NumericalCases, ParallelEdgesAtTinyOffsets) {
  const PreparedHull box = box_hull(0.5, 0.5);
  for (const Real gap : {1e-12, -1e-12, 0.0}) {
    for (const Real slide : {0.0, 0.3, 0.999}) {
      const Manifold m = collide_hulls(box, at(Vec2(0, 0)), box, at(Vec2(1 + gap, slide)), 0.01);
      ASSERT_EQ(m.point_count, 2) << gap << " " << slide;
      EXPECT_TRUE(unit_and_finite(m.normal));
      EXPECT_NEAR(m.normal.x(), 1, 1e-12);
      for (int i = 0; i < 2; ++i) EXPECT_NEAR(m.points[i].separation, gap, 1e-15);
      const DistanceResult d = gjk_distance(box, at(Vec2(0, 0)), box, at(Vec2(1 + gap, slide)));
      EXPECT_NEAR(d.distance, std::max(gap, 0.0), 1e-15);
      EXPECT_FALSE(d.reached_iteration_cap);
    }
  }
  // Edges turned by 1e-12 radians against each other.
  const Manifold tilted =
      collide_hulls(box, at(Vec2(0, 0)), box, at(Vec2(1 + 1e-12, 0.2), 1e-12), 0.01);
  ASSERT_EQ(tilted.point_count, 2);
  EXPECT_TRUE(unit_and_finite(tilted.normal));
  for (int i = 0; i < 2; ++i) EXPECT_NEAR(tilted.points[i].separation, 1e-12, 1e-12);
}

// Two boxes and two large round hulls posed near (1e9, 1e9), where doubles are 1.2e-7 apart:
// distance and manifold come out as at the origin, to that resolution.
TEST(NumericalCases, NarrowphaseNearCoordinates1e9) {
  const PreparedHull box = box_hull(0.5, 0.5);
  std::vector<Vec2> ring = generate_points(PointDistribution::on_circle, 200, 9);
  const PreparedHull round(build_hull(ring, HullAlgorithm::monotone_chain));
  const Vec2 far(1e9, 1e9);
  for (const Real angle : {0.0, 0.3, 1.2}) {
    for (const Real gap : {0.25, 0.001, -0.01}) {
      for (const PreparedHull* hull : {&box, &round}) {
        const Pose a0 = at(Vec2(0, 0), angle);
        const Pose b0 = at(Vec2(1.6 + gap, 0.1));
        const Pose a1 = at(far, angle);
        const Pose b1 = at(far + Vec2(1.6 + gap, 0.1));
        const DistanceResult near_origin = gjk_distance(*hull, a0, box, b0);
        const DistanceResult far_away = gjk_distance(*hull, a1, box, b1);
        EXPECT_NEAR(far_away.distance, near_origin.distance, 1e-6);
        EXPECT_FALSE(far_away.reached_iteration_cap);
        const Manifold m0 = collide_hulls(*hull, a0, box, b0, 0.1);
        const Manifold m1 = collide_hulls(*hull, a1, box, b1, 0.1);
        ASSERT_EQ(m1.point_count, m0.point_count) << angle << " " << gap;
        if (m0.point_count == 0) continue;
        EXPECT_TRUE(unit_and_finite(m1.normal));
        EXPECT_NEAR((m1.normal - m0.normal).norm(), 0, 1e-6);
        for (int i = 0; i < m0.point_count; ++i) {
          EXPECT_NEAR(m1.points[i].separation, m0.points[i].separation, 1e-6);
          EXPECT_NEAR((m1.points[i].point - far - m0.points[i].point).norm(), 0, 1e-6);
        }
      }
    }
  }
}

}  // namespace
