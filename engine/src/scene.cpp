#include "mink/engine/scene.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <span>
#include <string>
#include <variant>

#include "benchmark_scenes.hpp"
#include "human.hpp"
#include "mink/error.hpp"
#include "mink/geometry/point_sets.hpp"
#include "scene_building.hpp"

namespace mink {

using detail::add_body;
using detail::add_joint;
using detail::static_box;

Pose scene_body_pose(const SceneDef& scene, std::size_t index) {
  if (index >= scene.bodies.size()) {
    throw InvalidArgumentError("no body " + std::to_string(index) + " in a scene of " +
                               std::to_string(scene.bodies.size()));
  }
  const BodyDef& body = scene.bodies[index].body;
  return {body.position, Rotation::from_angle(body.angle)};
}

void shift_scene(SceneDef& scene, const Vec2& offset) {
  if (!std::isfinite(offset.x()) || !std::isfinite(offset.y())) {
    throw InvalidArgumentError("scene offset is not finite");
  }
  if (scene.schedule) {
    throw InvalidArgumentError("a scene with a schedule cannot be shifted: its actions are code");
  }
  for (SceneBody& body : scene.bodies) body.body.position += offset;
  for (SceneJoint& joint : scene.joints) {
    if (auto* pulley = std::get_if<PulleyJointDef>(&joint.def)) {
      pulley->ground_anchor_a += offset;
      pulley->ground_anchor_b += offset;
    }
  }
}

namespace {

std::string joint_path(std::size_t joint, const char* field) {
  return "joints[" + std::to_string(joint) + "]." + field;
}

// The joint's definition with the world's ids for the scene's indices.
JointDef joint_in_world(const SceneJoint& joint, std::size_t index, std::span<const BodyId> bodies,
                        std::span<const JointId> joints) {
  JointDef def = joint.def;
  if (auto* gear = std::get_if<GearJointDef>(&def)) {
    // Only earlier joints exist yet: a gear is made after the joints it couples.
    const auto earlier = [&](std::size_t j, const char* field) {
      if (j >= index) {
        throw InvalidArgumentError(joint_path(index, field) + ": no joint " + std::to_string(j) +
                                   " before this one");
      }
      return joints[j];
    };
    gear->joint1 = earlier(joint.joint1, "joint1");
    gear->joint2 = earlier(joint.joint2, "joint2");
    return def;
  }
  const auto body = [&](std::size_t b, const char* field) {
    if (b >= bodies.size()) {
      throw InvalidArgumentError(joint_path(index, field) + ": no body " + std::to_string(b));
    }
    return bodies[b];
  };
  JointBase& base = joint_base(def);
  base.body_a = body(joint.body_a, "body_a");
  base.body_b = body(joint.body_b, "body_b");
  return def;
}

}  // namespace

SceneIds add_scene(World& world, const SceneDef& scene) {
  SceneIds ids;
  std::vector<BodyId>& bodies = ids.bodies;
  for (const SceneBody& body : scene.bodies) {
    const BodyId id = world.create_body(body.body);
    bodies.push_back(id);
    for (const ShapeDef& shape : body.shapes) {
      if (shape.type == ShapeType::chain) {
        world.create_chain(id, shape);
      } else {
        world.create_shape(id, shape);
      }
    }
  }
  std::vector<JointId>& joints = ids.joints;
  for (std::size_t i = 0; i < scene.joints.size(); ++i) {
    const JointDef def = joint_in_world(scene.joints[i], i, bodies, joints);
    try {
      joints.push_back(world.create_joint(def));
    } catch (const InvalidArgumentError& error) {
      throw InvalidArgumentError("joints[" + std::to_string(i) + "]: " + error.what());
    }
  }
  // Adding shapes and joints wakes bodies; respect a body defined asleep.
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (!scene.bodies[i].body.awake) world.set_awake(bodies[i], false);
  }
  return ids;
}

World build_world(const SceneDef& scene) {
  World world(scene.world);
  add_scene(world, scene);
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

// Every live joint with the scene's indices for the world's ids (scene.bodies already in
// world.bodies() order), ids cleared so that a captured joint equals one read from a file.
void capture_joints(const World& world, SceneDef& scene) {
  std::map<std::uint32_t, std::size_t> body_index, joint_index;
  const std::vector<BodyId> bodies = world.bodies();
  for (std::size_t i = 0; i < bodies.size(); ++i) body_index[bodies[i].index] = i;
  std::vector<JointId> ids = world.joints();
  // A gear may sit in a lower slot than its joints (slots are reused), but must come after
  // them; gears never couple gears, so gears last is enough.
  std::stable_partition(ids.begin(), ids.end(),
                        [&](JointId id) { return world.joint_type(id) != JointType::gear; });
  for (std::size_t i = 0; i < ids.size(); ++i) joint_index[ids[i].index] = i;
  for (const JointId id : ids) {
    SceneJoint joint;
    joint.def = world.joint_def(id);
    if (auto* gear = std::get_if<GearJointDef>(&joint.def)) {
      joint.joint1 = joint_index.at(gear->joint1.index);
      joint.joint2 = joint_index.at(gear->joint2.index);
      gear->joint1 = JointId{};
      gear->joint2 = JointId{};
    } else {
      joint.body_a = body_index.at(world.joint_body_a(id).index);
      joint.body_b = body_index.at(world.joint_body_b(id).index);
    }
    JointBase& base = joint_base(joint.def);
    base.body_a = BodyId{};
    base.body_b = BodyId{};
    scene.joints.push_back(std::move(joint));
  }
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
    def.continuous_threshold = world.continuous_threshold(id);
    def.user_data = world.user_data(id);
    body.shapes = captured_shapes(world, id);
    scene.bodies.push_back(std::move(body));
  }
  capture_joints(world, scene);
  return scene;
}

namespace {

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

// A drum of 400 boxes turned by a revolute motor about a static hub: the drum is dynamic, so
// the boxes' weight loads the motor, which has torque to spare.
SceneDef tumbler_400_scene() {
  SceneDef scene;
  const std::size_t hub = add_body(scene, BodyType::static_body, Vec2(0, 10), {});
  const Real half = 10, wall = 0.5;
  const std::size_t drum = add_body(
      scene, BodyType::dynamic, Vec2(0, 10),
      {ShapeDef::box(wall, half, Vec2(half, 0)), ShapeDef::box(wall, half, Vec2(-half, 0)),
       ShapeDef::box(half, wall, Vec2(0, half)), ShapeDef::box(half, wall, Vec2(0, -half))});
  scene.bodies[drum].body.allow_sleep = false;
  RevoluteJointDef motor;
  motor.motor = {true, 0.25, 1e8};
  add_joint(scene, hub, drum, Vec2(0, 10), Vec2(0, 10), motor);
  for (int i = 0; i < 20; ++i) {
    for (int j = 0; j < 20; ++j) {
      add_body(scene, BodyType::dynamic, Vec2(-7.6 + 0.8 * i, 2.4 + 0.8 * j),
               {ShapeDef::box(0.25, 0.25)});
    }
  }
  return scene;
}

// Pendulums from a ceiling, started 1 rad out: three rigid ones on revolute joints (3, 4 and
// 5 m), a double pendulum, and two on distance joints (one rigid, one a spring). Their bobs
// share a negative group, so they swing through each other.
SceneDef pendulum_scene() {
  SceneDef scene;
  const Real top = 12;
  const std::size_t ceiling =
      add_body(scene, BodyType::static_body, Vec2(0, top), {ShapeDef::box(14, 0.1, Vec2(0, 0.1))});
  const auto bob = [&](const Vec2& at, const Vec2& pivot) {
    ShapeDef ball = ShapeDef::circle(0.3);
    ShapeDef rod = ShapeDef::capsule(Vec2(0, 0), pivot - at, 0.05);
    ball.filter.group = rod.filter.group = -1;
    return add_body(scene, BodyType::dynamic, at, {std::move(ball), std::move(rod)});
  };
  const Vec2 out(std::sin(1.0), -std::cos(1.0));  // 1 rad from hanging straight down
  for (int i = 0; i < 3; ++i) {
    const Vec2 pivot(-12 + 4 * i, top);
    add_joint<RevoluteJointDef>(scene, ceiling, bob(pivot + (3 + i) * out, pivot), pivot, pivot);
  }
  const Vec2 pivot(2, top), elbow = pivot + 2.5 * out, hand = elbow + Vec2(2.5, 0);
  const std::size_t upper = bob(elbow, pivot);
  add_joint<RevoluteJointDef>(scene, ceiling, upper, pivot, pivot);
  add_joint<RevoluteJointDef>(scene, upper, bob(hand, elbow), elbow, elbow);
  for (int i = 0; i < 2; ++i) {
    const Vec2 anchor(8 + 4 * i, top), at = anchor + 4 * out;
    ShapeDef ball = ShapeDef::circle(0.4);
    ball.filter.group = -1;
    const std::size_t b = add_body(scene, BodyType::dynamic, at, {std::move(ball)});
    SceneJoint& joint = add_joint<DistanceJointDef>(scene, ceiling, b, anchor, at);
    if (i == 1) std::get<DistanceJointDef>(joint.def).spring = {true, 1, 0.05, 0};
  }
  return scene;
}

// 30 capsule links from a static pin, laid out level so that they fall and swing, ending in a
// ball of 100 times a link's mass (the mass ratio solvers find hard).
SceneDef chain_scene() {
  SceneDef scene;
  const Vec2 pin(-10, 20);
  const Real h = 0.25, r = 0.1;  // half length between the link's pins, radius
  std::size_t previous =
      add_body(scene, BodyType::static_body, pin, {ShapeDef::box(0.2, 0.2, Vec2(-0.3, 0))});
  for (int i = 0; i < 30; ++i) {
    const std::size_t link = add_body(scene, BodyType::dynamic, pin + Vec2((2 * i + 1) * h, 0),
                                      {ShapeDef::capsule(Vec2(-h, 0), Vec2(h, 0), r)});
    const Vec2 joint = pin + Vec2(2 * i * h, 0);
    add_joint<RevoluteJointDef>(scene, previous, link, joint, joint);
    previous = link;
  }
  const Real link_mass = 4 * h * r + std::numbers::pi * r * r;  // density 1
  const Real radius = 0.5;
  ShapeDef ball = ShapeDef::circle(radius);
  ball.density = 100 * link_mass / (std::numbers::pi * radius * radius);
  const Vec2 end = pin + Vec2(60 * h, 0);
  const std::size_t weight =
      add_body(scene, BodyType::dynamic, end + Vec2(radius, 0), {std::move(ball)});
  add_joint<RevoluteJointDef>(scene, previous, weight, end, end);
  scene.bodies.push_back(static_box(Vec2(0, -1), 30, 1));
  return scene;
}

// 20 planks pinned end to end between two static anchors, and boxes dropped on them.
SceneDef bridge_scene() {
  SceneDef scene;
  scene.bodies.push_back(static_box(Vec2(0, -1), 20, 1));
  const int planks = 20;
  const Real y = 5, left = -planks / 2.0;
  std::size_t previous =
      add_body(scene, BodyType::static_body, Vec2(left - 0.5, y), {ShapeDef::box(0.5, 0.5)});
  for (int i = 0; i <= planks; ++i) {
    const std::size_t next = i < planks
                                 ? add_body(scene, BodyType::dynamic, Vec2(left + i + 0.5, y),
                                            {ShapeDef::box(0.5, 0.125)})
                                 : add_body(scene, BodyType::static_body, Vec2(-left + 0.5, y),
                                            {ShapeDef::box(0.5, 0.5)});
    add_joint<RevoluteJointDef>(scene, previous, next, Vec2(left + i, y), Vec2(left + i, y));
    previous = next;
  }
  for (int i = 0; i < 5; ++i) {
    add_body(scene, BodyType::dynamic, Vec2(-6 + 3 * i, y + 2 + 0.5 * i),
             {ShapeDef::box(0.4, 0.4)});
  }
  return scene;
}

// Ragdolls standing in a row and more dropped on them.
SceneDef ragdolls_scene() {
  SceneDef scene;
  scene.bodies.push_back(static_box(Vec2(0, -1), 20, 1));
  for (int i = 0; i < 12; ++i) {
    const Vec2 feet(-6 + 1.1 * (i % 6) + 0.4 * (i / 6), 3.0 * (i / 6));
    detail::add_human(scene, feet, -(i + 1));
  }
  return scene;
}

// A car on wheel joints, driven by their motors over a chain terrain of growing hills.
SceneDef car_scene() {
  SceneDef scene;
  std::vector<Vec2> terrain;  // right to left: a chain's solid side is on its right
  for (int i = 100; i >= -20; --i) {
    const Real x = i, hills = std::clamp<Real>((x - 5) / 40, 0, 1);
    terrain.emplace_back(x, hills * (0.8 * std::sin(0.4 * x) + 0.4 * std::sin(1.1 * x)));
  }
  add_body(scene, BodyType::static_body, Vec2(0, 0), {ShapeDef::chain(std::move(terrain))});
  ShapeDef hull;
  hull.points = {{-1.5, -0.5}, {1.5, -0.5}, {1.5, 0}, {0, 0.9}, {-1.15, 0.9}, {-1.5, 0.2}};
  const std::size_t chassis = add_body(scene, BodyType::dynamic, Vec2(0, 1.5), {std::move(hull)});
  for (const Real x : {-1.0, 1.0}) {
    ShapeDef tyre = ShapeDef::circle(0.4);
    tyre.density = 2;
    tyre.friction = 1.5;
    const Vec2 centre(x, 0.85);
    const std::size_t wheel = add_body(scene, BodyType::dynamic, centre, {std::move(tyre)});
    WheelJointDef def;
    def.local_axis_a = Vec2(0, 1);
    def.spring = {true, 5, 0.7, 0};
    def.limit = {true, -0.25, 0.25};
    def.motor = {true, -12, 40};  // clockwise: the car drives to the right
    add_joint(scene, chassis, wheel, centre, centre, def);
  }
  return scene;
}

// Five balls on distance joints, touching in a row; the first starts 0.7 rad out. Restitution
// 1 and no friction pass the blow along the row.
SceneDef newtons_cradle_scene() {
  SceneDef scene;
  const Real top = 10, length = 5, radius = 0.5;
  const std::size_t bar =
      add_body(scene, BodyType::static_body, Vec2(0, top), {ShapeDef::box(3.5, 0.1, Vec2(0, 0.1))});
  for (int i = 0; i < 5; ++i) {
    const Vec2 anchor(-2 + 2 * radius * i, top);
    const Real out = i == 0 ? 0.7 : 0;
    const Vec2 at = anchor + length * Vec2(-std::sin(out), -std::cos(out));
    ShapeDef ball = ShapeDef::circle(radius);
    ball.restitution = 1;
    ball.friction = 0;
    const std::size_t b = add_body(scene, BodyType::dynamic, at, {std::move(ball)});
    scene.bodies[b].body.allow_sleep = false;  // the resting balls must be awake for the blow
    add_joint<DistanceJointDef>(scene, bar, b, anchor, at);
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

// Ours, then Box2D v3's benchmark suite (benchmark_scenes.cpp).
constexpr std::array<std::string_view, 23> kSceneNames = {
    "pyramid",        "pyramid_100", "pyramid_grid", "rain_mixed", "tumbler_400",   "paper",
    "shapes",         "pendulum",    "chain",        "bridge",     "ragdolls",      "car",
    "newtons_cradle", "compounds",   "joint_grid",   "junkyard",   "large_pyramid", "many_pyramids",
    "rain",           "smash",       "spinner",      "tumbler",    "washer"};

}  // namespace

std::span<const std::string_view> builtin_scene_names() noexcept {
  return kSceneNames;
}

bool is_builtin_scene(std::string_view name) noexcept {
  return std::find(kSceneNames.begin(), kSceneNames.end(), name) != kSceneNames.end();
}

SceneDef builtin_scene(std::string_view name) {
  if (name == "pyramid") return pyramid_scene(20);
  if (name == "pyramid_100") return pyramid_scene(100);
  if (name == "pyramid_grid") return many_pyramids_scene(20, 20, 10);
  if (name == "rain_mixed") return rain_scene(300, 5, RainShapes::mixed);
  if (name == "tumbler_400") return tumbler_400_scene();
  if (name == "paper") return paper_scene();
  if (name == "shapes") return shapes_scene();
  if (name == "pendulum") return pendulum_scene();
  if (name == "chain") return chain_scene();
  if (name == "bridge") return bridge_scene();
  if (name == "ragdolls") return ragdolls_scene();
  if (name == "car") return car_scene();
  if (name == "newtons_cradle") return newtons_cradle_scene();
  if (std::optional<SceneDef> scene = detail::benchmark_scene(name)) return std::move(*scene);
  throw InvalidArgumentError("unknown scene '" + std::string(name) + "'");
}

}  // namespace mink
