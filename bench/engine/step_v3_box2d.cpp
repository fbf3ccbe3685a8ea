// Box2D v3's side of the race (bench/run_step.sh): one scene of its benchmark suite, built by
// its own shared/benchmarks.c and stepped as its benchmark app steps it: b2DefaultWorldDef with
// continuous collision on (off for box2d_v3_no_ccd) and workerCount workers (Box2D v3's
// built-in scheduler runs workerCount - 1 threads beside the caller), the scene's step
// function (rain's ragdolls, junkyard's pusher, spinner's angle) before each b2World_Step of
// 1/60 s in 4 substeps.
// See step_race.hpp for the command line.

#include <stdexcept>
#include <string>

#include "benchmarks.h"
#include "box2d/box2d.h"
#include "step_race.hpp"

namespace mink::bench {
namespace {

constexpr float kTimeStep = 1.0f / 60.0f;
constexpr int kSubsteps = 4;

struct Box2dV3Scene {
  std::string_view name;
  void (*create)(b2WorldId);
  float (*step)(b2WorldId, int);  // null: the scene does nothing between steps
};

// Box2D v3's scenes with the step functions its benchmark app calls between steps.
constexpr Box2dV3Scene kScenes[] = {
    {"compounds", CreateCompounds, nullptr},
    {"joint_grid", CreateJointGrid, nullptr},
    {"junkyard", CreateJunkyard, StepJunkyard},
    {"large_pyramid", CreateLargePyramid, nullptr},
    {"many_pyramids", CreateManyPyramids, nullptr},
    {"rain", CreateRain, StepRain},
    {"smash", CreateSmash, nullptr},
    {"spinner", CreateSpinner, StepSpinner},
    {"tumbler", CreateTumbler, nullptr},
    {"washer", CreateWasher, nullptr},
};

class Box2dV3World final : public RaceWorld {
 public:
  Box2dV3World(const Box2dV3Scene& scene, const RaceRequest& request) : scene_(scene) {
    const SuiteScene& suite = *request.scene;
    b2WorldDef def = b2DefaultWorldDef();
    // box2d_v3_no_ccd: what continuous collision costs Box2D v3 itself, beside ours.
    def.enableContinuous = request.implementation != "box2d_v3_no_ccd";
    def.workerCount = request.workers;
    world_ = b2CreateWorld(&def);
    scene.create(world_);
    // The suite table tells our runner whether to sleep; it must say what the scene does.
    if (b2World_IsSleepingEnabled(world_) == suite.sleep_off) {
      b2DestroyWorld(world_);
      throw std::runtime_error("the scene leaves sleeping " +
                               std::string(suite.sleep_off ? "on" : "off") +
                               ", unlike step_v3_suite.hpp");
    }
    if (!request.sleep) b2World_EnableSleeping(world_, false);
  }
  ~Box2dV3World() override { b2DestroyWorld(world_); }
  Box2dV3World(const Box2dV3World&) = delete;
  Box2dV3World& operator=(const Box2dV3World&) = delete;

  void step(int index) override {
    if (scene_.step != nullptr) scene_.step(world_, index);
    b2World_Step(world_, kTimeStep, kSubsteps);
  }

  RaceCounts counts() const override {
    const b2Counters c = b2World_GetCounters(world_);
    return {c.bodyCount, c.shapeCount, c.jointCount, c.contactCount};
  }

  std::vector<std::pair<std::string, double>> profile() const override {
    const b2Profile p = b2World_GetProfile(world_);
    return {{"step", p.step},
            {"pairs", p.pairs},
            {"collide", p.collide},
            {"solve", p.solve},
            {"solver_setup", p.solverSetup},
            {"prepare_constraints", p.prepareConstraints},
            {"integrate_velocities", p.integrateVelocities},
            {"warm_start", p.warmStart},
            {"solve_impulses", p.solveImpulses},
            {"integrate_positions", p.integratePositions},
            {"relax_impulses", p.relaxImpulses},
            {"apply_restitution", p.applyRestitution},
            {"store_impulses", p.storeImpulses},
            {"split_islands", p.splitIslands},
            {"transforms", p.transforms},
            {"hit_events", p.hitEvents},
            {"refit", p.refit},
            {"bullets", p.bullets},
            {"sleep_islands", p.sleepIslands},
            {"sensors", p.sensors}};
  }

 private:
  const Box2dV3Scene& scene_;
  b2WorldId world_{};
};

std::unique_ptr<RaceWorld> build(const RaceRequest& request) {
  for (const Box2dV3Scene& scene : kScenes) {
    if (scene.name == request.scene->name) {
      return std::make_unique<Box2dV3World>(scene, request);
    }
  }
  return nullptr;
}

}  // namespace
}  // namespace mink::bench

int main(int argc, char** argv) {
  using namespace mink::bench;
  return race_main(argc, argv, RaceEngine{{"box2d_v3", "box2d_v3_no_ccd"}, build});
}
