// Snapshots: a world restored from one continues bitwise as the world it was taken from (on
// every built-in scene, schedules included, at any worker count); bad snapshots are refused
// and leave the world as it was; ids made after a snapshot are stale once it is restored.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "contact.hpp"  // the engine's friction mixing rule
#include "mink/byte_stream.hpp"
#include "mink/engine/scene.hpp"
#include "mink/engine/scene_schedule.hpp"
#include "mink/engine/stale_id_error.hpp"
#include "mink/engine/world.hpp"
#include "test_worlds.hpp"

namespace mink {
namespace {

// A small world with a bit of everything a step keeps: a stack in contact, a pendulum on a
// revolute joint, a sensor, a fast bullet, a body asleep, and a destroyed body (a free slot).
World small_world(int workers = 1) {
  WorldDef def;
  def.worker_count = workers;
  World world(def);
  const BodyId ground = world.create_body({});
  world.create_shape(ground, ShapeDef::box(20, 0.5));
  for (int i = 0; i < 4; ++i) {
    BodyDef box;
    box.type = BodyType::dynamic;
    box.position = Vec2(0.1 * i, 1 + 1.05 * i);
    world.create_shape(world.create_body(box), ShapeDef::box(0.5, 0.5));
  }
  BodyDef bob;
  bob.type = BodyType::dynamic;
  bob.position = Vec2(6, 5);
  const BodyId pendulum = world.create_body(bob);
  world.create_shape(pendulum, ShapeDef::circle(0.3));
  world.create_joint(revolute_joint_at(world, ground, pendulum, Vec2(4, 5)));
  ShapeDef sensor = ShapeDef::box(1, 1, Vec2(-5, 1.5));
  sensor.is_sensor = true;
  world.create_shape(ground, sensor);
  BodyDef bullet;
  bullet.type = BodyType::dynamic;
  bullet.bullet = true;
  bullet.position = Vec2(-5, 8);
  bullet.linear_velocity = Vec2(0, -60);
  world.create_shape(world.create_body(bullet), ShapeDef::circle(0.1));
  BodyDef doomed;
  doomed.type = BodyType::dynamic;
  doomed.position = Vec2(10, 3);
  world.destroy_body(world.create_body(doomed));
  return world;
}

// What a caller sees of a world, to check that a refused restore changed nothing.
struct Seen {
  std::uint64_t hash;
  std::uint64_t steps;
  std::size_t bodies, joints;
  Vec2 position;
  bool operator==(const Seen&) const = default;
};
Seen seen(const World& world) {
  const BodyId first = world.bodies().at(1);
  return {world.state_hash(), world.step_count(), world.body_count(), world.joint_count(),
          world.position(first)};
}

class SnapshotScenes : public testing::TestWithParam<std::string_view> {};

// Run A (at one worker) for a while, snapshot it, and run on recording its state hash; a run
// of the same scene built apart at two workers (so its pool, world number and ids differ)
// restores the snapshot in place and must give the same hash at every checkpoint, the
// schedule resuming with it. A thousand steps where a step is cheap; the big scenes (joint
// grids, drums, the suite's thousands of bodies) a few hundred, which CI can afford, or a
// thousand with MINK_LOCKSTEP_FULL=1 (make lockstep).
TEST_P(SnapshotScenes, RestoredRunsContinueInLockstep) {
  const std::string_view name = GetParam();
  SceneDef scene = builtin_scene(name);
  scene.world.worker_count = 1;
  SceneRun a(scene);
  for (int i = 0; i < test::long_run(37, 3); ++i) a.step();
  const char* full = std::getenv("MINK_LOCKSTEP_FULL");
  const bool cut = full == nullptr || std::string_view(full) != "1";
  const bool big = a.world().body_count() > 400 || a.world().joint_count() > 100;
  const int steps = big && cut ? test::long_run(150, 5) : test::long_run(1000, 10);
  const std::vector<std::uint8_t> snapshot = a.snapshot();
  // A hash costs a snapshot: every 25th step (a difference persists to the end anyway).
  const int stride = 25;
  std::vector<std::uint64_t> hashes;
  for (int i = 1; i <= steps; ++i) {
    a.step();
    if (i % stride == 0 || i == steps) hashes.push_back(a.world().state_hash());
  }
  scene.world.worker_count = 2;
  SceneRun b(scene);
  b.step();  // so that it has something to roll back
  b.restore(snapshot);
  std::size_t k = 0;
  for (int i = 1; i <= steps; ++i) {
    b.step();
    if (i % stride == 0 || i == steps) {
      ASSERT_EQ(b.world().state_hash(), hashes[k++]) << name << " diverged by step " << i;
    }
  }
  EXPECT_EQ(b.world().step_count(), a.world().step_count());
  EXPECT_EQ(test::state_hash(b.world()), test::state_hash(a.world()));
}

INSTANTIATE_TEST_SUITE_P(Builtins, SnapshotScenes, testing::ValuesIn(builtin_scene_names()),
                         [](const auto& info) { return std::string(info.param); });

TEST(Snapshot, RestoringInPlaceRollsTheWorldBackAndItRunsTheSameAgain) {
  SceneRun run(builtin_scene("rain"));  // ragdolls made and destroyed by the schedule
  for (int i = 0; i < 20; ++i) run.step();
  const std::vector<std::uint8_t> snapshot = run.snapshot();
  const std::uint64_t at_snapshot = run.world().state_hash();
  const int steps = test::long_run(60, 20);
  for (int i = 0; i < steps; ++i) run.step();
  const std::uint64_t ahead = run.world().state_hash();
  const std::size_t bodies_ahead = run.world().body_count();
  // Twice: the second restore replaces a restored state (ASan sees anything it leaks).
  for (int again = 0; again < 2; ++again) {
    run.restore(snapshot);
    EXPECT_EQ(run.world().state_hash(), at_snapshot);
    EXPECT_EQ(run.world().step_count(), 20u);
    for (int i = 0; i < steps; ++i) run.step();
    EXPECT_EQ(run.world().state_hash(), ahead);
    EXPECT_EQ(run.world().body_count(), bodies_ahead);
  }
}

TEST(Snapshot, ASnapshotTakenAtTwoWorkersContinuesBitwiseAtOne) {
  SceneDef scene = builtin_scene("ragdolls");
  scene.world.worker_count = 2;
  World two = build_world(scene);
  for (int i = 0; i < 50; ++i) two.step();
  World one = World::from_snapshot(two.snapshot(), 1);
  EXPECT_EQ(one.def().worker_count, 1);
  EXPECT_EQ(two.def().worker_count, 2);
  for (int i = 0; i < test::long_run(300, 30); ++i) {
    two.step();
    one.step();
    ASSERT_EQ(one.state_hash(), two.state_hash()) << "step " << i;
  }
  EXPECT_EQ(test::state_hash(one), test::state_hash(two));
}

TEST(Snapshot, TheHashCoversWhatDecidesLaterSteps) {
  World a = small_world();
  World b = small_world();
  EXPECT_EQ(a.state_hash(), b.state_hash());  // serials differ; the state does not
  EXPECT_NE(a.serial(), b.serial());
  a.step();
  EXPECT_NE(a.state_hash(), b.state_hash());
  b.step();
  EXPECT_EQ(a.state_hash(), b.state_hash());
  // Time banked by advance() decides when the next step runs: it is state.
  a.advance(a.def().time_step * 0.5);
  EXPECT_NE(a.state_hash(), b.state_hash());
  World c = World::from_snapshot(a.snapshot());
  EXPECT_EQ(c.advance(a.def().time_step * 0.6).steps, 1);
  EXPECT_EQ(a.advance(a.def().time_step * 0.6).steps, 1);
  EXPECT_EQ(a.state_hash(), c.state_hash());
}

TEST(Snapshot, AWorldMadeFromOneHasItsOwnIdsForTheSameSlots) {
  World a = small_world();
  for (int i = 0; i < 30; ++i) a.step();
  World b = World::from_snapshot(a.snapshot());
  EXPECT_EQ(b.state_hash(), a.state_hash());
  EXPECT_EQ(b.step_count(), a.step_count());
  ASSERT_EQ(b.bodies().size(), a.bodies().size());
  for (std::size_t i = 0; i < a.bodies().size(); ++i) {
    const BodyId ia = a.bodies()[i], ib = b.bodies()[i];
    EXPECT_EQ(ia.index, ib.index);
    EXPECT_EQ(ia.generation, ib.generation);
    EXPECT_EQ(ib.world, b.serial());
    EXPECT_EQ(b.position(ib), a.position(ia));
    EXPECT_THROW(b.position(ia), StaleIdError);  // an id of the other world
  }
  // Joint definitions name their bodies with the new world's ids.
  const JointId joint = b.joints().at(0);
  EXPECT_EQ(joint_base(b.joint_def(joint)).body_a.world, b.serial());
  // A free slot is reused as it would have been in the original world.
  BodyDef def;
  def.type = BodyType::dynamic;
  const BodyId made_a = a.create_body(def), made_b = b.create_body(def);
  EXPECT_EQ(made_a.index, made_b.index);
  EXPECT_EQ(made_a.generation, made_b.generation);
}

TEST(Snapshot, IdsMadeAfterTheSnapshotAreStaleOnceItIsRestored) {
  World world = small_world();
  const std::vector<BodyId> before = world.bodies();
  const JointId joint = world.joints().at(0);
  for (int i = 0; i < 10; ++i) world.step();
  const std::vector<std::uint8_t> snapshot = world.snapshot();
  BodyDef def;
  def.type = BodyType::dynamic;
  def.position = Vec2(30, 3);
  const BodyId later = world.create_body(def);
  const ShapeId later_shape = world.create_shape(later, ShapeDef::circle(0.5));
  const JointId later_joint =
      world.create_joint(revolute_joint_at(world, before[0], later, {30, 3}));
  world.destroy_joint(joint);
  for (int i = 0; i < 10; ++i) world.step();
  world.restore(snapshot);
  EXPECT_FALSE(world.is_valid(later));
  EXPECT_FALSE(world.is_valid(later_shape));
  EXPECT_FALSE(world.is_valid(later_joint));
  EXPECT_THROW(world.position(later), StaleIdError);
  EXPECT_THROW(world.shape_body(later_shape), StaleIdError);
  EXPECT_THROW(world.joint_type(later_joint), StaleIdError);
  // Ids from before the snapshot name their objects again, the destroyed joint included.
  EXPECT_EQ(world.bodies(), before);
  EXPECT_TRUE(world.is_valid(joint));
  EXPECT_EQ(world.joint_type(joint), JointType::revolute);
  EXPECT_EQ(world.step_count(), 10u);
  EXPECT_TRUE(world.contact_begin_events().empty());
}

// The broadphase, rebuilt when a step brings many new shapes, kept the slots of shapes destroyed
// in the same step, and with nothing left alive its band starts, pointing into its old arrays:
// harmless to a step, but the snapshot's loader checks them and refused the world's own
// snapshot (found by the World API fuzzer's snapshot step). Both cases now restore: 30 of 40
// boxes destroyed and 15 made, and all 40 destroyed with 11 made and destroyed before a step.
TEST(Snapshot, AWorldRebuiltAfterDestroyingShapesRestores) {
  for (const bool none_left : {false, true}) {
    World world;
    std::vector<BodyId> boxes;
    for (int i = 0; i < 40; ++i) boxes.push_back(test::add_box(world, {1.5 * i, 0.5 * i}));
    world.step();
    for (int i = none_left ? 0 : 10; i < 40; ++i) {
      world.destroy_body(boxes[static_cast<std::size_t>(i)]);
    }
    for (int i = 0; i < (none_left ? 11 : 15); ++i) {
      const BodyId box = test::add_box(world, {1.5 * i, 30});
      if (none_left) world.destroy_body(box);
    }
    world.step();
    const std::vector<std::uint8_t> bytes = world.snapshot();
    World copy = World::from_snapshot(bytes);
    EXPECT_EQ(copy.state_hash(), world.state_hash()) << none_left;
    EXPECT_EQ(copy.snapshot(), bytes) << none_left;
    world.restore(bytes);
    for (int i = 0; i < 10; ++i) {
      copy.step();
      world.step();
    }
    EXPECT_EQ(copy.state_hash(), world.state_hash()) << none_left;
  }
}

TEST(Snapshot, EveryTruncationIsRefusedAndLeavesTheWorldAsItWas) {
  World source = small_world();
  for (int i = 0; i < 25; ++i) source.step();
  const std::vector<std::uint8_t> snapshot = source.snapshot();
  World world = small_world();
  for (int i = 0; i < 7; ++i) world.step();
  const Seen unchanged = seen(world);
  const std::span<const std::uint8_t> bytes(snapshot);
  for (std::size_t length = 0; length < bytes.size(); ++length) {
    EXPECT_THROW(world.restore(bytes.first(length)), SnapshotError) << "length " << length;
  }
  std::vector<std::uint8_t> longer = snapshot;
  longer.push_back(0);
  EXPECT_THROW(world.restore(longer), SnapshotError);
  EXPECT_EQ(seen(world), unchanged);
  try {
    world.restore(bytes.first(bytes.size() - 1));
    FAIL() << "a truncated snapshot was accepted";
  } catch (const SnapshotError& e) {
    EXPECT_NE(std::string(e.what()).find("truncated at byte " + std::to_string(bytes.size() - 1)),
              std::string::npos)
        << e.what();
  }
  world.restore(snapshot);
  EXPECT_EQ(world.state_hash(), source.state_hash());
}

TEST(Snapshot, FlippedBitsAreRefusedAndLeaveTheWorldAsItWas) {
  World source = small_world();
  for (int i = 0; i < 25; ++i) source.step();
  const std::vector<std::uint8_t> snapshot = source.snapshot();
  World world = small_world();
  const Seen unchanged = seen(world);
  std::mt19937_64 random(20261126);
  std::uniform_int_distribution<std::size_t> byte(0, snapshot.size() - 1);
  std::uniform_int_distribution<int> bit(0, 7);
  for (int trial = 0; trial < test::long_run(2000, 300); ++trial) {
    std::vector<std::uint8_t> corrupt = snapshot;
    const std::size_t at = byte(random);
    corrupt[at] ^= static_cast<std::uint8_t>(1u << bit(random));
    if (trial % 3 == 0) corrupt[byte(random)] ^= 0xff;  // sometimes a second byte
    EXPECT_THROW(world.restore(corrupt), SnapshotError) << "byte " << at;
  }
  EXPECT_EQ(seen(world), unchanged);
}

TEST(Snapshot, ErrorsNameWhatIsWrong) {
  World world = small_world();
  const std::vector<std::uint8_t> snapshot = world.snapshot();
  const auto message = [&](const std::vector<std::uint8_t>& bytes) {
    return test::error_of<SnapshotError>([&] { world.restore(bytes); });
  };
  std::vector<std::uint8_t> bytes = snapshot;
  bytes[0] = 'X';
  EXPECT_NE(message(bytes).find("not a Minkowski snapshot"), std::string::npos);
  bytes = snapshot;
  bytes[8] += 1;  // the format version
  EXPECT_NE(message(bytes).find("format version " + std::to_string(snapshot[8] + 1)),
            std::string::npos)
      << message(bytes);
  bytes = snapshot;
  bytes[12] ^= 1;  // the build fingerprint
  EXPECT_NE(message(bytes).find("another build"), std::string::npos) << message(bytes);
  bytes = snapshot;
  bytes[bytes.size() / 2] ^= 4;
  EXPECT_NE(message(bytes).find("checksum"), std::string::npos) << message(bytes);
  // Bytes that pass the checksum but do not describe a state: a body's contact list that runs
  // past the end.
  bytes = snapshot;
  bytes.erase(bytes.end() - 3, bytes.end());
  EXPECT_NE(message(test::resealed(bytes)).find("at byte"), std::string::npos) << message(bytes);
}

// A box on a ground whose friction, kGroundFriction, is a value found once in a snapshot's
// bytes; stepped once, so they touch.
constexpr Real kGroundFriction = 0.123456789;
void add_box_on_ground(World& world) {
  const BodyId ground = world.create_body({});
  ShapeDef ground_box = ShapeDef::box(20, 0.5);
  ground_box.friction = kGroundFriction;
  world.create_shape(ground, ground_box);
  test::add_box(world, {0, 1});
  world.step();
}

// A state that passes its checksum is still refused when it holds a value the API refuses:
// such values stepped into NaN (a gravity of 1e175 m/s^2 did within a step).
TEST(Snapshot, ValuesTheApiRefusesAreRefusedBehindAValidChecksum) {
  WorldDef def;
  def.gravity = Vec2(0, -9.87654321);
  World world(def);
  add_box_on_ground(world);
  const std::vector<std::uint8_t> snapshot = world.snapshot();
  const std::uint64_t unchanged = world.state_hash();
  // The snapshot with the one occurrence of `was` replaced by `now`, resealed.
  const auto replaced = [&](Real was, Real now) {
    std::vector<std::uint8_t> bytes = snapshot;
    std::uint8_t pattern[sizeof(Real)];
    std::memcpy(pattern, &was, sizeof was);
    const auto at = std::search(bytes.begin() + 36, bytes.end(), pattern, pattern + sizeof was);
    EXPECT_NE(at, bytes.end()) << was;
    EXPECT_EQ(std::search(at + 1, bytes.end(), pattern, pattern + sizeof was), bytes.end()) << was;
    std::memcpy(&*at, &now, sizeof now);
    return test::resealed(std::move(bytes));
  };
  const auto message = [&](Real was, Real now) {
    return test::error_of<SnapshotError>([&] { world.restore(replaced(was, now)); });
  };
  EXPECT_NE(message(-9.87654321, 1e175).find("gravity"), std::string::npos);
  EXPECT_NE(message(kGroundFriction, -0.5).find("friction"), std::string::npos);
  EXPECT_NE(message(kGroundFriction, std::numeric_limits<Real>::quiet_NaN()).find("non-finite"),
            std::string::npos);
  EXPECT_EQ(world.state_hash(), unchanged);
  // A world that never stepped (its broadphase never built) restores too.
  EXPECT_NO_THROW((void)World::from_snapshot(World().snapshot()));
  // The same bytes with in-range values are taken.
  world.restore(replaced(kGroundFriction, 0.25));
  world.step();
  EXPECT_TRUE(test::all_finite(world));
}

// A contact behind a valid checksum whose proxies are not its shapes' own, or that misstates
// which of its bodies are fixed, is refused: the step finds contacts by their proxies and links
// islands by those flags without looking at the bodies again.
TEST(Snapshot, AContactThatMisnamesItsProxiesOrBodiesIsRefused) {
  World world;
  add_box_on_ground(world);
  ASSERT_EQ(world.counters().contacts, 1u);
  const std::vector<std::uint8_t> snapshot = world.snapshot();
  const std::uint64_t unchanged = world.state_hash();
  // The contact's record: its friction (the shapes' mixed), restitution, shape and proxy
  // indices, four flags, approach speed and point, colour, then its fixed flags.
  // Materials are kept in the solver's precision.
  const auto friction =
      static_cast<detail::SolverReal>(detail::mix_friction(kGroundFriction, ShapeDef{}.friction));
  std::uint8_t pattern[sizeof friction];
  std::memcpy(pattern, &friction, sizeof friction);
  const auto at =
      std::search(snapshot.begin() + 36, snapshot.end(), pattern, pattern + sizeof friction);
  ASSERT_NE(at, snapshot.end());
  const auto proxies =
      static_cast<std::size_t>(at - snapshot.begin()) + 2 * sizeof friction + 4 + 4;
  const std::size_t a_fixed = proxies + 8 + 4 + 8 + 16 + 1;
  const auto restored = [&](std::size_t offset, std::uint8_t value) {
    std::vector<std::uint8_t> bytes = snapshot;
    bytes[offset] = value;
    return test::error_of<SnapshotError>([&] { world.restore(test::resealed(bytes)); });
  };
  std::uint32_t proxy_a = 0;
  std::memcpy(&proxy_a, snapshot.data() + proxies, sizeof proxy_a);
  EXPECT_NE(restored(proxies, static_cast<std::uint8_t>(proxy_a + 1)).find("proxies"),
            std::string::npos);
  ASSERT_LE(snapshot[a_fixed], 1);
  EXPECT_NE(restored(a_fixed, snapshot[a_fixed] ^ 1).find("contact"), std::string::npos);
  EXPECT_EQ(world.state_hash(), unchanged);
}

TEST(Snapshot, ARunSnapshotCarriesTheSchedule) {
  // A scheduled scene's run snapshot holds the schedule's state: restored into a run that has
  // dropped nothing yet, it drops the next column where the original does, not the first.
  SceneRun a(builtin_scene("rain"));
  for (int i = 0; i < test::long_run(60, 9); ++i) a.step();
  const std::vector<std::uint8_t> snapshot = a.snapshot();
  SceneRun b(builtin_scene("rain"));
  b.restore(snapshot);
  for (int i = 0; i < 16; ++i) {
    a.step();
    b.step();
  }
  EXPECT_EQ(a.world().body_count(), b.world().body_count());
  EXPECT_EQ(a.world().state_hash(), b.world().state_hash());
  // A world snapshot is not a run snapshot: refused, the run unchanged.
  const std::uint64_t hash = b.world().state_hash();
  EXPECT_THROW(b.restore(b.world().snapshot()), SnapshotError);
  EXPECT_EQ(b.world().state_hash(), hash);
}

}  // namespace
}  // namespace mink
