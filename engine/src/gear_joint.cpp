#include "gear_joint.hpp"

namespace mink::detail {

void prepare(GearJoint&, JointFrame&) {}
void warm_start(const GearJoint&, const JointFrame&, SolverBody*) {}
void solve(GearJoint&, const JointFrame&, SolverBody*, bool) {}
JointReaction reaction(const GearJoint&, const JointFrame&) { return {}; }
void finish(GearJoint&, const JointBodyState&, const JointBodyState&) {}
Real coordinate(const GearJoint&, const JointBodyState&, const JointBodyState&) { return 0; }
Real speed(const GearJoint&, const JointBodyState&, const JointBodyState&) { return 0; }
void draw(const GearJoint&, const JointBodyState&, const JointBodyState&, DebugDraw&) {}

}  // namespace mink::detail
