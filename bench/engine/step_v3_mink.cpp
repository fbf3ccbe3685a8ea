// Our side of the race against Box2D v3 (bench/run_step.sh): the built-in scene of the suite
// scene's name, on WorldDef::worker_count workers, in one of three settings:
//   mink_matched   Box2D v3's app's world: 1/60 s steps of 4 substeps, 30 Hz contacts of
//                  damping ratio 10, 3 m/s push-out, joints at 60 Hz and damping ratio 2,
//                  restitution and hit thresholds 1 m/s, 400 m/s top speed, fast bodies
//                  swept against static and kinematic shapes only, their boxes bare after
//                  a sweep that stops them nowhere (WorldDef::fast_body_margin)
//   mink_matched_no_ccd  the same with continuous collision off (WorldDef::enable_continuous),
//                  to show what continuous collision costs
//   mink_defaults  our own solver defaults (WorldDef{}: 5 substeps, 60 Hz contacts, fast
//                  bodies swept against each other too, ...)
// All keep the scene's gravity and sleep as Box2D v3's app does (off only where the scene
// turns it off, or everywhere with --sleep=off), so they differ only in what the solver is
// asked to do.
// A suite scene that is not one of our built-ins is skipped. See step_race.hpp for the
// command line.

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <string>

#include "mink/engine/scene.hpp"
#include "mink/engine/world.hpp"
#include "step_race.hpp"

namespace mink::bench {
namespace {

void match_box2d_v3(WorldDef& world) {
  world.time_step = 1.0 / 60.0;
  world.substeps = 4;
  world.contact_hertz = 30;
  world.contact_damping_ratio = 10;
  world.contact_push_max_velocity = 3;
  world.joint_hertz = 60;
  world.joint_damping_ratio = 2;
  world.restitution_threshold = 1;
  world.hit_event_threshold = 1;
  world.max_linear_speed = 400;
  world.enable_continuous = true;
  world.continuous_fast_pairs = false;
  world.fast_body_margin = false;
}

void our_solver_defaults(WorldDef& world) {
  const WorldDef ours;
  world.time_step = ours.time_step;
  world.substeps = ours.substeps;
  world.contact_hertz = ours.contact_hertz;
  world.contact_damping_ratio = ours.contact_damping_ratio;
  world.contact_push_max_velocity = ours.contact_push_max_velocity;
  world.joint_hertz = ours.joint_hertz;
  world.joint_damping_ratio = ours.joint_damping_ratio;
  world.restitution_threshold = ours.restitution_threshold;
  world.hit_event_threshold = ours.hit_event_threshold;
  world.max_linear_speed = ours.max_linear_speed;
  world.enable_continuous = ours.enable_continuous;
  world.continuous_fast_pairs = ours.continuous_fast_pairs;
  world.fast_body_margin = ours.fast_body_margin;
}

// A scene's world run with its schedule (rain's ragdolls, junkyard's pusher), as `mink run`
// runs it.
class MinkWorld final : public RaceWorld {
 public:
  explicit MinkWorld(const SceneDef& scene) : run_(scene) {}

  void step(int /*index*/) override { run_.step(); }

  RaceCounts counts() const override {
    const World& world = run_.world();
    return {static_cast<long long>(world.body_count()), static_cast<long long>(world.shape_count()),
            static_cast<long long>(world.joint_count()),
            static_cast<long long>(world.counters().contacts)};
  }

  std::vector<std::pair<std::string, double>> profile() const override {
    const StepProfile& p = run_.world().profile();
    return {
        {"step", p.pairs + p.collide + p.islands + p.prepare + p.solve + p.continuous + p.finish},
        {"pairs", p.pairs},
        {"collide", p.collide},
        {"islands", p.islands},
        {"prepare", p.prepare},
        {"solve", p.solve},
        {"continuous", p.continuous},
        {"finish", p.finish}};
  }

 private:
  SceneRun run_;
};

std::unique_ptr<RaceWorld> build(const RaceRequest& request) {
  const auto names = builtin_scene_names();
  if (std::find(names.begin(), names.end(), request.scene->name) == names.end()) return nullptr;
  // Our built-ins know how long Box2D v3's app runs each scene too: the two tables must agree.
  for (const BenchmarkScene& ours : benchmark_suite()) {
    if (ours.name == request.scene->name && ours.steps != request.scene->steps) {
      throw std::logic_error("benchmark_suite() runs it " + std::to_string(ours.steps) +
                             " steps, step_v3_suite.hpp " + std::to_string(request.scene->steps));
    }
  }
  SceneDef scene = builtin_scene(request.scene->name);
  if (request.implementation == "mink_matched") {
    match_box2d_v3(scene.world);
  } else if (request.implementation == "mink_matched_no_ccd") {
    match_box2d_v3(scene.world);
    scene.world.enable_continuous = false;
  } else {
    our_solver_defaults(scene.world);
  }
  scene.world.enable_sleep = request.sleep;
  scene.world.worker_count = request.workers;
  return std::make_unique<MinkWorld>(scene);
}

}  // namespace
}  // namespace mink::bench

int main(int argc, char** argv) {
  using namespace mink::bench;
  return race_main(argc, argv,
                   RaceEngine{{"mink_matched", "mink_matched_no_ccd", "mink_defaults"}, build});
}
