#include "prismatic_joint.hpp"

namespace mink::detail {

void prepare(PrismaticJoint&, JointFrame&) {}
void warm_start(const PrismaticJoint&, const JointFrame&, SolverBody*) {}
void solve(PrismaticJoint&, const JointFrame&, SolverBody*, bool) {}
JointReaction reaction(const PrismaticJoint&, const JointFrame&) { return {}; }
void finish(PrismaticJoint&, const JointBodyState&, const JointBodyState&) {}
Real coordinate(const PrismaticJoint&, const JointBodyState&, const JointBodyState&) { return 0; }
Real speed(const PrismaticJoint&, const JointBodyState&, const JointBodyState&) { return 0; }
void draw(const PrismaticJoint&, const JointBodyState&, const JointBodyState&, DebugDraw&) {}

}  // namespace mink::detail
