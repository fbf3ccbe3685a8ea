// A solve that diverges stops its bodies, and says so, instead of leaving NaN or a body beyond
// the world in the state (World::body_stopped_events).

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "mink/engine/scene.hpp"
#include "mink/engine/scene_file.hpp"
#include "mink/engine/scene_schedule.hpp"
#include "mink/engine/world.hpp"
#include "test_worlds.hpp"

namespace mink {
namespace {

// Two light capsules held together by two hinges (a weld of redundant rows), one of them
// hinged to a free 32 t circle at an anchor 300 m away, all inside the circle at the start:
// the hinge is a 300 m lever on a capsule, and the single-precision solve runs away within
// five steps (the scene reader's fuzz harness found this family; before, the state turned NaN
// and the next step's broadphase threw).
constexpr const char* kFarHinge = R"({"format": "minkowski-scene", "version": 1,
  "world": {"enable_sleep": false},
  "bodies": [
    {"type": "dynamic", "position": [0.8838834764831844, 19.116116523516816],
     "angle": -0.7853981633974483,
     "shapes": [{"capsule": {"center1": [-0.25, 0], "center2": [0.25, 0], "radius": 0.05}}]},
    {"type": "dynamic", "position": [1.2374368670764582, 18.762563132923542],
     "angle": -0.7853981633974483,
     "shapes": [{"capsule": {"center1": [-0.25, 0], "center2": [0.25, 0], "radius": 0.05}}]},
    {"type": "dynamic", "position": [3.7123106012293747, 16.287689398770624],
     "shapes": [{"circle": {"radius": 5.93}, "density": 294.64790894703253}]}],
  "joints": [
    {"type": "revolute", "body_a": 1, "body_b": 0, "anchor": [0.7071067811865476, 19.292893217813454]},
    {"type": "revolute", "body_a": 0, "body_b": 1, "anchor": [1.0606601717798214, 18.939339828220177]},
    {"type": "revolute", "body_a": 1, "body_b": 2, "anchor": [3.5355339059327378, 316.3]}]})";

struct BodyState {
  Vec2 position;
  Real angle;
};

TEST(Divergence, AFarHingeOnALightBodyIsStoppedAndReportedInsteadOfTurningNaN) {
  World world = build_world(parse_scene_json(kFarHinge));
  const std::vector<BodyId> bodies = world.bodies();
  int stopped_steps = 0;
  for (int step = 1; step <= 120; ++step) {
    std::vector<BodyState> before;
    for (const BodyId b : bodies) before.push_back({world.position(b), world.angle(b)});
    world.step();
    ASSERT_TRUE(test::all_finite(world)) << "step " << step;
    const auto stopped = world.body_stopped_events();
    if (stopped.empty()) continue;
    ++stopped_steps;
    // The three bodies are joined, so all three stop, in slot order, and the solve diverged
    // on at least one of them.
    ASSERT_EQ(stopped.size(), 3u) << "step " << step;
    bool any_diverged = false;
    for (std::size_t k = 0; k < stopped.size(); ++k) {
      EXPECT_EQ(stopped[k].body, bodies[k]);
      any_diverged = any_diverged || stopped[k].diverged;
      // Where the step began, at rest.
      EXPECT_EQ(world.position(bodies[k]), before[k].position) << "step " << step;
      EXPECT_EQ(world.angle(bodies[k]), before[k].angle) << "step " << step;
      EXPECT_EQ(world.linear_velocity(bodies[k]), Vec2(0, 0));
      EXPECT_EQ(world.angular_velocity(bodies[k]), 0);
    }
    EXPECT_TRUE(any_diverged) << "step " << step;
    for (const JointId j : world.joints()) {
      EXPECT_EQ(world.joint_force(j), Vec2(0, 0)) << "step " << step;
      EXPECT_EQ(world.joint_torque(j), 0) << "step " << step;
    }
  }
  EXPECT_GT(stopped_steps, 0);
  // What the world holds is a world: its own snapshot restores to the same state.
  const std::vector<std::uint8_t> bytes = world.snapshot();
  EXPECT_EQ(World::from_snapshot(bytes).state_hash(), world.state_hash());
}

TEST(Divergence, StopsAreBitwiseTheSameAtOneAndTwoWorkers) {
  SceneDef scene = parse_scene_json(kFarHinge);
  World one = build_world(scene);
  scene.world.worker_count = 2;
  World two = build_world(scene);
  for (int step = 1; step <= 30; ++step) {
    one.step();
    two.step();
    ASSERT_EQ(one.state_hash(), two.state_hash()) << "step " << step;
    ASSERT_EQ(one.body_stopped_events().size(), two.body_stopped_events().size());
  }
}

// Bodies joined to none that diverged move on as if nothing happened: a box dropped onto a
// ground beside the far hinge lands as it does alone, and is never stopped.
TEST(Divergence, OnlyBodiesJoinedToADivergedOneStop) {
  World world = build_world(parse_scene_json(kFarHinge));
  World alone(world.def());
  BodyDef ground_def;
  ground_def.position = Vec2(100, -2);
  BodyId box, lone_box;
  for (auto [w, b] : {std::pair{&world, &box}, std::pair{&alone, &lone_box}}) {
    w->create_shape(w->create_body(ground_def), ShapeDef::box(5, 0.5));
    *b = test::add_box(*w, {100, 0});
  }
  int stopped_steps = 0;
  for (int step = 0; step < 60; ++step) {
    world.step();
    alone.step();
    for (const BodyStoppedEvent& e : world.body_stopped_events()) EXPECT_NE(e.body, box);
    stopped_steps += world.body_stopped_events().empty() ? 0 : 1;
    EXPECT_EQ(world.position(box), alone.position(lone_box)) << "step " << step;
    EXPECT_EQ(world.linear_velocity(box), alone.linear_velocity(lone_box)) << "step " << step;
  }
  EXPECT_GT(stopped_steps, 0);
}

// A step that would carry a body's origin past max_world_coordinate stops it there: before, the
// body went past the limit, and the world's own snapshot was refused.
TEST(Divergence, AStepDoesNotCarryABodyBeyondTheWorld) {
  World world(test::free_world(/*gravity=*/false));
  const Vec2 start(max_world_coordinate - 2, 0);
  const BodyId body = test::add_ball(world, start, 0.5);
  world.set_linear_velocity(body, Vec2(300, 0));  // 5 m per step
  world.step();
  ASSERT_EQ(world.body_stopped_events().size(), 1u);
  EXPECT_TRUE(world.body_stopped_events()[0].diverged);
  EXPECT_EQ(world.position(body), start);
  EXPECT_EQ(world.linear_velocity(body), Vec2(0, 0));
  EXPECT_EQ(World::from_snapshot(world.snapshot()).state_hash(), world.state_hash());
  // Away from the limit it moves on.
  world.set_linear_velocity(body, Vec2(-300, 0));
  world.step();
  EXPECT_TRUE(world.body_stopped_events().empty());
  EXPECT_LT(world.position(body).x(), start.x());
  // A kinematic body, moved by its own velocity, stops at the limit too.
  BodyDef mover;
  mover.type = BodyType::kinematic;
  mover.position = Vec2(0, -(max_world_coordinate - 2));
  mover.linear_velocity = Vec2(0, -300);
  const BodyId kinematic = world.create_body(mover);
  world.create_shape(kinematic, ShapeDef::box(0.5, 0.5));
  world.step();
  ASSERT_EQ(world.body_stopped_events().size(), 1u);
  EXPECT_EQ(world.body_stopped_events()[0].body, kinematic);
  EXPECT_EQ(world.position(kinematic), mover.position);
  EXPECT_EQ(world.linear_velocity(kinematic), Vec2(0, 0));
  EXPECT_EQ(World::from_snapshot(world.snapshot()).state_hash(), world.state_hash());
}

// No ordinary scene's solve is taken for diverged: joint rows may spin a light body well past
// the turn limit for a substep (a lander's leg, 13 times it), never a thousand times.
TEST(Divergence, OrdinaryScenesNeverStop) {
  for (const char* name : {"pyramid", "rain_mixed", "tumbler_400", "shapes", "pendulum", "chain",
                           "bridge", "ragdolls", "car", "newtons_cradle", "joint_grid", "rain"}) {
    SCOPED_TRACE(name);
    SceneRun run(builtin_scene(name));
    const int steps = test::long_run(300, 40);
    for (int step = 0; step < steps; ++step) {
      run.step();
      ASSERT_TRUE(run.world().body_stopped_events().empty()) << "step " << step;
    }
  }
}

}  // namespace
}  // namespace mink
