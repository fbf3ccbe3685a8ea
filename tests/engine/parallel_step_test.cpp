// The parallel step: bitwise the same states and events at any worker count, with the
// built-in pool or an embedder's task system, on the SIMD and the scalar solver paths.

#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "mink/engine/scene.hpp"
#include "mink/engine/scene_schedule.hpp"
#include "mink/error.hpp"
#include "test_worlds.hpp"

namespace mink {
namespace {

// The state hash after `steps` steps, folded with every step's contact begin and end events in
// the order the world reports them.
std::uint64_t run(SceneDef scene, int steps) {
  SceneRun scene_run(scene);  // with the scene's schedule, if it has one
  World& world = scene_run.world();
  std::uint64_t events = 0;
  for (int i = 0; i < steps; ++i) {
    scene_run.step();
    for (const ContactBeginEvent& e : world.contact_begin_events()) {
      events = events * 1099511628211ull + e.shape_a.index * 31u + e.shape_b.index;
    }
    for (const ContactEndEvent& e : world.contact_end_events()) {
      events = events * 1099511628211ull + e.shape_a.index * 37u + e.shape_b.index + 1;
    }
  }
  return test::state_hash(world) ^ (events * 0x9e3779b97f4a7c15ull);
}

struct Case {
  const char* scene;
  int steps;
};

class WorkerCounts : public ::testing::TestWithParam<Case> {};

TEST_P(WorkerCounts, GiveBitwiseTheSameStateAndEvents) {
  const Case c = GetParam();
  SceneDef scene = builtin_scene(c.scene);
  // Under the sanitizers (ThreadSanitizer above all, ten times slower) a fifth of the run.
  const int steps = test::long_run(c.steps, c.steps / 5);
  scene.world.worker_count = 1;
  const std::uint64_t one = run(scene, steps);
  for (const int workers : {2, 3, 4, 8}) {
    scene.world.worker_count = workers;
    EXPECT_EQ(run(scene, steps), one) << c.scene << " at " << workers << " workers";
  }
  // The scalar twin of the solver, spread over workers too.
  scene.world.simd_solver = false;
  scene.world.worker_count = 2;
  EXPECT_EQ(run(scene, steps), one) << c.scene << ", scalar solver at 2 workers";
}

// Stacks, a kinematic-free rain of hulls with sleeping on, a motor-driven drum, joints of
// every kind the built-ins use, and every shape kind.
INSTANTIATE_TEST_SUITE_P(Scenes, WorkerCounts,
                         ::testing::Values(Case{"pyramid", 300}, Case{"rain_mixed", 300},
                                           Case{"tumbler_400", 200}, Case{"ragdolls", 300},
                                           Case{"bridge", 300}, Case{"car", 300},
                                           Case{"shapes", 300}, Case{"chain", 300},
                                           Case{"newtons_cradle", 300}),
                         [](const auto& info) { return std::string(info.param.scene); });

// Box2D v3's suite: stacks, a motor-driven drum, ragdolls dropped by the rain's schedule,
// compound bodies for a few hundred steps; the spinner (6000 bodies churned by a motor, our
// slowest scene) for twenty.
class SuiteWorkerCounts : public ::testing::TestWithParam<Case> {};

TEST_P(SuiteWorkerCounts, GiveBitwiseTheSameStateAndEvents) {
  const Case c = GetParam();
  SceneDef scene = builtin_scene(c.scene);
  const int steps = test::long_run(c.steps, 15);
  scene.world.worker_count = 1;
  const std::uint64_t one = run(scene, steps);
  for (const int workers : {2, 3, 4, 8}) {
    scene.world.worker_count = workers;
    EXPECT_EQ(run(scene, steps), one) << c.scene << " at " << workers << " workers";
  }
}

INSTANTIATE_TEST_SUITE_P(Suite, SuiteWorkerCounts,
                         ::testing::Values(Case{"large_pyramid", 200}, Case{"tumbler", 150},
                                           Case{"spinner", 20}, Case{"rain", 200},
                                           Case{"compounds", 100}),
                         [](const auto& info) { return std::string(info.param.scene); });

// Hundreds of bouncing contacts: restitution runs after the solve in a fixed order, whichever
// worker built each contact; the wide solver reads each bouncing constraint back from its
// lane, the scalar twin has it whole, and they agree.
TEST(WorkerCounts, BouncingRainAgrees) {
  SceneDef scene = rain_scene(300, 5);
  for (SceneBody& body : scene.bodies) {
    for (ShapeDef& shape : body.shapes) shape.restitution = 0.7;
  }
  scene.world.enable_sleep = false;
  const std::uint64_t one = run(scene, test::long_run(250, 50));
  for (const int workers : {2, 3}) {
    scene.world.worker_count = workers;
    EXPECT_EQ(run(scene, test::long_run(250, 50)), one) << workers << " workers";
  }
  scene.world.simd_solver = false;
  scene.world.worker_count = 1;
  EXPECT_EQ(run(scene, test::long_run(250, 50)), one) << "scalar solver";
}

// Bodies thrown hard at the ground and at each other: continuous collision sweeps them in
// parallel, with the same stops at any worker count.
TEST(WorkerCounts, FastRainAgrees) {
  SceneDef scene = rain_scene(200, 9);
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    BodyDef& body = scene.bodies[i].body;
    if (body.type != BodyType::dynamic) continue;
    body.linear_velocity = Vec2(i % 2 == 0 ? 40.0 : -40.0, -120);
    body.angular_velocity = i % 3 == 0 ? 50 : -20;
  }
  scene.world.enable_sleep = false;
  World probe = build_world(scene);
  probe.step();
  EXPECT_GT(probe.counters().fast_bodies, 100u);
  const std::uint64_t one = run(scene, test::long_run(120, 30));
  for (const int workers : {2, 4}) {
    scene.world.worker_count = workers;
    EXPECT_EQ(run(scene, test::long_run(120, 30)), one) << workers << " workers";
  }
}

TEST(WorkerCounts, LargeStackAgreesAtOneAndTwoWorkers) {
  SceneDef scene = builtin_scene("pyramid_100");
  scene.world.worker_count = 1;
  const std::uint64_t one = run(scene, 60);
  scene.world.worker_count = 2;
  EXPECT_EQ(run(scene, 60), one);
}

// An embedder's task system: each enqueue starts one thread per range, finish joins them.
struct ThreadPerRange {
  struct Task {
    std::vector<std::thread> threads;
  };
  static void* enqueue(TaskFunction* function, std::uint32_t count, std::uint32_t min_range,
                       void* context, void* user) {
    auto* self = static_cast<ThreadPerRange*>(user);
    ++self->enqueued;
    auto task = std::make_unique<Task>();
    const std::uint32_t ranges = 3;  // the worker count below
    const std::uint32_t size = std::max(min_range, (count + ranges - 1) / ranges);
    std::uint32_t worker = 0;
    for (std::uint32_t begin = 0; begin < count; begin += size, ++worker) {
      const std::uint32_t end = std::min(count, begin + size);
      task->threads.emplace_back([=] { function(begin, end, worker, context); });
    }
    return task.release();
  }
  static void finish(void* handle, void*) {
    std::unique_ptr<Task> task(static_cast<Task*>(handle));
    for (std::thread& t : task->threads) t.join();
  }
  int enqueued = 0;
};

// A task system that runs everything inside enqueue, on the stepping thread.
void* run_inline(TaskFunction* function, std::uint32_t count, std::uint32_t, void* context,
                 void* user) {
  ++*static_cast<int*>(user);
  function(0, count, 0, context);
  return nullptr;
}

void never_called(void*, void*) {
  ADD_FAILURE() << "finish called for a task that ran inside enqueue";
}

TEST(TaskSystem, AnEmbeddersThreadsGiveTheSameState) {
  SceneDef scene = builtin_scene("ragdolls");
  const std::uint64_t one = run(scene, 200);
  ThreadPerRange system;
  scene.world.worker_count = 3;
  scene.world.task_system = {&ThreadPerRange::enqueue, &ThreadPerRange::finish, &system};
  EXPECT_EQ(run(scene, 200), one);
  EXPECT_GT(system.enqueued, 200) << "the step handed its phases to the task system";
}

TEST(TaskSystem, OneThatRunsTasksInlineNeitherHangsNorChangesTheState) {
  SceneDef scene = builtin_scene("pyramid");
  const std::uint64_t one = run(scene, 150);
  int calls = 0;
  scene.world.worker_count = 4;
  scene.world.task_system = {&run_inline, &never_called, &calls};
  EXPECT_EQ(run(scene, 150), one);
  EXPECT_GT(calls, 150);
}

TEST(TaskSystem, BadSettingsAreRefusedNamingThem) {
  for (const int count : {0, -1, 257}) {
    WorldDef def;
    def.worker_count = count;
    try {
      World world(def);
      ADD_FAILURE() << "worker_count " << count << " accepted";
    } catch (const InvalidArgumentError& e) {
      EXPECT_NE(std::string(e.what()).find("worker_count"), std::string::npos) << e.what();
    }
  }
  WorldDef def;
  def.task_system.enqueue = &run_inline;
  EXPECT_THROW(World{def}, InvalidArgumentError);
}

}  // namespace
}  // namespace mink
