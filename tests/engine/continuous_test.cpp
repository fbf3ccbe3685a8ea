// Continuous collision: small, fast, spinning bodies fired at thin walls, at chain terrain and
// at each other never pass through, and never end inside what they hit.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "mink/engine/scene.hpp"
#include "mink/engine/scene_schedule.hpp"
#include "mink/error.hpp"
#include "mink/narrowphase/shape_geometry.hpp"

#include "test_worlds.hpp"

namespace mink {
namespace {

// The projectiles of the issue: circles of radius 0.05, boxes of 0.1, thin capsules, 3-gons.
ShapeDef projectile(int kind) {
  switch (kind % 4) {
    case 0:
      return ShapeDef::circle(0.05);
    case 1:
      return ShapeDef::box(0.05, 0.05);
    case 2:
      return ShapeDef::capsule(Vec2(-0.08, 0), Vec2(0.08, 0), 0.01);
    default:
      return ShapeDef::regular_polygon(3, 0.06);
  }
}

const char* projectile_name(int kind) {
  static const char* names[] = {"circle", "box", "capsule", "triangle"};
  return names[kind % 4];
}

struct Shot {
  int kind;
  Real speed, spin, offset, angle;
};

Shot random_shot(std::mt19937_64& rng, int kind) {
  std::uniform_real_distribution<Real> speed(50, 500), spin(-200, 200), offset(-0.5, 0.5),
      angle(-std::numbers::pi, std::numbers::pi);
  return {kind, speed(rng), spin(rng), offset(rng), angle(rng)};
}

WorldDef zero_gravity() {
  WorldDef def = test::free_world();
  def.gravity = Vec2(0, 0);
  return def;
}

BodyId fire(World& world, const Shot& shot, const Vec2& from, const Vec2& direction) {
  BodyDef def;
  def.type = BodyType::dynamic;
  def.position = from;
  def.angle = shot.angle;
  def.linear_velocity = shot.speed * direction;
  def.angular_velocity = shot.spin;
  const BodyId body = world.create_body(def);
  world.create_shape(body, projectile(shot.kind));
  return body;
}

// Box2D v3's continuous collision: fast bodies swept against still shapes only, their boxes
// bare after a sweep that stops them nowhere. Most fast bodies are then settled as their step
// finishes (nothing in their way needs a sweep), the rest by the continuous phase.
void as_box2d_v3(WorldDef& def) {
  def.continuous_fast_pairs = false;
  def.fast_body_margin = false;
}

// A wall 0.02 thick and 40 tall at x = 0 (a deflected shot slides along it, never off its end);
// the shot starts 1.5 m to its left, so it reaches the wall within two steps.
bool passes_wall(const Shot& shot, bool continuous = true, bool v3_settings = false) {
  WorldDef def = zero_gravity();
  def.enable_continuous = continuous;
  if (v3_settings) as_box2d_v3(def);
  World world(def);
  const BodyId wall = world.create_body({});
  world.create_shape(wall, ShapeDef::box(0.01, 20));
  const BodyId body = fire(world, shot, Vec2(-1.5, shot.offset), Vec2(1, 0));
  for (int i = 0; i < 30; ++i) {
    world.step();
    // Its centre beyond the wall's middle plane: it went through.
    if (world.position(body).x() > 0) return true;
  }
  return false;
}

TEST(Continuous, ShotsAtAThinWallNeverPassThrough) {
  std::mt19937_64 rng(1);
  int passed[4] = {};
  const int shots = 4000;
  for (int i = 0; i < shots; ++i) {
    const Shot shot = random_shot(rng, i);
    if (passes_wall(shot)) ++passed[i % 4];
  }
  for (int k = 0; k < 4; ++k) {
    std::printf("%s: %d of %d passed the wall\n", projectile_name(k), passed[k], shots / 4);
    EXPECT_EQ(passed[k], 0) << projectile_name(k);
  }
}

// Half a projectile's thinness: a contact lets shapes overlap by the linear slop, never by
// this much.
Real half_thinness(int kind) {
  switch (kind % 4) {
    case 0:
    case 1:
      return 0.025;
    case 2:
      return 0.005;
    default:
      return 0.5 * 0.06 * std::cos(std::numbers::pi / 3);  // half the triangle's inradius
  }
}

// Whether either projectile is inside the other: the circle of half its thinness about its
// middle (its origin) overlaps the other's shape.
bool inside(const World& world, BodyId a, int kind_a, BodyId b, int kind_b) {
  const auto middle_in = [&](BodyId x, int kind, BodyId y) {
    const Circle middle{Vec2(0, 0), half_thinness(kind)};
    return shape_distance(ShapeGeometry(middle), world.pose(x),
                          world.shape_geometry(world.body_shapes(y).front()), world.pose(y))
        .overlap;
  };
  return middle_in(a, kind_a, b) || middle_in(b, kind_b, a);
}

// The same shots with continuous collision off: speculative contacts alone let most of them
// through (so the test above can fail).
TEST(Continuous, WithoutItShotsTunnel) {
  std::mt19937_64 rng(1);
  int passed = 0;
  for (int i = 0; i < 400; ++i) passed += passes_wall(random_shot(rng, i), false);
  std::printf("continuous collision off: %d of 400 shots passed the wall\n", passed);
  EXPECT_GT(passed, 100);
}

// Chain terrain: a zigzag of 0.5 m teeth; shots come down at it steeply from above. Nothing
// may end below the terrain line.
bool passes_terrain(const Shot& shot, bool v3_settings = false) {
  WorldDef def = zero_gravity();
  if (v3_settings) as_box2d_v3(def);
  World world(def);
  const BodyId ground = world.create_body({});
  std::vector<Vec2> points;
  for (int i = 20; i >= -20; --i) points.emplace_back(0.5 * i, (i % 2 == 0) ? 0.0 : 0.25);
  world.create_chain(ground, ShapeDef::chain(points));
  const Vec2 direction = Vec2(0.3 * shot.offset, -1).normalized();
  const BodyId body = fire(world, shot, Vec2(shot.offset, 1.5), direction);
  for (int i = 0; i < 30; ++i) {
    world.step();
    if (world.position(body).y() < -0.001) return true;
  }
  return false;
}

TEST(Continuous, ShotsAtChainTerrainNeverPassThrough) {
  std::mt19937_64 rng(2);
  int passed[4] = {};
  const int shots = 2000;
  for (int i = 0; i < shots; ++i) {
    if (passes_terrain(random_shot(rng, i))) ++passed[i % 4];
  }
  for (int k = 0; k < 4; ++k) {
    std::printf("%s: %d of %d went through the terrain\n", projectile_name(k), passed[k],
                shots / 4);
    EXPECT_EQ(passed[k], 0) << projectile_name(k);
  }
}

TEST(Continuous, ShotsNeverPassThroughAtBox2dV3sSettings) {
  std::mt19937_64 rng(7);
  int walls[4] = {}, terrain[4] = {};
  const int shots = 1000;
  for (int i = 0; i < shots; ++i) {
    if (passes_wall(random_shot(rng, i), true, true)) ++walls[i % 4];
    if (passes_terrain(random_shot(rng, i), true)) ++terrain[i % 4];
  }
  for (int k = 0; k < 4; ++k) {
    std::printf("%s: %d of %d passed the wall, %d of %d went through the terrain\n",
                projectile_name(k), walls[k], shots / 4, terrain[k], shots / 4);
    EXPECT_EQ(walls[k], 0) << projectile_name(k);
    EXPECT_EQ(terrain[k], 0) << projectile_name(k);
  }
}

// A wall that comes across a shot's path between two steps, made there, moved there or given a
// shape there, stops it at Box2D v3's settings, where a fast body's way is looked at as its
// step finishes: each shot flies three steps first, then the wall appears 3 m ahead of it.
enum class WallArrives { created, moved, shape_added };

bool passes_wall_arriving(const Shot& shot, WallArrives how) {
  WorldDef def = zero_gravity();
  as_box2d_v3(def);
  World world(def);
  // Still bodies far above the path: one to be given a shape there, one to be moved into it.
  BodyDef far_above;
  far_above.position = Vec2(0, 500);
  const BodyId holder = world.create_body(far_above);
  world.create_shape(holder, ShapeDef::box(0.5, 0.5));
  const BodyId body = fire(world, shot, Vec2(-20, shot.offset), Vec2(1, 0));
  for (int i = 0; i < 3; ++i) world.step();
  const Real wall_x = world.position(body).x() + 3;
  switch (how) {
    case WallArrives::created: {
      BodyDef at;
      at.position = Vec2(wall_x, 0);
      world.create_shape(world.create_body(at), ShapeDef::box(0.01, 20));
      break;
    }
    case WallArrives::moved: {
      const BodyId wall = world.create_body(far_above);
      world.create_shape(wall, ShapeDef::box(0.01, 20));
      world.step();  // laid out where it is
      world.set_transform(wall, Vec2(wall_x, 0), 0);
      break;
    }
    case WallArrives::shape_added:
      world.create_shape(holder, ShapeDef::box(0.01, 20, Vec2(wall_x, -500)));
      break;
  }
  for (int i = 0; i < 30; ++i) {
    world.step();
    if (world.position(body).x() > wall_x) return true;
  }
  return false;
}

TEST(Continuous, AWallThatComesIntoAFreeFlightsPathStopsIt) {
  std::mt19937_64 rng(23);
  const char* names[] = {"made", "moved", "given a shape"};
  for (const WallArrives how :
       {WallArrives::created, WallArrives::moved, WallArrives::shape_added}) {
    int passed = 0;
    for (int i = 0; i < 100; ++i) {
      Shot shot = random_shot(rng, i);
      // 1-3 m a step: the wall is one to three steps ahead.
      shot.speed = 60 + 120 * (shot.offset + 0.5);
      passed += passes_wall_arriving(shot, how) ? 1 : 0;
    }
    EXPECT_EQ(passed, 0) << "a wall " << names[static_cast<int>(how)] << " in the path";
  }
}

// Rain of fast projectiles, spinning, onto shelves of boxes, a thin wall and chain terrain, at
// Box2D v3's settings: stepped as is, most fast bodies are settled as their step finishes; a
// sensor far away makes every fast body go through the continuous phase's sweep (sensors see
// fast bodies along their sweeps). The two must leave every body in the same place, bit for
// bit, with the same fast bodies and stops.
struct RainRun {
  std::vector<Pose> poses;
  std::size_t fast = 0, hits = 0;
};

RainRun rain_of_shots(bool far_sensor, int workers) {
  WorldDef def;
  def.worker_count = workers;
  as_box2d_v3(def);
  World world(def);
  const BodyId ground = world.create_body({});
  for (int i = -10; i <= 10; ++i) {
    world.create_shape(ground, ShapeDef::box(0.25, 0.25, Vec2(i * 0.5, 0)));
    world.create_shape(ground, ShapeDef::box(0.25, 0.25, Vec2(i * 0.5, -8)));
  }
  world.create_shape(ground, ShapeDef::box(6, 0.01, Vec2(0, -4)));
  std::vector<Vec2> points;
  for (int i = 24; i >= -24; --i) points.emplace_back(0.25 * i, -12 + ((i % 2 == 0) ? 0.0 : 0.2));
  world.create_chain(ground, ShapeDef::chain(points));
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<Real> x(-4, 4), height(2, 30), down(5, 200), side(-20, 20);
  std::vector<BodyId> bodies;
  for (int i = 0; i < 300; ++i) {
    Shot shot = random_shot(rng, i);
    shot.speed = 1;
    const BodyId body = fire(world, shot, Vec2(x(rng), height(rng)), Vec2(0, 0));
    world.set_linear_velocity(body, Vec2(side(rng), -down(rng)));
    bodies.push_back(body);
  }
  if (far_sensor) {
    const BodyId holder = world.create_body({});
    ShapeDef band = ShapeDef::box(1, 1, Vec2(1000, 1000));
    band.is_sensor = true;
    world.create_shape(holder, band);
  }
  RainRun run;
  for (int step = 0; step < 90; ++step) {
    world.step();
    run.fast += world.counters().fast_bodies;
    run.hits += world.counters().continuous_hits;
    for (const BodyId body : bodies) run.poses.push_back(world.pose(body));
  }
  return run;
}

TEST(Continuous, FastBodiesSettledAsTheirStepFinishesEndAsTheSweepLeavesThem) {
  const RainRun swept = rain_of_shots(true, 1);
  std::printf("%zu fast bodies, %zu stopped short, over 90 steps\n", swept.fast, swept.hits);
  EXPECT_GT(swept.hits, 50u);
  for (const int workers : {1, 2}) {
    const RainRun settled = rain_of_shots(false, workers);
    EXPECT_EQ(settled.fast, swept.fast);
    EXPECT_EQ(settled.hits, swept.hits);
    ASSERT_EQ(settled.poses.size(), swept.poses.size());
    std::size_t differ = 0;
    for (std::size_t k = 0; k < swept.poses.size(); ++k) {
      const Pose& a = settled.poses[k];
      const Pose& b = swept.poses[k];
      differ += a.position != b.position || a.rotation.cos != b.rotation.cos ||
                a.rotation.sin != b.rotation.sin;
    }
    EXPECT_EQ(differ, 0u) << workers << " workers";
  }
}

// Grazing shots: along a long flat chain floor, fast, closing on it by less than a quarter of
// their thinness per step (the shots the early out for chains leaves to the speculative
// contacts) or by more. Whether the middle ever gets below the floor, and whether it ever gets
// inside it (its circle of half its thinness below the floor's line).
struct GrazeResult {
  bool below = false, inside = false;
};

GrazeResult graze(const Shot& shot, Real sink_per_step, bool fast_body_margin,
                  bool continuous = true) {
  WorldDef def = zero_gravity();
  def.fast_body_margin = fast_body_margin;
  def.enable_continuous = continuous;
  World world(def);
  const BodyId ground = world.create_body({});
  std::vector<Vec2> points;
  for (int i = 400; i >= -400; --i) points.emplace_back(0.5 * i, 0);
  world.create_chain(ground, ShapeDef::chain(points));
  const Vec2 direction = Vec2(shot.speed, -sink_per_step / def.time_step);
  Shot along = shot;
  along.speed = direction.norm();
  const BodyId body =
      fire(world, along, Vec2(-150, 0.2 + 0.3 * (shot.offset + 0.5)), direction / along.speed);
  GrazeResult r;
  for (int i = 0; i < 40 && world.position(body).x() < 190; ++i) {
    world.step();
    const Real y = world.position(body).y();
    r.below = r.below || y < 0;
    r.inside = r.inside || y < half_thinness(shot.kind);
  }
  return r;
}

TEST(Continuous, GrazingShotsAlongAChainNeverGetBelowIt) {
  const auto count = [](bool margin, bool continuous) {
    std::mt19937_64 rng(5);
    // Log-uniform: as many shots close by under a centimetre a step as by more.
    std::uniform_real_distribution<Real> log_sink(std::log(0.0005), std::log(0.3));
    int below = 0, inside = 0;
    for (int i = 0; i < 400; ++i) {
      const Shot shot = random_shot(rng, i);
      const GrazeResult r = graze(shot, std::exp(log_sink(rng)), margin, continuous);
      below += r.below;
      inside += r.inside;
    }
    std::printf(
        "fast_body_margin %d, continuous %d: of 400 grazing shots %d got below the chain, "
        "%d inside it\n",
        margin, continuous, below, inside);
    return std::pair{below, inside};
  };
  for (const bool margin : {true, false}) {
    const auto [below, inside] = count(margin, true);
    EXPECT_EQ(below, 0);
    EXPECT_EQ(inside, 0);
  }
  // Without continuous collision some go through (so the counts above can fail).
  EXPECT_GT(count(true, false).first, 0);
}

// Two projectiles fired at each other, head on or on crossing paths timed to meet: they must
// meet (both velocities change) and never pass through or end inside each other.
struct PairResult {
  bool missed = false;  // neither was deflected: they passed through each other
  bool inside = false;  // one is inside the other at the end, well after meeting
};

PairResult fire_pair(const Shot& a, const Shot& b, bool crossing, bool fast_body_margin = true) {
  WorldDef def = zero_gravity();
  def.fast_body_margin = fast_body_margin;
  World world(def);
  BodyId first, second;
  if (crossing) {
    // A along +x, B along +y; both reach the origin after the same time.
    const Real time = 1.5 / a.speed;
    first = fire(world, a, Vec2(-1.5, 0), Vec2(1, 0));
    second = fire(world, b, Vec2(0, -b.speed * time), Vec2(0, 1));
  } else {
    first = fire(world, a, Vec2(-1.5, 0.3 * a.offset * 0.1), Vec2(1, 0));
    second = fire(world, b, Vec2(1.5, 0), Vec2(-1, 0));
  }
  const Vec2 va = world.linear_velocity(first), vb = world.linear_velocity(second);
  PairResult r;
  for (int i = 0; i < 20; ++i) world.step();
  r.inside = inside(world, first, a.kind, second, b.kind);
  r.missed = (world.linear_velocity(first) - va).norm() < 1e-9 &&
             (world.linear_velocity(second) - vb).norm() < 1e-9;
  return r;
}

struct PairCounts {
  int missed = 0, inside = 0;
};

// Pairs fired head on (even) and crossing (odd), counted.
PairCounts fire_pairs(std::uint64_t seed, int pairs, bool fast_body_margin) {
  std::mt19937_64 rng(seed);
  PairCounts total;
  for (int i = 0; i < pairs; ++i) {
    const Shot a = random_shot(rng, i), b = random_shot(rng, i / 4 + 1);
    const PairResult r = fire_pair(a, b, i % 2 == 1, fast_body_margin);
    total.missed += r.missed;
    total.inside += r.inside;
  }
  std::printf("pairs: %d passed through each other untouched, %d ended inside each other, of %d\n",
              total.missed, total.inside, pairs);
  return total;
}

TEST(Continuous, FastBodiesFiredAtEachOtherMeet) {
  const PairCounts r = fire_pairs(3, 4000, true);
  EXPECT_EQ(r.missed, 0);
  EXPECT_EQ(r.inside, 0);
}

// With Box2D v3's boxes for fast bodies (bare of the speculative margin after a clear sweep)
// the sweep of fast pairs still finds every meeting: it works from the swept boxes, not from
// the pairs the broadphase keeps.
TEST(Continuous, FastBodiesWithBareBoxesFiredAtEachOtherMeet) {
  const PairCounts r = fire_pairs(5, 1000, false);
  EXPECT_EQ(r.missed, 0);
  EXPECT_EQ(r.inside, 0);
}

// A ball of radius 0.1 flying at 60 m/s past a row of resting boxes, 9 cm from their faces:
// its broadphase box (2 cm of speculative margin, then a broadphase margin of an eighth of its
// radius) and theirs (2 cm, then 5 cm) overlap, so the broadphase pairs them. Without
// fast_body_margin the fast ball's box is bare, as Box2D v3's, and they stay 7.5 mm apart: no
// pairs. Either way nothing deflects it.
TEST(Continuous, AFastBodysBareBoxesMeetFewerShapes) {
  for (const bool margin : {true, false}) {
    WorldDef def = zero_gravity();
    def.fast_body_margin = margin;
    World world(def);
    for (int i = 0; i < 30; ++i) {
      BodyDef box;
      box.type = BodyType::dynamic;
      box.position = Vec2(i, 0);
      world.create_shape(world.create_body(box), ShapeDef::box(0.5, 0.5));
    }
    BodyDef flying;
    flying.type = BodyType::dynamic;
    flying.position = Vec2(-5, 0.5 + 0.09 + 0.1);
    flying.linear_velocity = Vec2(60, 0);
    const BodyId ball = world.create_body(flying);
    world.create_shape(ball, ShapeDef::circle(0.1));
    std::size_t most_pairs = 0;
    for (int step = 0; step < 20; ++step) {
      world.step();
      most_pairs = std::max(most_pairs, world.body_contacts(ball).size());
    }
    EXPECT_GT(world.position(ball).x(), 10);
    EXPECT_NEAR(world.position(ball).y(), 0.69, 1e-12);
    if (margin) {
      EXPECT_GT(most_pairs, 0u);
    } else {
      EXPECT_EQ(most_pairs, 0u);
    }
  }
}

// A sensor band 0.1 wide crossed within one step: the sensor reports the visitor's begin,
// then its end.
TEST(Continuous, ASensorCrossedInOneStepReportsBeginAndEnd) {
  int begins = 0, ends = 0, shots = 0;
  for (const Real speed : {60.0, 150.0, 300.0, 450.0}) {
    for (int kind = 0; kind < 4; ++kind) {
      World world(zero_gravity());
      const BodyId holder = world.create_body({});
      ShapeDef band = ShapeDef::box(0.05, 2);
      band.is_sensor = true;
      const ShapeId sensor = world.create_shape(holder, band);
      const BodyId body = fire(world, {kind, speed, 30, 0, 0}, Vec2(-1.2, 0), Vec2(1, 0));
      world.set_bullet(body, false);
      ++shots;
      bool began = false, ended = false;
      for (int i = 0; i < 30; ++i) {
        world.step();
        for (const SensorBeginEvent& e : world.sensor_begin_events()) {
          if (e.sensor == sensor) began = true;
        }
        for (const SensorEndEvent& e : world.sensor_end_events()) {
          if (e.sensor == sensor && began) ended = true;
        }
      }
      EXPECT_GT(world.position(body).x(), 1) << "the sensor does not stop it";
      begins += began;
      ends += ended;
    }
  }
  EXPECT_EQ(begins, shots);
  EXPECT_EQ(ends, shots);
}

// cast_shape stops a box short of a wall, reports the wall's face and normal, passes sensors
// and filtered shapes, and finds nothing when the way is clear.
TEST(Continuous, CastShapeFindsTheFirstSolidShapeOnTheWay) {
  World world(zero_gravity());
  const BodyId walls = world.create_body({});
  ShapeDef sensor = ShapeDef::box(0.05, 2, Vec2(1, 0));
  sensor.is_sensor = true;
  world.create_shape(walls, sensor);
  ShapeDef ghost = ShapeDef::box(0.05, 2, Vec2(2, 0));
  ghost.filter.category = 0x2;
  world.create_shape(walls, ghost);
  const ShapeId wall = world.create_shape(walls, ShapeDef::box(0.01, 2, Vec2(3, 0)));
  Filter filter;
  filter.mask = ~std::uint64_t{0x2};
  const auto hit = world.cast_shape(ShapeDef::box(0.1, 0.1), Pose{Vec2(0, 0.3), Rotation{}},
                                    Vec2(10, 0), filter);
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->shape, wall);
  // The box's face stops the slop short of the wall's face at x = 2.99.
  const Real face = 0.1 + 10 * hit->fraction;
  EXPECT_NEAR(face, 2.99 - world.def().linear_slop, 0.25 * world.def().linear_slop + 1e-9);
  EXPECT_NEAR(hit->normal.x(), -1, 1e-9);
  EXPECT_NEAR(hit->point.x(), 2.99, 1e-6);
  EXPECT_FALSE(
      world.cast_shape(ShapeDef::circle(0.1), Pose{Vec2(0, 3), Rotation{}}, Vec2(10, 0), filter)
          .has_value());
  EXPECT_THROW(
      world.cast_shape(ShapeDef::circle(0.1), Pose{Vec2(0, 0), Rotation{}}, Vec2(std::nan(""), 0)),
      InvalidArgumentError);
}

// Spinner's blade presses its 6076 bodies into the ring of chain that holds them (radius 40 m
// about (0, 32)), some so deep that the circle about a body's middle already overlaps the
// chain when a step begins, and drags them along it at up to 80 m/s. A body whose middle gets
// behind a chain segment passes through it (chains are one-sided), so the sweep keeps each
// fast body's middle in front of the chain segments it lies over. Without that, bodies slid
// out past the ring's corners from the 25th step on; Box2D v3 keeps all of them inside over
// 1500 steps, as we now do.
TEST(Continuous, BodiesPressedAlongAChainRingStayInsideIt) {
  SceneDef scene = builtin_scene("spinner");
  scene.world.enable_sleep = false;  // as Box2D v3's benchmark app runs it
  SceneRun run(scene);
  const World& world = run.world();
  int pressed = 0;
  for (int step = 1; step <= 60; ++step) {
    run.step();
    int outside = 0;
    for (const BodyId body : world.bodies()) {
      if (world.body_type(body) != BodyType::dynamic) continue;
      // Every point of the chain lies within 40 m of the centre; a middle farther out is
      // behind it.
      const Real from_centre = (world.position(body) - Vec2(0, 32)).norm();
      if (from_centre > 40) ++outside;
      if (from_centre > 39.75) ++pressed;
    }
    ASSERT_EQ(outside, 0) << "after step " << step;
  }
  EXPECT_GT(pressed, 1000);  // bodies did lie deep against the chain
}

}  // namespace
}  // namespace mink
