#include "mink/engine/scene.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <span>
#include <string>
#include <variant>

#include "mink/error.hpp"
#include "mink/geometry/point_sets.hpp"

namespace mink {

World build_world(const SceneDef& scene) {
  World world(scene.world);
  for (const SceneBody& body : scene.bodies) {
    const BodyId id = world.create_body(body.body);
    for (const ShapeDef& shape : body.shapes) {
      if (shape.type == ShapeType::chain) {
        world.create_chain(id, shape);
      } else {
        world.create_shape(id, shape);
      }
    }
    // Adding shapes wakes the body; respect a body defined asleep.
    if (!body.body.awake) world.set_awake(id, false);
  }
  return world;
}

namespace {

// The fields every kind of shape keeps, as the world reports them.
ShapeDef captured_material(const World& world, ShapeId id) {
  ShapeDef shape;
  shape.type = world.shape_type(id);
  shape.algorithm = world.shape_algorithm(id);
  shape.density = world.shape_density(id);
  shape.friction = world.shape_friction(id);
  shape.restitution = world.shape_restitution(id);
  shape.filter = world.shape_filter(id);
  shape.is_sensor = world.is_sensor(id);
  shape.user_data = world.shape_user_data(id);
  shape.enable_contact_events = world.shape_contact_events(id);
  shape.enable_sensor_events = world.shape_sensor_events(id);
  shape.enable_hit_events = world.shape_hit_events(id);
  return shape;
}

// One chain from its segments (in creation order), closed when it was made as a loop.
void capture_chain(const World& world, std::span<const ShapeId> run,
                   std::vector<ShapeDef>& shapes) {
  const auto segment_of = [&](ShapeId id) {
    return std::get<ChainSegment>(world.shape_geometry(id)).segment;
  };
  ShapeDef chain = captured_material(world, run.front());
  chain.loop = world.shape_chain(run.front())->loop;
  chain.points.push_back(segment_of(run.front()).point1);
  for (const ShapeId id : run) chain.points.push_back(segment_of(id).point2);
  if (chain.loop) chain.points.pop_back();  // the loop closes itself
  shapes.push_back(std::move(chain));
}

std::vector<ShapeDef> captured_shapes(const World& world, BodyId body) {
  std::vector<ShapeDef> shapes;
  const std::vector<ShapeId> ids = world.body_shapes(body);
  for (std::size_t i = 0; i < ids.size();) {
    const ShapeGeometry& geometry = world.shape_geometry(ids[i]);
    if (kind_of(geometry) == ShapeKind::chain_segment) {
      // A chain's segments stand together in the body's shape list, in creation order.
      const std::uint32_t chain = world.shape_chain(ids[i])->chain;
      std::size_t end = i + 1;
      while (end < ids.size() && world.shape_chain(ids[end]) &&
             world.shape_chain(ids[end])->chain == chain) {
        ++end;
      }
      capture_chain(world, std::span(ids).subspan(i, end - i), shapes);
      i = end;
      continue;
    }
    ShapeDef shape = captured_material(world, ids[i]);
    shape.radius = world.shape_radius(ids[i]);
    if (const auto* circle = std::get_if<Circle>(&geometry)) {
      shape.points = {circle->center};
    } else if (const auto* capsule = std::get_if<Capsule>(&geometry)) {
      shape.points = {capsule->center1, capsule->center2};
    } else if (const auto* segment = std::get_if<Segment>(&geometry)) {
      shape.points = {segment->point1, segment->point2};
    } else {
      const auto vertices = world.shape_hull(ids[i]).vertices();
      shape.points.assign(vertices.begin(), vertices.end());
    }
    shapes.push_back(std::move(shape));
    ++i;
  }
  return shapes;
}

}  // namespace

SceneDef capture_scene(const World& world) {
  SceneDef scene;
  scene.world = world.def();
  for (const BodyId id : world.bodies()) {
    SceneBody body;
    BodyDef& def = body.body;
    def.type = world.body_type(id);
    def.position = world.position(id);
    def.angle = world.angle(id);
    // BodyDef velocities are of the origin; the world keeps the centre's.
    const Real w = world.angular_velocity(id);
    const Vec2 r = world.world_center(id) - world.position(id);
    def.linear_velocity = world.linear_velocity(id) - w * Vec2(-r.y(), r.x());
    def.angular_velocity = w;
    def.linear_damping = world.linear_damping(id);
    def.angular_damping = world.angular_damping(id);
    def.gravity_scale = world.gravity_scale(id);
    def.allow_sleep = world.allow_sleep(id);
    def.awake = world.is_awake(id) || def.type != BodyType::dynamic;
    def.enabled = world.is_enabled(id);
    def.fixed_rotation = world.fixed_rotation(id);
    def.bullet = world.is_bullet(id);
    def.user_data = world.user_data(id);
    body.shapes = captured_shapes(world, id);
    scene.bodies.push_back(std::move(body));
  }
  return scene;
}

namespace {

SceneBody static_box(const Vec2& center, Real hx, Real hy) {
  SceneBody ground;
  ground.body.type = BodyType::static_body;
  ground.body.position = center;
  ground.shapes.push_back(ShapeDef::box(hx, hy));
  return ground;
}

// SplitMix64: a tiny generator whose output is the same everywhere (scenes are data that
// must not depend on the standard library's distributions).
struct SplitMix {
  std::uint64_t state;
  std::uint64_t next() {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  Real uniform() { return static_cast<Real>(next() >> 11) * 0x1.0p-53; }  // [0, 1)
};

}  // namespace

void add_pyramid(SceneDef& scene, int base_count, const Vec2& base_center, Real box_size) {
  const Real h = box_size / 2;
  for (int row = 0; row < base_count; ++row) {
    const Real y = base_center.y() + (2 * row + 1) * h;
    for (int j = row; j < base_count; ++j) {
      const Real x = base_center.x() + (row + 1) * h + 2 * (j - row) * h - h * base_count;
      SceneBody box;
      box.body.type = BodyType::dynamic;
      box.body.position = Vec2(x, y);
      box.shapes.push_back(ShapeDef::box(h, h));
      scene.bodies.push_back(std::move(box));
    }
  }
}

SceneDef pyramid_scene(int base_count) {
  if (base_count < 1) {
    throw InvalidArgumentError("pyramid_scene: base_count must be positive, got " +
                               std::to_string(base_count));
  }
  SceneDef scene;
  scene.bodies.push_back(static_box(Vec2(0, -1), base_count + 20.0, 1));
  add_pyramid(scene, base_count, Vec2(0, 0));
  return scene;
}

SceneDef many_pyramids_scene(int rows, int columns, int base_count) {
  if (rows < 1 || columns < 1 || base_count < 1) {
    throw InvalidArgumentError(
        "many_pyramids_scene: rows, columns and base_count must be "
        "positive");
  }
  SceneDef scene;
  const Real spacing = base_count + 2.0;
  const Real row_height = base_count + 2.0;
  const Real width = columns * spacing;
  for (int r = 0; r < rows; ++r) {
    const Real y = r * row_height;
    // A thin floor per row; the pyramids of the row below end a box short of it.
    scene.bodies.push_back(static_box(Vec2(0, y - 0.25), width / 2 + 1, 0.25));
    for (int c = 0; c < columns; ++c) {
      add_pyramid(scene, base_count, Vec2(-width / 2 + (c + 0.5) * spacing, y));
    }
  }
  return scene;
}

SceneDef rain_scene(int body_count, std::uint64_t seed, RainShapes kinds) {
  if (body_count < 0) throw InvalidArgumentError("rain_scene: body_count must be >= 0");
  SceneDef scene;
  const Real half_width = 12;
  scene.bodies.push_back(static_box(Vec2(0, -1), half_width + 1, 1));
  scene.bodies.push_back(static_box(Vec2(-half_width - 0.5, 30), 0.5, 30));
  scene.bodies.push_back(static_box(Vec2(half_width + 0.5, 30), 0.5, 30));
  SplitMix random{seed};
  const int per_row = 12;
  const Real cell = 2 * half_width / per_row;
  for (int i = 0; i < body_count; ++i) {
    // Polygons-only draws exactly what it always drew, so its scenes stay the same.
    const std::uint64_t kind = kinds == RainShapes::mixed ? random.next() % 4 : 0;
    ShapeDef shape;
    if (kind == 2) {
      shape = ShapeDef::circle(0.3 + 0.3 * random.uniform());
    } else if (kind == 3) {
      const Real half_length = 0.2 + 0.3 * random.uniform();
      shape = ShapeDef::capsule(Vec2(-half_length, 0), Vec2(half_length, 0),
                                0.15 + 0.15 * random.uniform());
    } else {
      const int vertex_count = 3 + static_cast<int>(random.next() % 62);  // 3..64
      const Real radius = 0.4 + 0.4 * random.uniform();
      // Vertices on a circle at jittered, evenly spread angles: every one is a hull vertex and
      // no sliver hulls.
      const Real slot = 2 * std::numbers::pi / vertex_count;
      for (int k = 0; k < vertex_count; ++k) {
        const Real a = (k + 0.8 * random.uniform()) * slot;
        shape.points.emplace_back(radius * std::cos(a), radius * std::sin(a));
      }
    }
    shape.friction = 0.4 + 0.4 * random.uniform();
    SceneBody body;
    body.body.type = BodyType::dynamic;
    body.body.position = Vec2(-half_width + (i % per_row + 0.5) * cell, 3 + (i / per_row) * cell);
    body.body.angle = 2 * std::numbers::pi * random.uniform();
    body.shapes.push_back(std::move(shape));
    scene.bodies.push_back(std::move(body));
  }
  return scene;
}

namespace {

SceneDef tumbler_scene() {
  SceneDef scene;
  SceneBody drum;
  drum.body.type = BodyType::kinematic;
  drum.body.position = Vec2(0, 10);
  drum.body.angular_velocity = 0.25;
  drum.body.allow_sleep = false;
  const Real half = 10, wall = 0.5;
  drum.shapes.push_back(ShapeDef::box(wall, half, Vec2(half, 0)));
  drum.shapes.push_back(ShapeDef::box(wall, half, Vec2(-half, 0)));
  drum.shapes.push_back(ShapeDef::box(half, wall, Vec2(0, half)));
  drum.shapes.push_back(ShapeDef::box(half, wall, Vec2(0, -half)));
  scene.bodies.push_back(std::move(drum));
  for (int i = 0; i < 20; ++i) {
    for (int j = 0; j < 20; ++j) {
      SceneBody box;
      box.body.type = BodyType::dynamic;
      box.body.position = Vec2(-7.6 + 0.8 * i, 2.4 + 0.8 * j);
      box.shapes.push_back(ShapeDef::box(0.25, 0.25));
      scene.bodies.push_back(std::move(box));
    }
  }
  return scene;
}

// The paper's pipeline as a scene: two random 500-point sets in a 400 x 400 canvas, hull A by
// Chan's algorithm and hull B by divide and conquer, each scaled about the canvas centre to a
// few metres and placed so they overlap; the solver pushes them apart and they fall.
SceneDef paper_scene() {
  SceneDef scene;
  scene.bodies.push_back(static_box(Vec2(0, -1), 20, 1));
  const auto [first, second] = paper_point_sets(1);
  const Vec2 canvas_center(200, 200);
  const std::array<std::pair<const std::vector<Vec2>*, HullAlgorithm>, 2> hulls = {
      std::pair{&first, HullAlgorithm::chan}, std::pair{&second, HullAlgorithm::divide_conquer}};
  const std::array<Real, 2> factors = {0.01, 0.008};
  const std::array<Vec2, 2> places = {Vec2(-0.8, 4), Vec2(0.8, 4.5)};
  for (std::size_t i = 0; i < 2; ++i) {
    SceneBody body;
    body.body.type = BodyType::dynamic;
    // The origin sits where the canvas centre lands, so the scaled hull is around `places`.
    body.body.position = places[i] - canvas_center;
    ShapeDef shape;
    shape.points = *hulls[i].first;
    shape.algorithm = hulls[i].second;
    shape.scale = ShapeScale{canvas_center, Vec2(factors[i], factors[i])};
    body.shapes.push_back(std::move(shape));
    scene.bodies.push_back(std::move(body));
  }
  return scene;
}

SceneBody dynamic_body(const Vec2& position, ShapeDef shape) {
  SceneBody body;
  body.body.type = BodyType::dynamic;
  body.body.position = position;
  body.shapes.push_back(std::move(shape));
  return body;
}

// Every shape kind in one small scene: a chain terrain between two walls, a rounded box, a
// circle, a capsule, a hexagon, a static segment shelf, a sensor band, and two filter teams
// dropped onto the same spot, which fall through each other but not through the ground.
SceneDef shapes_scene() {
  SceneDef scene;
  SceneBody ground;
  std::vector<Vec2> terrain;
  // A valley between two walls. A chain collides on the right of each segment: walking right
  // to left keeps its solid side down and its face up.
  terrain.emplace_back(15, 10);
  for (int i = 0; i <= 30; ++i) {
    const Real x = 15 - i;
    terrain.emplace_back(x, 0.5 * std::sin(0.4 * x) + 0.02 * x * x);
  }
  terrain.emplace_back(-15, 10);
  ground.shapes.push_back(ShapeDef::chain(std::move(terrain)));
  ground.shapes.push_back(ShapeDef::segment(Vec2(6, 6), Vec2(10, 5)));
  ShapeDef band = ShapeDef::box(15, 0.5, Vec2(0, 4));
  band.is_sensor = true;
  ground.shapes.push_back(std::move(band));
  scene.bodies.push_back(std::move(ground));

  ShapeDef rounded = ShapeDef::box(0.6, 0.4);
  rounded.radius = 0.15;
  scene.bodies.push_back(dynamic_body(Vec2(-9, 8), std::move(rounded)));
  scene.bodies.push_back(dynamic_body(Vec2(-6, 9), ShapeDef::circle(0.5)));
  scene.bodies.push_back(
      dynamic_body(Vec2(11, 9), ShapeDef::capsule(Vec2(-0.5, 0), Vec2(0.5, 0), 0.3)));
  scene.bodies.push_back(dynamic_body(Vec2(8, 8), ShapeDef::regular_polygon(6, 0.5)));

  // Team bits: each team's mask leaves out the other team, so they pass through each other.
  // Both drop into the bottom of the valley.
  constexpr std::uint64_t kRed = 0x2, kBlue = 0x4;
  for (int i = 0; i < 4; ++i) {
    ShapeDef red = ShapeDef::box(0.4, 0.4);
    red.filter.category = kRed;
    red.filter.mask = ~kBlue;
    red.user_data = 1;
    scene.bodies.push_back(dynamic_body(Vec2(-2.5, 7 + 1.2 * i), std::move(red)));
    ShapeDef blue = ShapeDef::circle(0.4);
    blue.filter.category = kBlue;
    blue.filter.mask = ~kRed;
    blue.user_data = 2;
    scene.bodies.push_back(dynamic_body(Vec2(-2.3, 7.5 + 1.2 * i), std::move(blue)));
  }
  return scene;
}

constexpr std::array<std::string_view, 7> kSceneNames = {
    "large_pyramid", "pyramid", "many_pyramids", "rain", "tumbler", "paper", "shapes"};

}  // namespace

std::span<const std::string_view> builtin_scene_names() noexcept {
  return kSceneNames;
}

SceneDef builtin_scene(std::string_view name) {
  if (name == "large_pyramid") return pyramid_scene(100);
  if (name == "pyramid") return pyramid_scene(20);
  if (name == "many_pyramids") return many_pyramids_scene(20, 20, 10);
  if (name == "rain") return rain_scene(300, 5, RainShapes::mixed);
  if (name == "tumbler") return tumbler_scene();
  if (name == "paper") return paper_scene();
  if (name == "shapes") return shapes_scene();
  throw InvalidArgumentError("unknown scene '" + std::string(name) + "'");
}

}  // namespace mink
