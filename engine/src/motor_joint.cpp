#include "motor_joint.hpp"

namespace mink::detail {

void prepare(MotorJoint&, JointFrame&) {}
void warm_start(const MotorJoint&, const JointFrame&, SolverBody*) {}
void solve(MotorJoint&, const JointFrame&, SolverBody*, bool) {}
JointReaction reaction(const MotorJoint&, const JointFrame&) { return {}; }
void finish(MotorJoint&, const JointBodyState&, const JointBodyState&) {}
Real coordinate(const MotorJoint&, const JointBodyState&, const JointBodyState&) { return 0; }
Real speed(const MotorJoint&, const JointBodyState&, const JointBodyState&) { return 0; }
void draw(const MotorJoint&, const JointBodyState&, const JointBodyState&, DebugDraw&) {}

}  // namespace mink::detail
