#include "distance_joint.hpp"

namespace mink::detail {

void prepare(DistanceJoint&, JointFrame&) {}
void warm_start(const DistanceJoint&, const JointFrame&, SolverBody*) {}
void solve(DistanceJoint&, const JointFrame&, SolverBody*, bool) {}
JointReaction reaction(const DistanceJoint&, const JointFrame&) { return {}; }
void finish(DistanceJoint&, const JointBodyState&, const JointBodyState&) {}
Real coordinate(const DistanceJoint&, const JointBodyState&, const JointBodyState&) { return 0; }
Real speed(const DistanceJoint&, const JointBodyState&, const JointBodyState&) { return 0; }
void draw(const DistanceJoint&, const JointBodyState&, const JointBodyState&, DebugDraw&) {}

}  // namespace mink::detail
