#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <random>
#include <utility>
#include <variant>
#include <vector>

#include "contact_kernels.hpp"
#include "mink/engine/scene.hpp"
#include "run_counts.hpp"
#include "test_worlds.hpp"

namespace mink {
namespace {

// A busy scene: random hulls of 3..64 vertices raining into a box, 300 steps, some of them
// destroyed and replaced on the way, sleeping on.
std::uint64_t run_busy_scene(bool simd_solver) {
  SceneDef scene = rain_scene(150, 11);
  scene.world.simd_solver = simd_solver;
  World world = build_world(scene);
  const std::vector<BodyId> bodies = world.bodies();
  for (int i = 0; i < 300; ++i) {
    if (i == 100) world.destroy_body(bodies[40]);
    if (i == 150) {
      BodyDef def;
      def.type = BodyType::dynamic;
      def.position = Vec2(0, 30);
      world.create_shape(world.create_body(def), ShapeDef::regular_polygon(7, 0.6));
    }
    world.step();
  }
  return test::state_hash(world);
}

// Recorded from this test's own run. Any change to the solver, the narrowphase, the
// broadphase pair order or the scenes changes it: re-record it then (the test prints the new
// value), after checking the behaviour tests still pass. Last re-recorded when the solver
// went to single precision (eight SIMD lanes, constraints built in it too) and manifolds were
// kept over Box2D v3's contact recycling distance, and the broadphase took Box2D v3's margins;
// again when friction moved to the relax pass, and when positions moved onto the grid
// (position_grid_step) and contacts came to be measured from their first body's origin.
constexpr std::uint64_t kGoldenHash = 0xa289b1e8271e3bf2ull;

TEST(Determinism, BusySceneIsBitwiseIdenticalRunAfterRun) {
  const std::uint64_t first = run_busy_scene(true);
  const std::uint64_t second = run_busy_scene(true);
  EXPECT_EQ(first, second);
  std::printf("busy scene hash: 0x%016llx\n", static_cast<unsigned long long>(first));
  EXPECT_EQ(first, kGoldenHash) << "re-record kGoldenHash if the solver changed on purpose";
}

// The SIMD solver and its one-constraint-at-a-time twin take the same steps in the same
// order: bitwise equal states.
TEST(Determinism, SimdSolverMatchesItsScalarTwinBitForBit) {
  EXPECT_EQ(run_busy_scene(true), run_busy_scene(false));
}

TEST(Determinism, LargeStackSimdMatchesScalarTwin) {
  const auto [wide, scalar] =
      test::stepped_twins(20, 120, [](WorldDef& def) { def.simd_solver = false; });
  EXPECT_EQ(test::state_hash(wide), test::state_hash(scalar));
}

// Lanes sharing a kinematic body (tumbler_400's drum, made kinematic again, touches many boxes
// in one colour) leave its velocity alone: still bitwise equal to the twin.
TEST(Determinism, KinematicSharedAcrossLanesMatchesScalarTwin) {
  SceneDef scene = builtin_scene("tumbler_400");
  ASSERT_EQ(scene.joints.size(), 1u);
  BodyDef& drum = scene.bodies[scene.joints[0].body_b].body;
  drum.type = BodyType::kinematic;
  drum.angular_velocity = 0.25;
  scene.joints.clear();
  World wide = build_world(scene);
  scene.world.simd_solver = false;
  World scalar = build_world(scene);
  for (int i = 0; i < 150; ++i) {
    wide.step();
    scalar.step();
  }
  EXPECT_EQ(wide.counters().overflow_constraints, 0u);
  EXPECT_EQ(test::state_hash(wide), test::state_hash(scalar));
}

// Box2D v3's joint grid at `workers`, and a twin of it changed by `change`, stepped alike;
// expects the grid to be falling and swinging by then.
template <typename Change>
std::pair<World, World> joint_grid_twins(int workers, Change change) {
#ifdef MINK_SANITIZED_BUILD
  constexpr int kSteps = 8;
#else
  constexpr int kSteps = 40;
#endif
  SceneDef scene = builtin_scene("joint_grid");
  scene.world.worker_count = workers;
  World first = build_world(scene);
  change(scene);
  World second = build_world(scene);
  for (int i = 0; i < kSteps; ++i) {
    first.step();
    second.step();
  }
  const std::vector<BodyId> bodies = first.bodies();
  std::size_t moved = 0;
  for (const BodyId body : bodies) moved += first.linear_velocity(body).norm() > 0.1 ? 1 : 0;
  EXPECT_GT(moved, bodies.size() / 2) << "the net is meant to be falling and swinging";
  return {std::move(first), std::move(second)};
}

// A revolute joint that is only its point row is solved from a pin row (68 bytes, prepared
// outside its record, eight at a time in SIMD lanes); the same joint with a limit too wide
// ever to be reached goes through a revolute row instead, whose limit rows never push: the
// bodies move alike, bit for bit, at one worker and at two (Box2D v3's joint grid). Either
// row's copy of a joint going wrong, or its impulses not coming back, parts them.
TEST(Determinism, PinRowsMatchRevoluteRows) {
  for (const int workers : {1, 2}) {
    const auto [pins, rows] = joint_grid_twins(workers, [](SceneDef& scene) {
      for (SceneJoint& joint : scene.joints) {
        std::get<RevoluteJointDef>(joint.def).limit = {true, -1e6, 1e6};
      }
    });
    const std::vector<BodyId> a = pins.bodies(), b = rows.bodies();
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      ASSERT_EQ(pins.position(a[i]), rows.position(b[i])) << "body " << i;
      ASSERT_EQ(pins.angle(a[i]), rows.angle(b[i])) << "body " << i;
      ASSERT_EQ(pins.linear_velocity(a[i]), rows.linear_velocity(b[i])) << "body " << i;
      ASSERT_EQ(pins.angular_velocity(a[i]), rows.angular_velocity(b[i])) << "body " << i;
    }
  }
}

// The pins of a colour eight at a time in SIMD lanes (the last batch of a colour part full)
// and one at a time in the scalar twin: bitwise equal, at one worker and at two.
TEST(Determinism, WidePinsMatchTheirScalarTwin) {
  for (const int workers : {1, 2}) {
    const auto [wide, scalar] =
        joint_grid_twins(workers, [](SceneDef& scene) { scene.world.simd_solver = false; });
    EXPECT_EQ(test::state_hash(wide), test::state_hash(scalar)) << workers << " workers";
  }
}

// The revolute rows of a colour eight at a time in SIMD lanes, those with their point row and
// those whose chain solves it (a ragdoll's limbs), against one at a time in the scalar twin:
// bitwise equal, at one worker and at two. The ragdolls' joints have their spring, motor or
// limit switched off in turn, so lanes with a row off sit beside lanes with it on.
TEST(Determinism, WideRevoluteRowsMatchTheirScalarTwin) {
#ifdef MINK_SANITIZED_BUILD
  constexpr int kSteps = 40;
#else
  constexpr int kSteps = 150;
#endif
  SceneDef scene = builtin_scene("ragdolls");
  for (std::size_t j = 0; j < scene.joints.size(); ++j) {
    auto& def = std::get<RevoluteJointDef>(scene.joints[j].def);
    def.spring.enabled = j % 3 != 0;
    def.motor.enabled = j % 3 != 1;
    def.limit.enabled = j % 4 != 2;
  }
  for (const int workers : {1, 2}) {
    scene.world.worker_count = workers;
    scene.world.simd_solver = true;
    World wide = build_world(scene);
    scene.world.simd_solver = false;
    World scalar = build_world(scene);
    for (int i = 0; i < kSteps; ++i) {
      wide.step();
      scalar.step();
    }
    std::size_t moved = 0;
    for (const BodyId body : wide.bodies()) moved += wide.linear_velocity(body).norm() > 0.1;
    EXPECT_GT(moved, 20u) << "the ragdolls are meant to be falling";
    EXPECT_EQ(test::state_hash(wide), test::state_hash(scalar)) << workers << " workers";
  }
}

// The counting sort split into runs (the constraints' order by first body and by colour) against
// a stable sort of the whole: the same order for 1 to 8 runs, over random bucket lists with
// empty buckets, empty runs and more runs than items.
TEST(Determinism, CountingSortInRunsMatchesAStableSort) {
  std::mt19937 random(11);
  for (int trial = 0; trial < 300; ++trial) {
    const std::size_t buckets = 1 + random() % 40;
    const std::size_t items = random() % 200;
    std::vector<std::uint32_t> bucket_of(items);
    for (std::uint32_t& b : bucket_of) b = static_cast<std::uint32_t>(random() % buckets);
    std::vector<std::uint32_t> expected(items);
    for (std::uint32_t i = 0; i < items; ++i) expected[i] = i;
    std::stable_sort(expected.begin(), expected.end(),
                     [&](std::uint32_t x, std::uint32_t y) { return bucket_of[x] < bucket_of[y]; });
    for (std::uint32_t runs = 1; runs <= 8; ++runs) {
      std::vector<std::uint32_t> counts(runs * buckets, 0);
      for (std::uint32_t run = 0; run < runs; ++run) {
        for (std::size_t i = detail::run_begin(items, run, runs);
             i < detail::run_begin(items, run + 1, runs); ++i) {
          ++counts[run * buckets + bucket_of[i]];
        }
      }
      ASSERT_EQ(detail::place_runs(counts, runs, buckets, buckets), items);
      std::vector<std::uint32_t> placed(items, ~0u);
      // The runs place their items in reverse order of runs: each run's places are its own.
      for (std::uint32_t run = runs; run-- > 0;) {
        for (std::size_t i = detail::run_begin(items, run, runs);
             i < detail::run_begin(items, run + 1, runs); ++i) {
          placed[counts[run * buckets + bucket_of[i]]++] = static_cast<std::uint32_t>(i);
        }
      }
      ASSERT_EQ(placed, expected) << "runs " << runs << ", trial " << trial;
    }
  }
}

// The points' masses and base separations of a SIMD batch, worked out for all eight lanes at
// once, against the one-at-a-time twin on each lane: bitwise equal, over random constraints
// with one and two points, fixed bodies (zero masses) and lanes left empty.
TEST(Determinism, BatchPointMassesMatchTheirScalarTwin) {
  using detail::ContactConstraint;
  using detail::kWideLanes;
  using detail::SolverReal;
  std::mt19937 rng(7);
  std::uniform_real_distribution<SolverReal> unit(-1, 1), mass(0, 2);
  const auto same_bits = [](SolverReal x, SolverReal y) {
    return std::memcmp(&x, &y, sizeof x) == 0;
  };
  int compared = 0;
  for (int round = 0; round < 2000; ++round) {
    detail::WideConstraint wide{};
    ContactConstraint scalar[kWideLanes];
    std::uint32_t two_points = 0;
    const int used = 1 + round % kWideLanes;
    for (int lane = 0; lane < used; ++lane) {
      ContactConstraint& c = scalar[lane];
      c = ContactConstraint{};
      const SolverReal angle = 3.2f * unit(rng);
      c.nx = std::cos(angle);
      c.ny = std::sin(angle);
      // A fixed body now and then: no mass on that side.
      c.inv_mass_a = rng() % 4 == 0 ? 0 : mass(rng);
      c.inv_inertia_a = c.inv_mass_a == 0 ? 0 : mass(rng);
      c.inv_mass_b = rng() % 4 == 1 ? 0 : mass(rng);
      c.inv_inertia_b = c.inv_mass_b == 0 ? 0 : mass(rng);
      c.dx = unit(rng);
      c.dy = unit(rng);
      c.point_count = 1 + static_cast<int>(rng() % 2);
      for (int j = 0; j < c.point_count; ++j) {
        c.points[j].ax = unit(rng);
        c.points[j].ay = unit(rng);
        c.points[j].bx = c.points[j].ax + c.dx;
        c.points[j].by = c.points[j].ay + c.dy;
        c.points[j].base_separation = 0.05f * unit(rng);  // the separation, until finished
        c.points[j].normal_impulse = mass(rng);
      }
      if (c.point_count == 2) two_points |= 1u << lane;
      detail::pack(wide, lane, c);
      detail::finish_points(c);
    }
    detail::finish_points_wide(wide, two_points);
    for (int lane = 0; lane < used; ++lane) {
      const ContactConstraint lanes = detail::unpack(wide, lane);
      for (int j = 0; j < 2; ++j) {
        const auto& want = scalar[lane].points[j];
        const auto& got = lanes.points[j];
        EXPECT_TRUE(same_bits(got.base_separation, want.base_separation) &&
                    same_bits(got.normal_mass, want.normal_mass) &&
                    same_bits(got.tangent_mass, want.tangent_mass))
            << "round " << round << " lane " << lane << " point " << j;
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 10000);
}

// A SIMD batch built whole from its lanes' seeds against the way of its twins: each lane's
// constraint built one at a time, packed, the points' masses worked out for the batch, the lanes
// past the batch packed as padding. Bitwise equal, over random seeds of one and two points,
// sides without mass, both softnesses and part-full batches.
TEST(Determinism, BatchBuiltFromSeedsMatchesPackedConstraints) {
  using detail::ContactConstraint;
  using detail::kWideLanes;
  using detail::SolverReal;
  std::mt19937 rng(19);
  std::uniform_real_distribution<SolverReal> unit(-1, 1), mass(0, 2);
  const detail::Softness soft = detail::make_softness(30, 10, 1.0 / 240);
  const detail::Softness fixed_soft = detail::make_softness(60, 10, 1.0 / 240);
  constexpr std::int32_t padding_body = 99;
  int differing = 0;
  for (int round = 0; round < 3000; ++round) {
    const int count = 1 + round % kWideLanes;
    detail::ContactSeed seeds[kWideLanes];
    detail::BatchLane lanes[kWideLanes];
    std::uint32_t two_points = 0;
    detail::WideConstraint expected{}, built{};
    for (int lane = 0; lane < count; ++lane) {
      detail::ContactSeed& seed = seeds[lane];
      const SolverReal angle = 3.2f * unit(rng);
      seed = {std::cos(angle), std::sin(angle), unit(rng), unit(rng), mass(rng), 0, {}};
      const int points = 1 + static_cast<int>(rng() % 2);
      for (int j = 0; j < points; ++j) {
        seed.points[j] = {unit(rng), unit(rng), 0.05f * unit(rng), mass(rng), unit(rng)};
      }
      if (points == 2) two_points |= 1u << lane;
      detail::BatchLane& in = lanes[lane];
      in = {&seed, lane, lane + kWideLanes, 0, 0, 0, 0, {0, 0}};
      if (rng() % 4 != 0) {
        in.inv_mass_a = mass(rng);
        in.inv_inertia_a = mass(rng);
      }
      if (rng() % 4 != 1) {
        in.inv_mass_b = mass(rng);
        in.inv_inertia_b = mass(rng);
      }
      // The one-at-a-time build of the set-up, less the masses it leaves to the batch.
      ContactConstraint c{};
      c.body_a = in.body_a;
      c.body_b = in.body_b;
      c.inv_mass_a = in.inv_mass_a;
      c.inv_inertia_a = in.inv_inertia_a;
      c.inv_mass_b = in.inv_mass_b;
      c.inv_inertia_b = in.inv_inertia_b;
      c.nx = seed.nx;
      c.ny = seed.ny;
      c.dx = seed.dx;
      c.dy = seed.dy;
      c.friction = seed.friction;
      const detail::Softness& s = (c.inv_mass_a == 0 || c.inv_mass_b == 0) ? fixed_soft : soft;
      c.bias_rate = static_cast<SolverReal>(s.bias_rate);
      c.mass_scale = static_cast<SolverReal>(s.mass_scale);
      c.impulse_scale = static_cast<SolverReal>(s.impulse_scale);
      c.point_count = points;
      for (int j = 0; j < points; ++j) {
        c.points[j].ax = seed.points[j].ax;
        c.points[j].ay = seed.points[j].ay;
        c.points[j].base_separation = seed.points[j].separation;
        c.points[j].normal_impulse = seed.points[j].normal_impulse;
        c.points[j].tangent_impulse = seed.points[j].tangent_impulse;
      }
      detail::pack(expected, lane, c);
    }
    detail::finish_points_wide(expected, two_points);
    ContactConstraint padding{};
    padding.body_a = padding.body_b = padding_body;
    padding.nx = 1;
    padding.mass_scale = 1;
    for (int lane = count; lane < kWideLanes; ++lane) detail::pack(expected, lane, padding);
    detail::build_wide(built, lanes, count, two_points, padding_body, soft, fixed_soft);
    if (std::memcmp(&expected, &built, sizeof built) != 0) ++differing;
  }
  EXPECT_EQ(differing, 0);
}

}  // namespace
}  // namespace mink
