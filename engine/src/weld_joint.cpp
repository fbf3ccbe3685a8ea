#include "weld_joint.hpp"

namespace mink::detail {

void prepare(WeldJoint&, JointFrame&) {}
void warm_start(const WeldJoint&, const JointFrame&, SolverBody*) {}
void solve(WeldJoint&, const JointFrame&, SolverBody*, bool) {}
JointReaction reaction(const WeldJoint&, const JointFrame&) { return {}; }
void finish(WeldJoint&, const JointBodyState&, const JointBodyState&) {}
Real coordinate(const WeldJoint&, const JointBodyState&, const JointBodyState&) { return 0; }
Real speed(const WeldJoint&, const JointBodyState&, const JointBodyState&) { return 0; }
void draw(const WeldJoint&, const JointBodyState&, const JointBodyState&, DebugDraw&) {}

}  // namespace mink::detail
