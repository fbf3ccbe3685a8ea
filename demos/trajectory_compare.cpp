#include "trajectory_compare.hpp"

#include <box2d/box2d.h>

#include "box2d_scene.hpp"

namespace mink::cli {

namespace {

Vec2 to_double(const b2Vec2& v) {
  return {v.x, v.y};
}

}  // namespace

TrajectoryRecorder::TrajectoryRecorder(const SceneDef& scene) {
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    if (scene.bodies[i].body.type == BodyType::dynamic) dynamic_.push_back(i);
  }
  for (std::size_t i = 0; i < scene.joints.size(); ++i) {
    const JointType type = joint_type(scene.joints[i].def);
    if (type == JointType::revolute || type == JointType::weld) pinned_.push_back(i);
  }
}

void TrajectoryRecorder::record(long long step, const World& ours,
                                const interop::Box2dScene& rival) {
  // A fresh world's slots are in scene order.
  const std::vector<BodyId> bodies = ours.bodies();
  for (const std::size_t i : dynamic_) {
    const Vec2 mink = ours.position(bodies[i]);
    const Vec2 box2d = to_double(rival.bodies[i]->GetPosition());
    rows_.push_back({step, i, mink, box2d, (mink - box2d).norm()});
  }
  if (pinned_.empty()) return;
  const std::vector<JointId> joints = ours.joints();
  JointGapRow gap{step, 0, 0};
  for (const std::size_t j : pinned_) {
    gap.mink += (ours.joint_anchor_b(joints[j]) - ours.joint_anchor_a(joints[j])).norm();
    const b2Joint& theirs = *rival.joints[j];
    gap.box2d += (to_double(theirs.GetAnchorB()) - to_double(theirs.GetAnchorA())).norm();
  }
  gaps_.push_back(gap);
}

WorstDifference worst_difference(const std::vector<TrajectoryRow>& rows, long long last_step) {
  WorstDifference worst;
  for (const TrajectoryRow& row : rows) {
    if (row.step <= last_step && row.distance > worst.distance) {
      worst = {row.distance, row.step, row.body};
    }
  }
  return worst;
}

std::vector<StepDifference> step_differences(const std::vector<TrajectoryRow>& rows) {
  std::vector<StepDifference> out;
  std::size_t count = 0;
  for (const TrajectoryRow& row : rows) {
    if (out.empty() || out.back().step != row.step) {
      if (!out.empty()) out.back().mean /= static_cast<double>(count);
      out.push_back({row.step, 0, 0});
      count = 0;
    }
    out.back().max = std::max(out.back().max, row.distance);
    out.back().mean += row.distance;
    ++count;
  }
  if (!out.empty()) out.back().mean /= static_cast<double>(count);
  return out;
}

}  // namespace mink::cli
