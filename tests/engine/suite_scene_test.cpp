// Box2D v3's benchmark suite as built-ins: the same counts as Box2D v3 at the end of its
// benchmark app's run, and a simulation that touches about as much as Box2D v3's.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "mink/engine/scene.hpp"
#include "test_worlds.hpp"

namespace mink {
namespace {

// Box2D v3 (617d32ab) running each scene as its benchmark app does (benchmark/main.c: the
// scene's step function, then b2World_Step at 1/60 s with 4 substeps, one worker, for the
// app's step count): b2World_GetCounters at the end (bodyCount, shapeCount, jointCount), and
// the contacts touching after every 50th step (contacts whose manifold has points, read from
// its contact flags by a program stepping the scene the same way).
//
// Its counters' contactCount, the pairs whose fattened boxes overlap, follows the piles' shape
// at the end of a long run: the full-length runs compare it (our boxes are fattened as Box2D
// v3's are), as bench/run_step.sh does. The touching contacts are what the scenes' simulation
// decides, over short runs too.
struct Box2dV3Run {
  std::string_view name;
  std::size_t bodies, shapes, joints;
  std::size_t contacts;  // contactCount at the end of the run (bench/results/step_v3_counts.csv)
  std::vector<std::size_t> touching;  // after steps 50, 100, ..., to the end of the run
  // The shortened run that `make test` compares. Where a scene starts with bodies falling
  // (rain's first ragdolls land near step 200), it runs past the first landings: the count
  // at the first checkpoint after them swings by tens of percent with a step's difference in
  // when they land.
  int short_steps;
  std::string_view mismatch;  // why the short run is skipped (empty: it is not)
};

const std::vector<Box2dV3Run>& box2d_v3_runs() {
  // clang-format off
  static const std::vector<Box2dV3Run> runs = {
      {"compounds", 3001, 6282, 0, 26221,
       {2850, 3293, 4109, 5051, 6384, 8318, 10642, 13303, 14473, 12161}, 200, ""},
      {"joint_grid", 10000, 10000, 19800, 0, {0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, 50, ""},
      {"junkyard", 8002, 8262, 0, 24341,
       {0, 133, 10261, 16528, 14326, 16274, 16356, 16647, 16699, 16785, 16662, 16397, 16368,
        16418, 16538, 16526}, 200, ""},
      {"large_pyramid", 5051, 5051, 0, 14950,
       {14950, 14950, 14950, 14950, 14950, 14950, 14950, 14950, 14950, 14950}, 100, ""},
      {"many_pyramids", 22001, 22020, 0, 58000, {58000, 58000, 58000, 58000}, 50, ""},
      {"rain", 11001, 15505, 10000, 20651,
       {0, 0, 0, 1052, 4141, 7481, 8599, 8418, 7898, 7955, 8191, 8342, 7830, 8085, 8287, 8106,
        7842, 7942, 8029, 8336}, 300,
       "our ragdoll piles keep 7-15% more contacts touching than Box2D v3's once they have landed "
       "(steps 250 to 500: 4534, 8173, 9232, 9274, 8874, 9090 against 4141, 7481, 8599, 8418, "
       "7898, 7955; with fast bodies' boxes bare as Box2D v3's, 2-5% more than with their "
       "margin)"},
      {"smash", 9601, 9601, 0, 6296, {0, 15771, 16141, 4280, 2559, 1893}, 100,
       "the block smashes through the wall of sleeping boxes as in Box2D v3, but at step 100 ours "
       "keeps 5.7% more contacts touching (0.2% more over its 300 steps)"},
      {"spinner", 6078, 6437, 1, 23049,
       {13914, 13261, 14009, 15037, 15666, 15993, 15635, 15958, 16445, 16116}, 100, ""},
      {"tumbler", 2027, 2029, 1, 8823,
       {1356, 5017, 5216, 5224, 4945, 4142, 3719, 4187, 3918, 4028, 4073, 4171, 4194, 3925, 4075},
       200, ""},
      {"washer", 8102, 8140, 0, 29669,
       {31160, 30240, 24806, 23175, 22177, 20554, 18616, 16974, 18795, 19359}, 50, ""},
  };
  // clang-format on
  return runs;
}

// gtest names a parameter by the scene.
void PrintTo(const Box2dV3Run& run, std::ostream* out) {
  *out << run.name;
}

constexpr int kEvery = 50;

int box2d_v3_steps(std::string_view name) {
  for (const BenchmarkScene& scene : benchmark_suite()) {
    if (scene.name == name) return scene.steps;
  }
  ADD_FAILURE() << "no suite scene " << name;
  return 0;
}

TEST(SuiteScenes, AreTheTenOfBox2dV3WithItsStepCounts) {
  std::vector<std::string_view> names;
  for (const BenchmarkScene& scene : benchmark_suite()) {
    names.push_back(scene.name);
    EXPECT_NO_THROW(builtin_scene(scene.name)) << scene.name;
  }
  EXPECT_EQ(names, (std::vector<std::string_view>{"compounds", "joint_grid", "junkyard",
                                                  "large_pyramid", "many_pyramids", "rain", "smash",
                                                  "spinner", "tumbler", "washer"}));
  for (const Box2dV3Run& run : box2d_v3_runs()) {
    EXPECT_EQ(static_cast<int>(run.touching.size()) * kEvery, box2d_v3_steps(run.name)) << run.name;
  }
}

// Bodies, shapes and joints come and go only by the scene's schedule: the world at the end of
// Box2D v3's run holds what the schedule leaves, stepped or not. So the static scenes are
// counted as built, and the schedules run to the end of the run without the physics.
TEST(SuiteScenes, CountsEqualBox2dV3sAtTheEndOfItsRun) {
  for (const Box2dV3Run& run : box2d_v3_runs()) {
    SCOPED_TRACE(std::string(run.name));
    const SceneDef scene = builtin_scene(run.name);
    World world(scene.world);
    const SceneIds ids = add_scene(world, scene);
    if (scene.schedule) {
      const SceneActions actions = scene.schedule(world, ids);
      const int steps = box2d_v3_steps(run.name);
      for (int step = 0; step < steps; ++step) actions(world, static_cast<std::uint64_t>(step));
    }
    EXPECT_EQ(world.body_count(), run.bodies);
    EXPECT_EQ(world.shape_count(), run.shapes);
    EXPECT_EQ(world.joint_count(), run.joints);
  }
  // The scenes that change are those whose Box2D v3 step function changes the world.
  for (const BenchmarkScene& scene : benchmark_suite()) {
    const bool scheduled = static_cast<bool>(builtin_scene(scene.name).schedule);
    EXPECT_EQ(scheduled, scene.name == "rain" || scene.name == "junkyard") << scene.name;
  }
}

// rain drops a column of five groups of five ragdolls every eighth step; once all 40 columns
// are down it destroys the oldest column and drops it anew, so the count stays at 1000.
TEST(SuiteScenes, RainDropsAndReplacesItsRagdollsOnSchedule) {
  const SceneDef scene = builtin_scene("rain");
  World world(scene.world);
  const SceneActions actions = scene.schedule(world, add_scene(world, scene));
  const std::size_t ragdoll = 11;  // bodies; ten joints
  for (std::uint64_t step = 0; step < 400; ++step) {
    actions(world, step);
    const std::size_t columns = std::min<std::size_t>(step / 8 + 1, 40);
    ASSERT_EQ(world.body_count(), 1 + 25 * ragdoll * columns) << step;
    ASSERT_EQ(world.joint_count(), 25 * 10 * columns) << step;
  }
  // Two runs of the schedule are independent: a fresh one starts from the first column.
  World other(scene.world);
  const SceneActions again = scene.schedule(other, add_scene(other, scene));
  again(other, 0);
  EXPECT_EQ(other.body_count(), 1 + 25 * ragdoll);
}

std::vector<std::size_t> touching_every(SceneRun& run, int steps, bool& finite) {
  std::vector<std::size_t> touching;
  for (int step = 1; step <= steps; ++step) {
    run.step();
    if (step % kEvery == 0) touching.push_back(run.world().counters().touching_contacts);
  }
  finite = true;
  for (const BodyId id : run.world().bodies())
    finite = finite && test::finite_state(run.world(), id);
  return touching;
}

double mean(const std::vector<std::size_t>& values, std::size_t count) {
  double sum = 0;
  for (std::size_t i = 0; i < count; ++i) sum += static_cast<double>(values[i]);
  return sum / static_cast<double>(count);
}

// Within 5% over a run: the mean of the touching counts at the same steps (single steps of a
// tumbling pile swing by more than that).
void expect_touching_near(const std::vector<std::size_t>& ours, const Box2dV3Run& run,
                          std::size_t checkpoints) {
  const double want = mean(run.touching, checkpoints);
  const double got = mean(ours, checkpoints);
  if (want == 0) {
    EXPECT_EQ(got, 0);
  } else {
    EXPECT_LT(std::abs(got - want), 0.05 * want) << "mean touching over " << checkpoints * kEvery
                                                 << " steps: ours " << got << ", Box2D v3 " << want;
  }
}

class SuiteScene : public testing::TestWithParam<Box2dV3Run> {};

// A shortened run of each scene: no NaN, and its touching contacts within 5% of Box2D v3's.
// Under the sanitizers a few steps only, for the memory checks (schedules included).
TEST_P(SuiteScene, TouchesAsMuchAsBox2dV3OverAShortRun) {
  const Box2dV3Run& v3 = GetParam();
#ifdef MINK_SANITIZED_BUILD
  SceneRun run(builtin_scene(v3.name));
  bool finite = false;
  touching_every(run, 10, finite);
  EXPECT_TRUE(finite);
#else
  if (!v3.mismatch.empty()) GTEST_SKIP() << "does not match Box2D v3 yet: " << v3.mismatch;
  SceneRun run(builtin_scene(v3.name));
  bool finite = false;
  const std::vector<std::size_t> touching = touching_every(run, v3.short_steps, finite);
  EXPECT_TRUE(finite);
  expect_touching_near(touching, v3, touching.size());
#endif
}

INSTANTIATE_TEST_SUITE_P(Box2dV3, SuiteScene, testing::ValuesIn(box2d_v3_runs()),
                         [](const testing::TestParamInfo<Box2dV3Run>& info) {
                           return std::string(info.param.name);
                         });

// The highest box of each pyramid, and where it started: a box with no box right above it
// (within a box's height).
std::vector<test::Start> pyramid_tops(const World& world) {
  std::vector<test::Start> tops;
  for (const test::Start& box : test::dynamic_bodies(world)) {
    bool covered = false;
    for (const ShapeId shape : world.query_point(box.position + Vec2(0, 1))) {
      covered = covered || world.body_type(world.shape_body(shape)) == BodyType::dynamic;
    }
    if (!covered) tops.push_back(box);
  }
  return tops;
}

// The whole of each run, as `make test` cannot afford (minutes): every scene for Box2D v3's
// step count and at least 600 steps without NaN, the touching contacts within 5% of Box2D
// v3's over its whole run, the contacts at the end of its run within 5% of its contactCount,
// and many_pyramids standing (each top box within 0.3 of its start
// after 500 steps; large_pyramid has its own test in pyramid_test.cpp). Run it with
//   build/bin/mink_engine_tests --gtest_also_run_disabled_tests --gtest_filter='*FullLength*'
TEST(SuiteScenes, DISABLED_FullLengthRunsMatchBox2dV3) {
  for (const Box2dV3Run& v3 : box2d_v3_runs()) {
    SCOPED_TRACE(std::string(v3.name));
    SceneRun run(builtin_scene(v3.name));
    const int steps = box2d_v3_steps(v3.name);
    const bool stack = v3.name == "many_pyramids";
    const std::vector<test::Start> tops =
        stack ? pyramid_tops(run.world()) : std::vector<test::Start>{};
    bool finite = false;
    std::vector<std::size_t> touching = touching_every(run, stack ? 500 : steps, finite);
    const auto contacts = static_cast<double>(run.world().counters().contacts);
    EXPECT_LE(std::abs(contacts - static_cast<double>(v3.contacts)),
              0.05 * static_cast<double>(v3.contacts))
        << "contacts after " << steps << " steps: ours " << contacts << ", Box2D v3 "
        << v3.contacts;
    if (stack) {
      EXPECT_EQ(tops.size(), 400u);
      Real worst = 0;
      for (const test::Start& top : tops) {
        worst = std::max(worst, (run.world().position(top.id) - top.position).norm());
      }
      EXPECT_LT(worst, 0.3);
    }
    const std::vector<std::size_t> rest =
        touching_every(run, std::max(600, steps) - (stack ? 500 : steps), finite);
    touching.insert(touching.end(), rest.begin(), rest.end());
    EXPECT_TRUE(finite);
    expect_touching_near(touching, v3, v3.touching.size());
    std::printf(
        "%s: mean touching over %d steps, ours %.0f, Box2D v3 %.0f; contacts at the end, ours "
        "%.0f, Box2D v3 %zu\n",
        std::string(v3.name).c_str(), steps, mean(touching, v3.touching.size()),
        mean(v3.touching, v3.touching.size()), contacts, v3.contacts);
  }
}

}  // namespace
}  // namespace mink
