#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <span>
#include <vector>

#include "mink/engine/scene.hpp"
#include "test_worlds.hpp"

namespace mink {
namespace {

using test::add_box;
using test::add_ground;

// Begin or end events alike: whether one names the pair, in either order.
template <typename Event>
bool has_pair(std::span<const Event> events, ShapeId a, ShapeId b) {
  return std::any_of(events.begin(), events.end(), [&](const Event& e) {
    return (e.shape_a == a && e.shape_b == b) || (e.shape_a == b && e.shape_b == a);
  });
}

TEST(Events, BeginWhenLandingEndWhenLifted) {
  World world;
  const BodyId ground = add_ground(world);
  const BodyId box = add_box(world, {0, 1.5});
  const ShapeId ground_shape = world.body_shapes(ground)[0];
  const ShapeId box_shape = world.body_shapes(box)[0];
  int begin_step = -1;
  for (int i = 0; i < 60 && begin_step < 0; ++i) {
    world.step();
    if (has_pair(world.contact_begin_events(), ground_shape, box_shape)) begin_step = i;
  }
  ASSERT_GE(begin_step, 0);
  // Free fall of 1 m takes about 0.45 s.
  EXPECT_NEAR(begin_step * world.def().time_step, 0.45, 0.05);
  world.step();
  EXPECT_TRUE(world.contact_begin_events().empty());
  EXPECT_EQ(world.counters().touching_contacts, 1u);
  EXPECT_GE(world.counters().broadphase_pairs, 1u);
  world.set_transform(box, Vec2(0, 5), 0);
  world.step();
  EXPECT_TRUE(has_pair(world.contact_end_events(), ground_shape, box_shape));
  EXPECT_EQ(world.counters().touching_contacts, 0u);
}

TEST(Events, DestroyingATouchingShapeEndsItsContacts) {
  World world;
  const BodyId ground = add_ground(world);
  const BodyId box = add_box(world, {0, 0.5});
  for (int i = 0; i < 5; ++i) world.step();
  ASSERT_EQ(world.counters().touching_contacts, 1u);
  const ShapeId box_shape = world.body_shapes(box)[0];
  world.destroy_body(box);
  EXPECT_TRUE(has_pair(world.contact_end_events(), world.body_shapes(ground)[0], box_shape));
  world.step();
  EXPECT_EQ(world.counters().touching_contacts, 0u);
  EXPECT_EQ(world.counters().contacts, 0u);
}

TEST(Events, AdvanceCollectsEventsOfAllItsSteps) {
  World world;
  add_ground(world);
  add_box(world, {0, 0.55});
  const AdvanceResult result = world.advance(10 * world.def().time_step);
  EXPECT_EQ(result.steps, 8);  // capped at max_steps_per_advance
  EXPECT_EQ(world.contact_begin_events().size(), 1u);
}

// A field of random shapes for the queries, checked against a scan of every shape.
struct Field {
  World world;
  std::vector<ShapeId> shapes;
};

Field make_field() {
  Field field{build_world(rain_scene(60, 21)), {}};
  for (int i = 0; i < 90; ++i) field.world.step();
  for (const BodyId id : field.world.bodies()) {
    for (const ShapeId s : field.world.body_shapes(id)) field.shapes.push_back(s);
  }
  std::sort(field.shapes.begin(), field.shapes.end(),
            [](ShapeId a, ShapeId b) { return a.index < b.index; });
  return field;
}

TEST(Queries, PointQueryMatchesAScanOfEveryHull) {
  Field field = make_field();
  World& world = field.world;
  int hits = 0;
  for (int i = 0; i < 400; ++i) {
    const Vec2 p(-12 + 24 * std::fmod(i * 0.618034, 1.0), 0.05 * i);
    std::vector<ShapeId> expected;
    for (const ShapeId s : field.shapes) {
      if (hull_contains(world.shape_hull(s), world.pose(world.shape_body(s)), p)) {
        expected.push_back(s);
      }
    }
    EXPECT_EQ(world.query_point(p), expected) << p.transpose();
    hits += expected.empty() ? 0 : 1;
  }
  EXPECT_GT(hits, 20);
}

// The separating-axis gap between a box and a convex polygon (counter-clockwise, world
// coordinates): the largest gap along the box's axes and the polygon's edge normals. Positive
// means apart by at least that much; negative, overlapping by that much along every axis.
Real separating_axis_gap(const Aabb& box, std::span<const Vec2> polygon) {
  Vec2 lower = polygon[0];
  Vec2 upper = polygon[0];
  for (const Vec2& v : polygon) {
    lower = lower.cwiseMin(v);
    upper = upper.cwiseMax(v);
  }
  Real gap = std::max({lower.x() - box.upper.x(), box.lower.x() - upper.x(),
                       lower.y() - box.upper.y(), box.lower.y() - upper.y()});
  const std::array<Vec2, 4> corners = {box.lower, Vec2(box.upper.x(), box.lower.y()), box.upper,
                                       Vec2(box.lower.x(), box.upper.y())};
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec2 a = polygon[i];
    const Vec2 edge = polygon[(i + 1) % polygon.size()] - a;
    const Vec2 outward = Vec2(edge.y(), -edge.x()).normalized();
    Real nearest = std::numeric_limits<Real>::infinity();
    for (const Vec2& c : corners) nearest = std::min(nearest, outward.dot(c - a));
    gap = std::max(gap, nearest);
  }
  return gap;
}

TEST(Queries, AabbQueryFindsExactlyTheOverlappingHulls) {
  Field field = make_field();
  World& world = field.world;
  // Closer to touching than this, the two computations may round either way: not judged.
  const Real tolerance = 1e-9;
  int overlapping = 0;
  int apart_but_boxes_overlap = 0;
  for (int i = 0; i < 200; ++i) {
    const Vec2 lower(-12 + 20 * std::fmod(i * 0.618034, 1.0), 0.05 * i);
    const Aabb box{lower, lower + Vec2(1.5, 0.7)};
    const std::vector<ShapeId> found = world.query_aabb(box);
    EXPECT_TRUE(std::is_sorted(found.begin(), found.end(),
                               [](ShapeId a, ShapeId b) { return a.index < b.index; }));
    for (const ShapeId s : found) {
      EXPECT_NE(std::find(field.shapes.begin(), field.shapes.end(), s), field.shapes.end());
    }
    for (const ShapeId s : field.shapes) {
      const bool listed = std::count(found.begin(), found.end(), s) == 1;
      std::vector<Vec2> polygon;
      const Pose pose = world.pose(world.shape_body(s));
      for (const Vec2& v : world.shape_hull(s).vertices()) polygon.push_back(pose.apply(v));
      const Real gap = separating_axis_gap(box, polygon);
      if (gap < -tolerance) {
        EXPECT_TRUE(listed) << "box " << i << " overlaps shape " << s.index << " by " << -gap;
        ++overlapping;
      } else if (gap > tolerance) {
        EXPECT_FALSE(listed) << "box " << i << " is " << gap << " from shape " << s.index;
        apart_but_boxes_overlap += world.shape_aabb(s).overlaps(box);
      }
    }
  }
  // Both verdicts were exercised, including shapes whose boxes overlap the query box.
  EXPECT_GT(overlapping, 20);
  EXPECT_GE(apart_but_boxes_overlap, 5);
}

TEST(Queries, RayCastMatchesAScanOfEveryHull) {
  Field field = make_field();
  World& world = field.world;
  int hits = 0;
  for (int i = 0; i < 200; ++i) {
    const Vec2 origin(-14, 0.2 + 0.1 * i);
    const Vec2 translation(28, -3 + 6 * std::fmod(i * 0.618034, 1.0));
    std::optional<ShapeRayHit> expected;
    for (const ShapeId s : field.shapes) {
      const auto hit =
          ray_cast_hull(world.shape_hull(s), world.pose(world.shape_body(s)), origin, translation);
      if (hit && (!expected || hit->fraction < expected->hit.fraction)) {
        expected = ShapeRayHit{s, *hit};
      }
    }
    const auto got = world.ray_cast(origin, translation);
    ASSERT_EQ(got.has_value(), expected.has_value()) << i;
    if (!got) continue;
    ++hits;
    EXPECT_EQ(got->shape, expected->shape);
    EXPECT_DOUBLE_EQ(got->hit.fraction, expected->hit.fraction);
    // The hit point is on the hull boundary and the normal faces the ray.
    EXPECT_LT(got->hit.normal.dot(translation), 0);
    EXPECT_NEAR(got->hit.normal.norm(), 1, 1e-12);
  }
  EXPECT_GT(hits, 50);
}

TEST(Queries, RayCastAgainstABoxHitsTheNearFace) {
  const ConvexHull box = make_shape_hull(ShapeDef::box(1, 1));
  const Pose pose{Vec2(5, 0), Rotation::from_angle(0)};
  const auto hit = ray_cast_hull(box, pose, Vec2(0, 0.5), Vec2(10, 0));
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->fraction, 0.4, 1e-12);
  EXPECT_NEAR(hit->point.x(), 4, 1e-12);
  EXPECT_NEAR(hit->normal.x(), -1, 1e-12);
  EXPECT_FALSE(ray_cast_hull(box, pose, Vec2(0, 1.5), Vec2(10, 0)));  // passes above
  EXPECT_FALSE(ray_cast_hull(box, pose, Vec2(0, 0.5), Vec2(3, 0)));   // stops short
  EXPECT_FALSE(ray_cast_hull(box, pose, Vec2(5, 0), Vec2(10, 0)));    // starts inside
  const Pose turned{Vec2(5, 0), Rotation::from_angle(std::numbers::pi / 4)};
  const auto corner = ray_cast_hull(box, turned, Vec2(0, 0), Vec2(10, 0));
  ASSERT_TRUE(corner);
  EXPECT_NEAR(corner->point.x(), 5 - std::sqrt(2.0), 1e-12);
}

}  // namespace
}  // namespace mink

namespace mink {
namespace {

// Counts what World::draw reports, layer by layer.
class CountingDraw : public DebugDraw {
 public:
  void draw_polygon(std::span<const Vec2> vertices, Color fill, Color) override {
    (fill.a > 0 ? filled_polygons : outlines) += 1;
    vertex_count += vertices.size();
  }
  void draw_segment(const Vec2&, const Vec2&, Color) override { ++segments; }
  void draw_point(const Vec2&, float, Color) override { ++points; }
  void draw_circle(const Vec2&, Real, Color) override {}
  void draw_text(const Vec2&, std::string_view, Color) override {}
  int filled_polygons = 0, outlines = 0, segments = 0, points = 0;
  std::size_t vertex_count = 0;
};

TEST(DebugDrawing, EachLayerReportsWhatTheWorldHolds) {
  World world;
  add_ground(world);
  add_box(world, {0, 0.5});
  add_box(world, {3, 0.5});
  for (int i = 0; i < 10; ++i) world.step();
  CountingDraw shapes_only;
  shapes_only.layers = draw_shapes;
  world.draw(shapes_only);
  EXPECT_EQ(shapes_only.filled_polygons, 3);
  EXPECT_EQ(shapes_only.vertex_count, 12u);
  EXPECT_EQ(shapes_only.segments + shapes_only.points + shapes_only.outlines, 0);
  CountingDraw everything;
  everything.layers = ~0u;
  world.draw(everything);
  EXPECT_EQ(everything.outlines, 3);  // one fat box per shape
  // Two contacts of two points each, a normal per point, a pair segment per broadphase pair,
  // a velocity segment per moving body, a centre of mass per moving body.
  EXPECT_EQ(everything.points, 4 + 2);
  EXPECT_EQ(everything.segments, 4 + static_cast<int>(world.counters().broadphase_pairs) + 2);
}

}  // namespace
}  // namespace mink
