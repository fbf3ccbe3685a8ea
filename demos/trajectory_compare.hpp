#pragma once

#include <cstddef>
#include <vector>

#include "mink/engine/scene.hpp"

namespace mink::interop {
struct Box2dScene;
}

namespace mink::cli {

// One dynamic body at one step: its origin in both engines and their distance.
struct TrajectoryRow {
  long long step = 0;
  std::size_t body = 0;  // scene body index
  Vec2 mink{0, 0};
  Vec2 box2d{0, 0};
  double distance = 0;
};

// How far the joints that pin two points together (revolute and weld) have come apart,
// summed over those joints: a chain's stretch, in metres.
struct JointGapRow {
  long long step = 0;
  double mink = 0;
  double box2d = 0;
};

// The worst position difference over a span of steps.
struct WorstDifference {
  double distance = 0;
  long long step = 0;
  std::size_t body = 0;
};

// The largest and mean difference over the dynamic bodies, per step.
struct StepDifference {
  long long step = 0;
  double max = 0;
  double mean = 0;
};

// Records both engines' trajectories of a scene stepped side by side: every dynamic body's
// origin, and the joint gap when the scene has revolute or weld joints. `scene` is the one
// both worlds were built from, unstepped bodies and joints in scene order.
class TrajectoryRecorder {
 public:
  explicit TrajectoryRecorder(const SceneDef& scene);
  // The state after `step` steps (0: as built).
  void record(long long step, const World& ours, const interop::Box2dScene& rival);

  const std::vector<TrajectoryRow>& rows() const { return rows_; }  // step, then body order
  const std::vector<JointGapRow>& gaps() const { return gaps_; }    // empty without such joints
  std::size_t body_count() const { return dynamic_.size(); }

 private:
  std::vector<std::size_t> dynamic_;  // scene indices of the dynamic bodies
  std::vector<std::size_t> pinned_;   // scene indices of the revolute and weld joints
  std::vector<TrajectoryRow> rows_;
  std::vector<JointGapRow> gaps_;
};

// The worst row with step <= last_step.
WorstDifference worst_difference(const std::vector<TrajectoryRow>& rows, long long last_step);

// Max and mean per step, in step order.
std::vector<StepDifference> step_differences(const std::vector<TrajectoryRow>& rows);

}  // namespace mink::cli
