#include "pulley_joint.hpp"

namespace mink::detail {

void prepare(PulleyJoint&, JointFrame&) {}
void warm_start(const PulleyJoint&, const JointFrame&, SolverBody*) {}
void solve(PulleyJoint&, const JointFrame&, SolverBody*, bool) {}
JointReaction reaction(const PulleyJoint&, const JointFrame&) { return {}; }
void finish(PulleyJoint&, const JointBodyState&, const JointBodyState&) {}
Real coordinate(const PulleyJoint&, const JointBodyState&, const JointBodyState&) { return 0; }
Real speed(const PulleyJoint&, const JointBodyState&, const JointBodyState&) { return 0; }
void draw(const PulleyJoint&, const JointBodyState&, const JointBodyState&, DebugDraw&) {}

}  // namespace mink::detail
