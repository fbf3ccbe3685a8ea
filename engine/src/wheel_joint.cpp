#include "wheel_joint.hpp"

namespace mink::detail {

void prepare(WheelJoint&, JointFrame&) {}
void warm_start(const WheelJoint&, const JointFrame&, SolverBody*) {}
void solve(WheelJoint&, const JointFrame&, SolverBody*, bool) {}
JointReaction reaction(const WheelJoint&, const JointFrame&) { return {}; }
void finish(WheelJoint&, const JointBodyState&, const JointBodyState&) {}
Real coordinate(const WheelJoint&, const JointBodyState&, const JointBodyState&) { return 0; }
Real speed(const WheelJoint&, const JointBodyState&, const JointBodyState&) { return 0; }
void draw(const WheelJoint&, const JointBodyState&, const JointBodyState&, DebugDraw&) {}

}  // namespace mink::detail
