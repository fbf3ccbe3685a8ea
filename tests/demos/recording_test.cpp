// Recordings of sandbox-style runs: a scripted drag with a motor joint, a dropped hull, an
// impulse and a rollback, all through the World calls the sandbox makes, replay with equal
// hashes; a tampered call is caught at the first step it changes.

#include <gtest/gtest.h>

#include <filesystem>
#include <vector>

#include "cli_test_support.hpp"
#include "mink/engine/scene.hpp"
#include "mink/engine/scene_schedule.hpp"
#include "recording.hpp"

namespace {

using namespace mink;
using namespace mink::cli;

// 90 steps of ragdolls with the sandbox's actions scripted: a body dragged by a motor joint
// from step 10 to 60, a hull dropped at step 30, an impulse at 70, and at step 80 a rollback
// to the snapshot kept at step 75 (the sandbox's step back), after which the run goes on.
Recording scripted_run(std::size_t& target_call) {
  SceneRun run(builtin_scene("ragdolls"));
  World& world = run.world();
  RunRecorder recorder(world);
  const BodyId anchor = world.create_body({});
  BodyId dragged;
  for (const BodyId id : world.bodies()) {
    if (world.body_type(id) == BodyType::dynamic) dragged = id;
  }
  JointId drag;
  std::vector<std::uint8_t> kept;
  target_call = 0;
  for (int step = 0; step < 90; ++step) {
    if (step == 10) {
      MotorJointDef motor;
      motor.body_a = anchor;
      motor.body_b = dragged;
      motor.linear_offset = world.position(dragged);
      motor.max_force = 1000 * world.mass(dragged);
      motor.max_torque = 0;
      drag = world.create_joint(motor);
    }
    if (step >= 10 && step < 60) {
      world.set_motor_target(drag, world.position(dragged) + Vec2(0.05, 0.08), 0);
      if (step == 20) target_call = recorder.recording().entries.size() - 1;
    }
    if (step == 60) world.destroy_joint(drag);
    if (step == 30) {
      BodyDef hull;
      hull.type = BodyType::dynamic;
      hull.position = Vec2(1, 12);
      world.create_shape(world.create_body(hull), ShapeDef::regular_polygon(6, 0.6));
    }
    if (step == 70) world.apply_linear_impulse(dragged, Vec2(3, 5), world.world_center(dragged));
    if (step == 75) kept = world.snapshot();
    if (step == 80) world.restore(kept);
    run.step();
  }
  EXPECT_EQ(world.step_count(), 85u);  // rolled back five steps at step 80
  EXPECT_EQ(recorder.steps(), 90u);
  return recorder.recording();
}

TEST(Recording, AScriptedSandboxRunReplaysWithEqualHashes) {
  std::size_t target_call = 0;
  const Recording recording = scripted_run(target_call);
  const auto file = mink_test::fresh_dir("recording") / "sandbox.rec";
  save_recording(file, recording);
  const Recording loaded = load_recording(file);
  ASSERT_EQ(loaded.entries.size(), recording.entries.size());
  for (const int workers : {1, 2}) {
    const ReplayResult result = replay(loaded, workers);
    EXPECT_FALSE(result.diverged_at.has_value()) << "at step " << *result.diverged_at;
    EXPECT_EQ(result.steps, 90u);
  }
}

TEST(Recording, ATamperedCallIsNamedAtTheFirstStepItChanges) {
  std::size_t target_call = 0;
  Recording recording = scripted_run(target_call);
  Recording::Entry& call = recording.entries.at(target_call);
  ASSERT_FALSE(call.is_step);
  // A byte of the motor target's x: the call ends with x, y and the angle, 8 bytes each.
  call.call.at(call.call.size() - 20) ^= 0x40;
  const ReplayResult result = replay(recording, 1);
  ASSERT_TRUE(result.diverged_at.has_value());
  EXPECT_EQ(*result.diverged_at, 21u);  // the step run right after the call at step 20
  EXPECT_EQ(result.steps, 20u);
  EXPECT_NE(result.recorded_hash, result.replayed_hash);
}

TEST(Recording, ARecordingCutShortIsRefused) {
  std::size_t target_call = 0;
  const auto file = mink_test::fresh_dir("recording_cut") / "cut.rec";
  save_recording(file, scripted_run(target_call));
  std::filesystem::resize_file(file, std::filesystem::file_size(file) - 1);
  EXPECT_THROW(load_recording(file), SnapshotError);
}

}  // namespace
