// Box2D v3's benchmark suite as scenes: what its shared/benchmarks.c and shared/human.c build
// (shapes, positions, materials, filters, joints, motors, movers, counts) and what its
// benchmark/main.c runs (world settings, steps, the per-step actions of rain and junkyard).

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <numbers>
#include <span>
#include <utility>
#include <vector>

#include "benchmark_scenes.hpp"
#include "human.hpp"
#include "scene_building.hpp"
#include "snapshot_io.hpp"

namespace mink {

namespace {

constexpr std::array<BenchmarkScene, 10> kSuite = {{{"compounds", 500},
                                                    {"joint_grid", 500},
                                                    {"junkyard", 800},
                                                    {"large_pyramid", 500},
                                                    {"many_pyramids", 200},
                                                    {"rain", 1000},
                                                    {"smash", 300},
                                                    {"spinner", 500},
                                                    {"tumbler", 750},
                                                    {"washer", 500}}};

}  // namespace

std::span<const BenchmarkScene> benchmark_suite() noexcept {
  return kSuite;
}

namespace detail {

namespace {

constexpr Real kPi = std::numbers::pi;
constexpr Real kDegree = kPi / 180;

// Box2D v3's default world as its benchmark app steps it: 1/60 s steps of 4 substeps, 30 Hz
// contacts with damping ratio 10, joints at its joint default of 60 Hz and damping ratio 2,
// overlap pushed out at no more than 3 m/s, continuous collision for fast bodies against static
// and kinematic shapes only. Sleeping stays on unless the scene turns it off.
SceneDef box2d_v3_scene(bool sleep) {
  SceneDef scene;
  WorldDef& world = scene.world;
  world.gravity = Vec2(0, -10);
  world.time_step = 1.0 / 60.0;
  world.substeps = 4;
  world.contact_hertz = 30;
  world.contact_damping_ratio = 10;
  world.joint_hertz = 60;
  world.joint_damping_ratio = 2;
  world.contact_push_max_velocity = 3;
  world.restitution_threshold = 1;
  world.hit_event_threshold = 1;
  world.linear_slop = 0.005;
  world.max_linear_speed = 400;
  world.enable_sleep = sleep;
  world.continuous_fast_pairs = false;
  world.fast_body_margin = false;
  return scene;
}

// Box2D v3's grounds are one static body at the origin with many shapes.
std::size_t add_ground(SceneDef& scene, std::vector<ShapeDef> shapes) {
  return add_body(scene, BodyType::static_body, Vec2(0, 0), std::move(shapes));
}

// A bin of boxes: a floor of 2 half_span + 1 boxes (half extents 0.55 x 0.5) along y = 0 from
// x = -half_span, and walls of `height` boxes (0.5 x 0.55) at x = -half_span and half_span from
// y = 1 up, in that order.
std::vector<ShapeDef> bin(int half_span, int height) {
  std::vector<ShapeDef> shapes;
  for (int i = 0; i <= 2 * half_span; ++i) {
    shapes.push_back(ShapeDef::box(0.55, 0.5, Vec2(i - half_span, 0)));
  }
  for (const int x : {-half_span, half_span}) {
    for (int i = 1; i <= height; ++i) shapes.push_back(ShapeDef::box(0.5, 0.55, Vec2(x, i)));
  }
  return shapes;
}

// 3000 bodies of two triangles each, in 20 columns of 150, falling into a bin.
SceneDef compounds() {
  SceneDef scene = box2d_v3_scene(true);
  std::vector<ShapeDef> ground = bin(40, 100);
  ground.push_back(ShapeDef::segment(Vec2(-800, -80), Vec2(800, -80)));
  add_ground(scene, std::move(ground));
  ShapeDef left, right;
  left.points = {{-1, 0}, {0.5, 1}, {0, 2}};
  right.points = {{1, 0}, {-0.5, 1}, {0, 2}};
  left.friction = right.friction = 0.5;
  Real side = 0.25;  // alternate bodies lean left and right
  for (int i = 0; i < 20; ++i) {
    for (int j = 0; j < 150; ++j) {
      add_body(scene, BodyType::dynamic, Vec2(2 * i - 19 + side, 2.25 * j + 5.575), {left, right});
      side = -side;
    }
  }
  return scene;
}

// A 100 x 100 net of circles on revolute joints, hanging from seven static circles in the
// middle of its top row. The circles are category 2 and do not collide with each other.
SceneDef joint_grid() {
  SceneDef scene = box2d_v3_scene(false);
  const int n = 100;
  ShapeDef circle = ShapeDef::circle(0.4);
  circle.filter.category = 2;
  circle.filter.mask = ~std::uint64_t{2};
  for (int k = 0; k < n; ++k) {
    for (int i = 0; i < n; ++i) {
      const bool pinned = k >= n / 2 - 3 && k <= n / 2 + 3 && i == 0;
      const std::size_t body = add_body(scene, pinned ? BodyType::static_body : BodyType::dynamic,
                                        Vec2(k, -i), {circle});
      if (i > 0)
        add_joint<RevoluteJointDef>(scene, body - 1, body, Vec2(k, 0.5 - i), Vec2(k, 0.5 - i));
      if (k > 0) {
        add_joint<RevoluteJointDef>(scene, body - n, body, Vec2(k - 0.5, -i), Vec2(k - 0.5, -i));
      }
    }
  }
  return scene;
}

// 8000 pentagons in 200 columns of 40 dropped into a wide bin, and a kinematic pusher that
// sweeps the floor from side to side.
SceneDef junkyard() {
  SceneDef scene = box2d_v3_scene(true);
  add_ground(scene, bin(80, 50));
  // Five points a golden angle apart on a circle: an irregular pentagon.
  const Real radius = 0.25, golden = kPi * (std::sqrt(5.0) - 1);
  ShapeDef pentagon;
  for (int i = 0; i < 5; ++i) {
    pentagon.points.emplace_back(radius * std::cos(golden * i), radius * std::sin(golden * i));
  }
  Real side = -0.1;
  for (int i = 0; i < 200; ++i) {
    for (int j = 0; j < 40; ++j) {
      add_body(scene, BodyType::dynamic, Vec2(1.5 * (2 * i - 200) * radius + side, j + 15),
               {pentagon});
      side = -side;
    }
  }
  const std::size_t pusher =
      add_body(scene, BodyType::kinematic, Vec2(0, 0), {ShapeDef::box(2, 4, Vec2(0, 4))});
  // Each step the pusher is steered to where its path is at the end of the step: the actions
  // keep nothing but the scene's id.
  scene.schedule = [pusher](World&, const SceneIds& ids) -> SceneActions {
    SceneActions actions;
    actions.act = [id = ids.bodies[pusher]](World& world, std::uint64_t step) {
      const Real dt = world.def().time_step;
      const Real t = dt * static_cast<Real>(step);
      world.set_target_transform(id, Vec2(60 * std::sin(0.2 * t), 0), 0, dt);
    };
    return actions;
  };
  return scene;
}

// 5050 boxes in a pyramid of 100 rows.
SceneDef large_pyramid() {
  SceneDef scene = box2d_v3_scene(false);
  scene.bodies.push_back(static_box(Vec2(0, -1), 100, 1));
  add_pyramid(scene, 100, Vec2(0, 0));
  return scene;
}

// 20 rows of 20 pyramids of 55 boxes, each row on its own floor segment.
SceneDef many_pyramids() {
  SceneDef scene = box2d_v3_scene(false);
  const int base = 10, rows = 20, columns = 20;
  const Real spacing = base + 1, half_width = 0.5 * columns * spacing;
  std::vector<ShapeDef> floors;
  for (int r = 0; r < rows; ++r) {
    floors.push_back(
        ShapeDef::segment(Vec2(-half_width, r * spacing), Vec2(half_width, r * spacing)));
  }
  add_ground(scene, std::move(floors));
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < columns; ++c) {
      add_pyramid(scene, base, Vec2(-half_width + c * spacing + 5.5, r * spacing));
    }
  }
  return scene;
}

// rain: rows of ragdoll groups dropped onto five shelves, a column of groups every eighth
// step; once all 40 columns are down, the oldest column is destroyed and dropped anew.
constexpr int kRainShelves = 5, kRainColumns = 40, kRainGroup = 5;
constexpr int kRainCells = 500;  // boxes per shelf, less one
constexpr Real kRainCell = 0.5;  // their size

class RainActions {
 public:
  void operator()(World& world, std::uint64_t step) {
    if (step % 8 != 0) return;
    if (columns_ < kRainColumns) {
      for (int shelf = 0; shelf < kRainShelves; ++shelf) drop(world, shelf, columns_);
      ++columns_;
      return;
    }
    for (int shelf = 0; shelf < kRainShelves; ++shelf) {
      clear(world, shelf, oldest_);
      drop(world, shelf, oldest_);
    }
    oldest_ = (oldest_ + 1) % kRainColumns;
  }

  // The groups' ids and the counters, for SceneRun snapshots.
  std::vector<std::uint8_t> save() const {
    ByteWriter out;
    SaveArchive archive{out};
    fields(archive, const_cast<RainActions&>(*this));
    return std::move(out.bytes());
  }
  void load(std::span<const std::uint8_t> bytes, const World& world) {
    ByteReader in(bytes);
    LoadArchive archive{in, world.serial()};
    RainActions loaded;
    fields(archive, loaded);
    if (in.remaining() != 0) in.fail("rain schedule state ends early");
    if (loaded.groups_.size() != groups_.size() || loaded.columns_ < 0 ||
        loaded.columns_ > kRainColumns || loaded.oldest_ < 0 || loaded.oldest_ >= kRainColumns) {
      in.fail("rain schedule state out of range");
    }
    *this = std::move(loaded);
  }

 private:
  template <typename Archive>
  static void fields(Archive& archive, RainActions& rain) {
    archive(rain.groups_);
    archive(rain.columns_);
    archive(rain.oldest_);
  }

  using Group = std::array<SceneIds, kRainGroup>;

  Group& group(int shelf, int column) {
    return groups_[static_cast<std::size_t>(shelf * kRainColumns + column)];
  }

  // Five humans half a metre apart, 40 m above the shelf; each i-th human of every group
  // shares group -(i + 1), so those pass through each other.
  void drop(World& world, int shelf, int column) {
    const Real span = kRainCells * kRainCell, spacing = span / kRainColumns;
    Vec2 feet(-0.5 * span + spacing * (column + 0.5), 40 + 45 * shelf);
    Group& humans = group(shelf, column);
    for (int i = 0; i < kRainGroup; ++i) {
      SceneDef human;
      add_human(human, feet, -(i + 1));
      humans[static_cast<std::size_t>(i)] = add_scene(world, human);
      feet.x() += 0.5;
    }
  }

  void clear(World& world, int shelf, int column) {
    for (SceneIds& human : group(shelf, column)) {
      for (const JointId joint : human.joints) world.destroy_joint(joint);
      for (const BodyId body : human.bodies) world.destroy_body(body);
      human = {};
    }
  }

  std::vector<Group> groups_ = std::vector<Group>(kRainShelves * kRainColumns);
  int columns_ = 0;  // columns dropped so far
  int oldest_ = 0;   // the column replaced next, once all are down
};

SceneDef rain() {
  SceneDef scene = box2d_v3_scene(true);
  // Box2D v3 lets a human sleep below 0.1 m/s; humans are all that moves here.
  scene.world.linear_sleep_tolerance = 0.1;
  std::vector<ShapeDef> shelves;
  for (int shelf = 0; shelf < kRainShelves; ++shelf) {
    for (int j = 0; j <= kRainCells; ++j) {
      const Real x = -0.5 * kRainCells * kRainCell + j * kRainCell;
      shelves.push_back(ShapeDef::box(0.5 * kRainCell, 0.5 * kRainCell, Vec2(x, 45 * shelf)));
    }
  }
  add_ground(scene, std::move(shelves));
  scene.schedule = [](World&, const SceneIds&) -> SceneActions {
    auto rain = std::make_shared<RainActions>();
    return {.act = [rain](World& world, std::uint64_t step) { (*rain)(world, step); },
            .save = [rain] { return rain->save(); },
            .load = [rain](std::span<const std::uint8_t> bytes,
                           const World& world) { rain->load(bytes, world); }};
  };
  return scene;
}

// A heavy block at 40 m/s into a resting wall of 9600 small boxes, without gravity; the boxes
// start asleep and wake as the block reaches them.
SceneDef smash() {
  SceneDef scene = box2d_v3_scene(true);
  scene.world.gravity = Vec2(0, 0);
  ShapeDef block = ShapeDef::box(4, 4);
  block.density = 8;
  const std::size_t ram = add_body(scene, BodyType::dynamic, Vec2(-20, 0), {block});
  scene.bodies[ram].body.linear_velocity = Vec2(40, 0);
  const Real d = 0.4;
  for (int i = 0; i < 120; ++i) {
    for (int j = 0; j < 80; ++j) {
      const std::size_t box = add_body(scene, BodyType::dynamic, Vec2(i * d + 30, (j - 40) * d),
                                       {ShapeDef::box(0.5 * d, 0.5 * d)});
      scene.bodies[box].body.awake = false;
    }
  }
  return scene;
}

// 6076 capsules, circles and squares inside a ring of chain, stirred by a long rounded blade on
// a revolute motor of unbounded torque.
SceneDef spinner() {
  SceneDef scene = box2d_v3_scene(true);
  const int points = 360;
  std::vector<Vec2> ring;
  for (int i = 0; i < points; ++i) {
    const Real a = -2 * kPi * i / points;  // clockwise: the chain's solid side faces in
    ring.emplace_back(40 * std::cos(a), 40 * std::sin(a) + 32);
  }
  ShapeDef wall = ShapeDef::chain(std::move(ring), true);
  wall.friction = 0.1;
  const std::size_t ground = add_ground(scene, {std::move(wall)});
  ShapeDef blade = ShapeDef::box(0.4, 20);
  blade.radius = 0.2;
  blade.friction = 0;
  const std::size_t spinner = add_body(scene, BodyType::dynamic, Vec2(0, 12), {std::move(blade)});
  scene.bodies[spinner].body.allow_sleep = false;
  RevoluteJointDef motor;
  motor.motor = {true, 5, std::numeric_limits<float>::max()};
  add_joint(scene, ground, spinner, Vec2(0, 12), Vec2(0, 12), motor);
  std::array<ShapeDef, 3> kinds = {ShapeDef::capsule(Vec2(-0.25, 0), Vec2(0.25, 0), 0.25),
                                   ShapeDef::circle(0.35), ShapeDef::box(0.35, 0.35)};
  for (ShapeDef& kind : kinds) {
    kind.friction = 0.1;
    kind.restitution = 0.1;
    kind.density = 0.25;
  }
  Real x = -23, y = 2;
  for (int i = 0; i < 2 * 3038; ++i) {
    add_body(scene, BodyType::dynamic, Vec2(x, y), {kinds[static_cast<std::size_t>(i % 3)]});
    x += 0.5;
    if (x >= 23) {
      x = -23;
      y += 0.5;
    }
  }
  return scene;
}

// 2025 small boxes in a heavy dynamic drum turned by a revolute motor at 25 degrees a second.
SceneDef tumbler() {
  SceneDef scene = box2d_v3_scene(true);
  const std::size_t ground = add_ground(scene, {});
  std::vector<ShapeDef> walls = {
      ShapeDef::box(0.5, 10, Vec2(10, 0)), ShapeDef::box(0.5, 10, Vec2(-10, 0)),
      ShapeDef::box(10, 0.5, Vec2(0, 10)), ShapeDef::box(10, 0.5, Vec2(0, -10))};
  for (ShapeDef& wall : walls) wall.density = 50;
  const std::size_t drum = add_body(scene, BodyType::dynamic, Vec2(0, 10), std::move(walls));
  RevoluteJointDef motor;
  motor.motor = {true, 25 * kDegree, 1e8};
  add_joint(scene, ground, drum, Vec2(0, 10), Vec2(0, 10), motor);
  const int n = 45;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      add_body(scene, BodyType::dynamic, Vec2(-0.2 * n + 0.4 * j, -0.2 * n + 10 + 0.4 * i),
               {ShapeDef::box(0.125, 0.125)});
    }
  }
  return scene;
}

// 8100 small boxes (with hit events) in a kinematic ring with four paddles, turning at 25
// degrees a second and drifting very slowly.
SceneDef washer() {
  SceneDef scene = box2d_v3_scene(true);
  add_ground(scene, {});
  const Real r0 = 14, r1 = 16, r2 = 18, step = kPi / 18, overlap = 0.1 * step;
  const auto at = [](Real radius, Real angle) {
    return Vec2(radius * std::cos(angle), radius * std::sin(angle));
  };
  std::vector<ShapeDef> ring;
  for (int i = 0; i < 36; ++i) {
    const Real a1 = i * step, a2 = (i + 1) % 36 * step;
    // Rim pieces overlap their neighbours by a tenth of their angle at each end.
    ShapeDef rim;
    rim.points = {at(r1, a1 - overlap), at(r2, a1 - overlap), at(r1, a2 + overlap),
                  at(r2, a2 + overlap)};
    ring.push_back(std::move(rim));
    if (i % 9 == 0) {
      ShapeDef paddle;
      paddle.points = {at(r0, a1), at(r1, a1), at(r0, a2), at(r1, a2)};
      ring.push_back(std::move(paddle));
    }
  }
  const std::size_t drum = add_body(scene, BodyType::kinematic, Vec2(0, 10), std::move(ring));
  scene.bodies[drum].body.angular_velocity = 25 * kDegree;
  scene.bodies[drum].body.linear_velocity = Vec2(0.001, -0.002);
  ShapeDef box = ShapeDef::box(0.1, 0.1);
  box.enable_hit_events = true;
  const int n = 90;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      add_body(scene, BodyType::dynamic, Vec2(-0.11 * n + 0.21 * j, -0.11 * n + 10 + 0.21 * i),
               {box});
    }
  }
  return scene;
}

}  // namespace

std::optional<SceneDef> benchmark_scene(std::string_view name) {
  if (name == "compounds") return compounds();
  if (name == "joint_grid") return joint_grid();
  if (name == "junkyard") return junkyard();
  if (name == "large_pyramid") return large_pyramid();
  if (name == "many_pyramids") return many_pyramids();
  if (name == "rain") return rain();
  if (name == "smash") return smash();
  if (name == "spinner") return spinner();
  if (name == "tumbler") return tumbler();
  if (name == "washer") return washer();
  return std::nullopt;
}

}  // namespace detail

}  // namespace mink
