// Joints in scenes: SceneDef::joints through build_world and capture_scene, the scene file's
// "joints" array (both frames, every key, the named errors), and the built-in scenes with joints.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "mink/engine/scene.hpp"
#include "mink/engine/scene_fields.hpp"
#include "mink/engine/scene_file.hpp"
#include "mink/engine/world.hpp"
#include "mink/error.hpp"
#include "test_worlds.hpp"

namespace mink {
namespace {

using JointRow = SceneField<SceneJointRecord>;

// The keys the reader converts and the writer never writes.
bool read_only(const JointRow& row) {
  return row.key == "anchor" || row.key == "anchor_a" || row.key == "anchor_b" || row.key == "axis";
}

// Every key of every table that applies to both joints, exactly.
void expect_same_joint(const SceneJoint& a, const SceneJoint& b, const std::string& where) {
  SceneJointRecord ra, rb;
  ra.joint = a;
  rb.joint = b;
  ASSERT_EQ(joint_type(a.def), joint_type(b.def)) << where;
  for (const JointRow& row : joint_fields()) {
    if (row.applies != nullptr && !row.applies(ra)) continue;
    EXPECT_TRUE(row.get(ra) == row.get(rb)) << where << "." << row.key;
  }
  for (const SceneJointPart& part : joint_parts()) {
    if (!part.applies(ra)) continue;
    for (const JointRow& row : part.fields) {
      if (row.applies != nullptr && !row.applies(ra)) continue;
      EXPECT_TRUE(row.get(ra) == row.get(rb)) << where << "." << part.key << "." << row.key;
    }
  }
}

void expect_same_joints(const SceneDef& a, const SceneDef& b) {
  ASSERT_EQ(a.joints.size(), b.joints.size());
  for (std::size_t i = 0; i < a.joints.size(); ++i) {
    expect_same_joint(a.joints[i], b.joints[i], "joints[" + std::to_string(i) + "]");
  }
}

// A value for the row other than its kind's default, valid for the engine; `salt` keeps the
// values of one joint apart (upper above lower, ...).
FieldValue other_value(const JointRow& row, const FieldValue& current, int salt) {
  if (row.key == "local_axis_a") return Vec2(0.6, -0.8);
  if (row.key == "break_force" || row.key == "break_torque") return Real(100 + salt);
  switch (row.kind) {
    case FieldKind::real:
      return std::get<Real>(current) + 0.1 + 0.01 * salt;  // not a binary fraction
    case FieldKind::boolean:
      return !std::get<bool>(current);
    case FieldKind::vec2:
      return Vec2(std::get<Vec2>(current) + Vec2(0.1 * (salt + 1), -0.3 * (salt + 1)));
    case FieldKind::user_data:
      return std::uint64_t{1000} + static_cast<std::uint64_t>(salt);
    default:
      ADD_FAILURE() << row.key << ": no other value";
      return current;
  }
}

// A joint of the kind with every key that is written set to a value other than its default
// (in its part's object too), between scene bodies 1 and 2, or for a gear joints 0 and 1.
SceneJoint joint_with_every_key(std::string_view kind) {
  SceneJointRecord record;
  joint_fields()[0].set(record, std::string(kind));
  int salt = 0;
  const auto set_rows = [&](std::span<const JointRow> rows) {
    for (const JointRow& row : rows) {
      if (row.key == "type" || read_only(row)) continue;
      if (row.applies != nullptr && !row.applies(record)) continue;
      if (row.kind == FieldKind::integer) continue;  // indices: set below
      const FieldValue before = row.get(record);
      const FieldValue value = other_value(row, before, salt++);
      row.set(record, value);
      EXPECT_TRUE(row.get(record) == value) << kind << "." << row.key;
      EXPECT_FALSE(before == value) << kind << "." << row.key << " kept its default";
    }
  };
  set_rows(joint_fields());
  for (const SceneJointPart& part : joint_parts()) {
    if (!part.applies(record)) continue;
    part.enable(record);
    set_rows(part.fields);
  }
  record.joint.body_a = 1;
  record.joint.body_b = 2;
  record.joint.joint1 = 0;
  record.joint.joint2 = 1;
  return record.joint;
}

// A static body and three dynamic ones, turned, so that local and world frames differ.
SceneDef four_bodies() {
  SceneDef scene;
  scene.bodies.resize(4);
  for (std::size_t i = 0; i < 4; ++i) {
    BodyDef& body = scene.bodies[i].body;
    body.type = i == 0 ? BodyType::static_body : BodyType::dynamic;
    body.position = Vec2(2.0 * i - 3, 1.0 + 0.5 * i);
    body.angle = 0.3 * i - 0.2;
    scene.bodies[i].shapes.push_back(ShapeDef::circle(0.25));
  }
  return scene;
}

std::vector<std::string_view> kind_names() {
  const auto names = joint_fields()[0].names();
  return {names.begin(), names.end()};
}

// Revolute and prismatic first: the gear couples joints 0 and 1; and the gear last, where
// capture puts gears.
TEST(JointScene, EveryKindRoundTripsThroughWorldCaptureAndFile) {
  std::vector<std::string_view> kinds = kind_names();
  ASSERT_EQ(kinds.size(), 8u);
  ASSERT_EQ(kinds[0], "revolute");
  ASSERT_EQ(kinds[1], "prismatic");
  std::stable_partition(kinds.begin(), kinds.end(), [](std::string_view k) { return k != "gear"; });
  SceneDef scene = four_bodies();
  for (const std::string_view kind : kinds) scene.joints.push_back(joint_with_every_key(kind));

  World world = build_world(scene);
  ASSERT_EQ(world.joint_count(), kinds.size());
  const SceneDef captured = capture_scene(world);
  expect_same_joints(scene, captured);

  const std::string text = scene_to_json(captured);
  const SceneDef loaded = parse_scene_json(text);
  expect_same_joints(scene, loaded);
  EXPECT_EQ(scene_to_json(loaded), text);
  // The body-local forms are written, never the world ones.
  for (const std::string key : {"\"anchor\"", "\"anchor_a\"", "\"axis\"", "\"lower\""}) {
    EXPECT_EQ(key == "\"lower\"", text.find(key) != std::string::npos) << key;
  }
}

// A captured joint keeps its body-local anchors: pulled apart, the pendulum is rebuilt with
// the same joint, which pulls the bob back (not a joint made where the bob now is).
TEST(JointScene, CaptureKeepsAStretchedJointAsItWasDefined) {
  SceneDef scene;
  scene.world.gravity = Vec2(0, 0);
  scene.bodies.push_back({});
  SceneBody bob;
  bob.body.type = BodyType::dynamic;
  bob.body.position = Vec2(0, -2);
  bob.shapes.push_back(ShapeDef::circle(0.25));
  scene.bodies.push_back(bob);
  SceneJoint pin;
  pin.body_a = 0;
  pin.body_b = 1;
  RevoluteJointDef def;
  def.local_anchor_b = Vec2(0, 2);
  pin.def = def;
  scene.joints.push_back(pin);

  World world = build_world(scene);
  const BodyId moved = world.bodies()[1];
  world.set_transform(moved, Vec2(1, -3), 0.4);
  const SceneDef captured = capture_scene(world);
  expect_same_joints(scene, captured);
  World rebuilt = build_world(captured);
  const BodyId again = rebuilt.bodies()[1];
  const auto gap = [&] {
    return (rebuilt.joint_anchor_b(rebuilt.joints()[0]) - Vec2(0, 0)).norm();
  };
  const Real stretched = gap();
  EXPECT_GT(stretched, 1.0);
  for (int i = 0; i < 60; ++i) rebuilt.step();
  EXPECT_LT(gap(), 0.05 * stretched);
  EXPECT_TRUE(test::finite_state(rebuilt, again));
}

// Capture lists gears after their joints even when a gear took a lower, reused slot.
TEST(JointScene, CaptureOrdersGearsAfterTheirJoints) {
  SceneDef scene = four_bodies();
  World world = build_world(scene);
  const std::vector<BodyId> b = world.bodies();
  const JointId doomed =
      world.create_joint(revolute_joint_at(world, b[0], b[3], world.position(b[3])));
  const JointId first = world.create_joint(revolute_joint_at(world, b[0], b[1], Vec2(0, 0)));
  const JointId second =
      world.create_joint(prismatic_joint_at(world, b[0], b[2], Vec2(0, 0), Vec2(1, 0)));
  world.destroy_joint(doomed);
  GearJointDef gear;
  gear.joint1 = first;
  gear.joint2 = second;
  gear.ratio = 3;
  const JointId made = world.create_joint(gear);
  ASSERT_LT(made.index, first.index);  // the reused slot
  const SceneDef captured = capture_scene(world);
  ASSERT_EQ(captured.joints.size(), 3u);
  EXPECT_EQ(joint_type(captured.joints[2].def), JointType::gear);
  EXPECT_EQ(captured.joints[2].joint1, 0u);
  EXPECT_EQ(captured.joints[2].joint2, 1u);
  EXPECT_EQ(captured.joints[0].body_b, 1u);
  EXPECT_EQ(captured.joints[1].body_b, 2u);
  World rebuilt = build_world(captured);
  EXPECT_EQ(rebuilt.joint_count(), 3u);
}

// World-frame keys become what the engine's *_joint_at helpers make from the same points, with
// the bodies where the scene defines them.
TEST(JointScene, WorldPointsBecomeTheHelpersBodyLocalDefinitions) {
  const SceneDef scene = parse_scene_json(R"({
    "bodies": [
      {"type": "static", "position": [-3, 1], "angle": -0.2, "shapes": []},
      {"type": "dynamic", "position": [-1, 1.5], "angle": 0.1, "shapes": []},
      {"type": "dynamic", "position": [1, 2], "angle": 0.4, "shapes": []}],
    "joints": [
      {"type": "revolute", "body_a": 1, "body_b": 2, "anchor": [0, 2]},
      {"type": "prismatic", "body_a": 1, "body_b": 2, "anchor": [0, 2], "axis": [3, 4]},
      {"type": "distance", "body_a": 0, "body_b": 2, "anchor_a": [-3, 3], "anchor_b": [1, 2.5]},
      {"type": "weld", "body_a": 1, "body_b": 2, "anchor": [0.5, 1]},
      {"type": "wheel", "body_a": 1, "body_b": 2, "anchor": [1, 2], "axis": [0, 2]},
      {"type": "pulley", "body_a": 1, "body_b": 2, "ground_a": [-1, 6], "ground_b": [1, 6],
       "anchor_a": [-1, 2], "anchor_b": [1, 2.5], "ratio": 2},
      {"type": "revolute", "body_a": 0, "body_b": 1, "anchor": [-2, 1], "reference_angle": 1}]
  })");
  World world = build_world(scene);
  const std::vector<BodyId> b = world.bodies();
  const std::vector<JointDef> want = {
      revolute_joint_at(world, b[1], b[2], Vec2(0, 2)),
      prismatic_joint_at(world, b[1], b[2], Vec2(0, 2), Vec2(3, 4)),
      distance_joint_at(world, b[0], b[2], Vec2(-3, 3), Vec2(1, 2.5)),
      weld_joint_at(world, b[1], b[2], Vec2(0.5, 1)),
      wheel_joint_at(world, b[1], b[2], Vec2(1, 2), Vec2(0, 2)),
      pulley_joint_at(world, b[1], b[2], Vec2(-1, 6), Vec2(1, 6), Vec2(-1, 2), Vec2(1, 2.5), 2),
  };
  for (std::size_t i = 0; i < want.size(); ++i) {
    SCOPED_TRACE("joints[" + std::to_string(i) + "]");
    SceneJointRecord got, expected;
    got.joint = scene.joints[i];
    expected.joint.def = want[i];
    ASSERT_EQ(joint_type(got.joint.def), joint_type(want[i]));
    for (const JointRow& row : joint_fields()) {
      if (row.kind != FieldKind::real && row.kind != FieldKind::vec2) continue;
      if (read_only(row) || (row.applies != nullptr && !row.applies(got))) continue;
      const FieldValue g = row.get(got), e = row.get(expected);
      if (g == e) continue;  // exactly (and infinite break thresholds)
      if (row.kind == FieldKind::real) {
        EXPECT_NEAR(std::get<Real>(g), std::get<Real>(e), 1e-12) << row.key;
      } else {
        EXPECT_NEAR((std::get<Vec2>(g) - std::get<Vec2>(e)).norm(), 0, 1e-12) << row.key;
      }
    }
  }
  // An explicit reference angle wins over the bodies' angle difference.
  EXPECT_EQ(std::get<RevoluteJointDef>(scene.joints[6].def).reference_angle, 1);
  // Limits and parts: given is on, and a part's missing keys keep the kind's defaults.
  const SceneDef parts = parse_scene_json(R"({
    "bodies": [{"type": "static", "shapes": []}, {"type": "dynamic", "shapes": []}],
    "joints": [
      {"type": "wheel", "body_a": 0, "body_b": 1, "spring": {"hertz": 4}, "lower": -1,
       "upper": 1, "motor": {"speed": 2, "max_torque": 3, "enabled": false}},
      {"type": "distance", "body_a": 0, "body_b": 1, "max_length": 2},
      {"type": "wheel", "body_a": 0, "body_b": 1}]
  })");
  const auto& wheel = std::get<WheelJointDef>(parts.joints[0].def);
  EXPECT_TRUE(wheel.spring.enabled);
  EXPECT_EQ(wheel.spring.hertz, 4);
  EXPECT_EQ(wheel.spring.damping_ratio, WheelJointDef{}.spring.damping_ratio);
  EXPECT_TRUE(wheel.limit.enabled);
  EXPECT_FALSE(wheel.motor.enabled);
  EXPECT_EQ(wheel.motor.max_force, 3);
  const auto& rope = std::get<DistanceJointDef>(parts.joints[1].def);
  EXPECT_TRUE(rope.limit.enabled);
  EXPECT_EQ(rope.limit.lower, 0);
  EXPECT_EQ(rope.limit.upper, 2);
  EXPECT_TRUE(std::get<WheelJointDef>(parts.joints[2].def).spring.enabled);
  EXPECT_FALSE(std::isfinite(std::get<WheelJointDef>(parts.joints[2].def).break_force));
}

TEST(JointScene, EveryBadJointGetsItsPathAndProblem) {
  struct Bad {
    std::string joints;  // the "joints" array's entries
    std::string path;
    std::string problem;
  };
  const std::string pin = R"({"type": "revolute", "body_a": 0, "body_b": 1, "anchor": [0, 0]})";
  const std::vector<Bad> cases = {
      {pin + "," + pin + "," + pin + R"(, {"type": "revolute", "body_a": 0, "body_b": 12})",
       "joints[3].body_b", "no body 12"},
      {R"({"type": "hinge", "body_a": 0, "body_b": 1})", "joints[0].type",
       R"(expected "revolute", "prismatic", "distance", "weld", "wheel", "motor", "gear" or )"
       R"("pulley", got "hinge")"},
      {R"({"body_a": 0, "body_b": 1})", "joints[0].type", "missing field"},
      {R"({"type": "weld", "body_b": 1})", "joints[0].body_a", "missing field"},
      {R"({"type": "weld", "body_a": -1, "body_b": 1})", "joints[0].body_a",
       "must be in 0..2147483647, got -1"},
      {R"({"type": "weld", "body_a": 1, "body_b": 1})", "joints[0].body_b",
       "the same body as body_a (1)"},
      {R"({"type": "distance", "body_a": 0, "body_b": 1, "lower": 0, "upper": 1})",
       "joints[0].lower", "only allowed on revolute, prismatic and wheel joints"},
      {R"({"type": "revolute", "body_a": 0, "body_b": 1, "lower": 0.5})", "joints[0].upper",
       "missing field (lower is given)"},
      {R"({"type": "revolute", "body_a": 0, "body_b": 1, "lower": 0.5, "upper": 0.2})",
       "joints[0].upper", "must be >= lower (0.5), got 0.2"},
      {R"({"type": "distance", "body_a": 0, "body_b": 1, "min_length": 3, "max_length": 2})",
       "joints[0].max_length", "must be >= min_length (3), got 2"},
      {R"({"type": "distance", "body_a": 0, "body_b": 1, "min_length": 1})", "joints[0].max_length",
       "missing field (min_length is given)"},
      {R"({"type": "distance", "body_a": 0, "body_b": 1, "length": 0})", "joints[0].length",
       "must be > 0, got 0"},
      {R"({"type": "revolute", "body_a": 0, "body_b": 1, "anchor": [0, 0],
           "local_anchor_a": [1, 0]})",
       "joints[0].local_anchor_a", "give only one of anchor and local_anchor_a"},
      {R"({"type": "wheel", "body_a": 0, "body_b": 1, "axis": [0, 0]})", "joints[0].axis",
       "must not be [0, 0]"},
      {R"({"type": "prismatic", "body_a": 0, "body_b": 1, "local_axis_a": [1, 1]})",
       "joints[0].local_axis_a", "must be a unit vector"},
      {R"({"type": "weld", "body_a": 0, "body_b": 1, "motor": {"speed": 1}})", "joints[0].motor",
       "only allowed on revolute, prismatic, distance and wheel joints"},
      {R"({"type": "revolute", "body_a": 0, "body_b": 1, "motor": {"max_force": 1}})",
       "joints[0].motor.max_force", "only allowed on prismatic and distance joints"},
      {R"({"type": "revolute", "body_a": 0, "body_b": 1, "spring": {"hertz": -1}})",
       "joints[0].spring.hertz", "must be >= 0, got -1"},
      {R"({"type": "distance", "body_a": 0, "body_b": 1, "spring": {"target": 1}})",
       "joints[0].spring.target", "only allowed on revolute, prismatic and wheel joints"},
      {R"({"type": "revolute", "body_a": 0, "body_b": 1, "anchr": [0, 0]})", "joints[0].anchr",
       "unknown key"},
      {R"({"type": "revolute", "body_a": 0, "body_b": 1, "break_force": -1})",
       "joints[0].break_force", "must be >= 0, got -1"},
      {R"({"type": "motor", "body_a": 0, "body_b": 1, "correction_factor": 2})",
       "joints[0].correction_factor", "must be in 0..1, got 2"},
      {R"({"type": "pulley", "body_a": 0, "body_b": 1, "ratio": 0})", "joints[0].ratio",
       "must be > 0 for a pulley, got 0"},
      {R"({"type": "gear", "joint1": 0, "joint2": 1})", "joints[0].joint1",
       "no joint 0 before this one"},
      {pin + R"(, {"type": "distance", "body_a": 0, "body_b": 1},
                  {"type": "gear", "joint1": 0, "joint2": 1})",
       "joints[2].joint2", "joint 1 is a distance joint; a gear couples revolute or prismatic"},
      {pin + R"(, {"type": "gear", "joint1": 0, "joint2": 0})", "joints[1].joint2",
       "the same joint as joint1 (0)"},
      {pin + "," + pin + R"(, {"type": "gear", "joint1": 0, "joint2": 1, "ratio": 0})",
       "joints[2].ratio", "must not be 0 for a gear"},
      {R"({"type": "gear", "body_a": 0, "joint1": 0, "joint2": 1})", "joints[0].body_a",
       "only allowed on revolute, prismatic, distance, weld, wheel, motor and pulley joints"},
      {R"({"type": "revolute", "body_a": 0, "body_b": 1, "joint1": 0})", "joints[0].joint1",
       "only allowed on gear joints"},
  };
  const std::string bodies =
      R"("bodies": [{"type": "static", "shapes": []}, {"type": "dynamic", "shapes": []}])";
  for (const Bad& bad : cases) {
    SCOPED_TRACE(bad.joints);
    try {
      (void)parse_scene_json("{" + bodies + R"(, "joints": [)" + bad.joints + "]}");
      ADD_FAILURE() << "accepted";
    } catch (const SceneFileError& error) {
      const std::string message = error.what();
      EXPECT_EQ(error.json_path(), bad.path) << message;
      EXPECT_NE(message.find(bad.problem), std::string::npos) << message;
    }
  }
  try {
    (void)parse_scene_json("{" + bodies + R"(, "joints": {}})");
    ADD_FAILURE() << "accepted";
  } catch (const SceneFileError& error) {
    EXPECT_EQ(std::string(error.what()), "joints: expected an array, got an object");
  }
}

TEST(JointScene, BuildWorldNamesABadJointsIndices) {
  SceneDef scene = four_bodies();
  SceneJoint joint;
  joint.def = RevoluteJointDef{};
  joint.body_a = 0;
  joint.body_b = 12;
  scene.joints = {joint, joint};
  scene.joints[0].body_b = 1;
  const auto message = [&] {
    try {
      (void)build_world(scene);
    } catch (const InvalidArgumentError& error) {
      return std::string(error.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(message(), "joints[1].body_b: no body 12");
  scene.joints[1].def = GearJointDef{};
  scene.joints[1].joint1 = 0;
  scene.joints[1].joint2 = 1;
  EXPECT_EQ(message(), "joints[1].joint2: no joint 1 before this one");
  scene.joints.pop_back();
  std::get<RevoluteJointDef>(scene.joints[0].def).limit = {true, 1, 0};
  EXPECT_EQ(message().rfind("joints[0]: revolute joint.limit.lower must not exceed", 0), 0u)
      << message();
}

}  // namespace
}  // namespace mink

namespace mink {
namespace {

// ---- Built-in scenes with joints ----

// Largest gap between the two anchors of the world's revolute joints: 0 when all hold.
Real widest_revolute_gap(const World& world) {
  Real widest = 0;
  for (const JointId j : world.joints()) {
    if (world.joint_type(j) != JointType::revolute) continue;
    widest = std::max(widest, (world.joint_anchor_a(j) - world.joint_anchor_b(j)).norm());
  }
  return widest;
}

bool all_finite(const World& world) {
  for (const BodyId id : world.bodies()) {
    if (!test::finite_state(world, id)) return false;
  }
  return true;
}

// Box2D v3's suite scenes are left to suite_scene_test.cpp: 600 steps of all ten take minutes.
TEST(JointScenes, EveryBuiltinRuns600StepsWithoutNaN) {
  for (const std::string_view name : builtin_scene_names()) {
    if (test::is_benchmark_scene(name)) continue;
    SCOPED_TRACE(std::string(name));
    SceneRun run(builtin_scene(name));
    for (int i = 0; i < 600; ++i) run.step();
    EXPECT_TRUE(all_finite(run.world()));
  }
}

// Long runs of every built-in with joints, with sleeping off so every joint is solved every
// step: 10^4 steps (under the sanitizers, whose slowdown would make this minutes, 2000).
TEST(JointScenes, EveryJointSceneRunsTenThousandStepsWithoutNaN) {
  constexpr int kSteps = test::long_run(10000, 2000);
  int scenes = 0;
  for (const std::string_view name : builtin_scene_names()) {
    // Box2D v3's suite scenes have runs of their own (suite_scene_test.cpp).
    if (test::is_benchmark_scene(name)) continue;
    SceneDef scene = builtin_scene(name);
    if (scene.joints.empty()) continue;
    ++scenes;
    SCOPED_TRACE(std::string(name));
    scene.world.enable_sleep = false;
    World world = build_world(scene);
    for (int i = 1; i <= kSteps; ++i) {
      world.step();
      if (i % 1000 == 0) {
        ASSERT_TRUE(all_finite(world)) << "at step " << i;
      }
    }
    EXPECT_TRUE(all_finite(world));
    EXPECT_EQ(world.joint_count(), scene.joints.size()) << "no joint lost";
  }
  EXPECT_GE(scenes, 7) << "pendulum, chain, bridge, ragdolls, car, newtons_cradle, tumbler";
}

// The first pendulum (3 m, started 1 rad out) swings from one side to the other on its rigid
// pin; the rigid distance pendulum keeps its length.
TEST(JointScenes, PendulumsSwingOnTheirJoints) {
  const SceneDef scene = builtin_scene("pendulum");
  World world = build_world(scene);
  const std::vector<JointId> joints = world.joints();
  const JointId first = joints[0];
  const Vec2 pivot = world.joint_anchor_a(first);
  const BodyId bob = world.joint_body_b(first);
  JointId rope;
  for (const JointId j : joints) {
    if (world.joint_type(j) == JointType::distance) {
      rope = j;
      break;
    }
  }
  ASSERT_FALSE(rope.is_null());
  const Vec2 rope_anchor = world.joint_anchor_a(rope);
  const Real rope_length = (world.joint_anchor_b(rope) - rope_anchor).norm();
  Real left = 0, right = 0, worst_rod = 0, worst_rope = 0;
  for (int i = 0; i < 600; ++i) {
    world.step();
    const Real dx = world.position(bob).x() - pivot.x();
    left = std::min(left, dx);
    right = std::max(right, dx);
    worst_rod = std::max(worst_rod, std::abs((world.position(bob) - pivot).norm() - 3));
    worst_rope = std::max(
        worst_rope, std::abs((world.joint_anchor_b(rope) - rope_anchor).norm() - rope_length));
  }
  EXPECT_GT(right, 2.0);
  EXPECT_LT(left, -2.0);
  EXPECT_LT(worst_rod, 0.02);
  EXPECT_LT(widest_revolute_gap(world), 0.02);
  EXPECT_LT(worst_rope, 0.05);
}

// The chain falls from level and hangs below its pin, its links still pinned together, the
// heavy weight at most the chain's length (plus its radius) from the pin.
TEST(JointScenes, ChainHangsBelowItsPin) {
  const SceneDef scene = builtin_scene("chain");
  ASSERT_EQ(scene.joints.size(), 31u);
  World world = build_world(scene);
  const std::vector<JointId> joints = world.joints();
  const Vec2 pin = world.joint_anchor_a(joints.front());
  const BodyId weight = world.joint_body_b(joints.back());
  const BodyId link = world.joint_body_b(joints.front());
  EXPECT_NEAR(world.mass(weight), 100 * world.mass(link), 1e-9);
  for (int i = 0; i < 600; ++i) world.step();
  for (std::size_t j = 0; j < joints.size(); ++j) {
    EXPECT_LT(world.position(world.joint_body_b(joints[j])).y(), pin.y() + 0.05) << j;
  }
  EXPECT_LT((world.position(weight) - pin).norm(), 15 + 0.5 + 0.3);
  EXPECT_LT(widest_revolute_gap(world), 0.1);
  EXPECT_TRUE(all_finite(world));
}

// The bridge carries its boxes between its anchors: planks sag, but stay up and pinned.
TEST(JointScenes, BridgeHoldsItsLoad) {
  World world = build_world(builtin_scene("bridge"));
  for (int i = 0; i < 600; ++i) world.step();
  for (const JointId j : world.joints()) {
    const BodyId plank = world.joint_body_b(j);
    if (world.body_type(plank) == BodyType::dynamic) {
      EXPECT_GT(world.position(plank).y(), 3);
    }
  }
  EXPECT_LT(widest_revolute_gap(world), 0.05);
  // The boxes rest on the bridge, not on the ground.
  for (const BodyId id : world.bodies()) {
    if (world.body_type(id) == BodyType::dynamic) {
      EXPECT_GT(world.position(id).y(), 3);
    }
  }
}

// Ragdolls fall in a heap but keep their joints and stay above the ground.
TEST(JointScenes, RagdollsKeepTheirJointsAndParts) {
  const SceneDef scene = builtin_scene("ragdolls");
  EXPECT_EQ(scene.joints.size(), 12u * 10u);
  World world = build_world(scene);
  for (int i = 0; i < 600; ++i) world.step();
  EXPECT_LT(widest_revolute_gap(world), 0.05);
  for (const BodyId id : world.bodies()) {
    if (world.body_type(id) == BodyType::dynamic) {
      EXPECT_GT(world.position(id).y(), 0);
    }
  }
  // Limits hold (with a little give).
  for (const JointId j : world.joints()) {
    const JointLimit limit = world.joint_limit(j);
    EXPECT_GT(world.joint_coordinate(j), limit.lower - 0.1);
    EXPECT_LT(world.joint_coordinate(j), limit.upper + 0.1);
  }
}

TEST(JointScenes, CarDrivesRightOnItsWheelJoints) {
  World world = build_world(builtin_scene("car"));
  const BodyId chassis = world.joint_body_a(world.joints()[0]);
  const Real start = world.position(chassis).x();
  for (int i = 0; i < 600; ++i) world.step();
  EXPECT_GT(world.position(chassis).x() - start, 5);
  EXPECT_GT(world.position(chassis).y(), -0.5);
}

TEST(JointScenes, NewtonsCradlePassesTheBlow) {
  World world = build_world(builtin_scene("newtons_cradle"));
  const std::vector<JointId> joints = world.joints();
  ASSERT_EQ(joints.size(), 5u);
  const BodyId last = world.joint_body_b(joints.back());
  const Real rest = world.position(last).x();
  Real farthest = 0;
  for (int i = 0; i < 600; ++i) {
    world.step();
    farthest = std::max(farthest, world.position(last).x() - rest);
  }
  EXPECT_GT(farthest, 1.5);
}

}  // namespace
}  // namespace mink
