#pragma once

#include <memory>
#include <vector>

#include "mink/engine/scene.hpp"

class b2World;
class b2Body;
class b2Joint;

namespace mink::interop {

// The same scene in Box2D 2.4.1: every body, shape and joint of the SceneDef, same gravity,
// friction, restitution, filters and sensors. Shapes:
// - polygons as b2PolygonShape (hull vertices, at most b2_maxPolygonVertices). A sharp polygon
//   keeps Box2D's own skin (b2_polygonRadius), as it would for a user; a rounded one gets its
//   radius as the skin.
// - circles as b2CircleShape, segments as two-sided b2EdgeShape, chains as b2ChainShape (an
//   open chain's end ghosts turned towards its back, as ours).
// - capsules, which 2.4.1 lacks, as a rounded b2PolygonShape: the core segment lengthened
//   and thickened by 5 mm (b2_linearSlop) each way, rounded by the radius less that. It is
//   never short of the capsule and reaches at most 2 mm beyond it (off the ends' diagonals).
// Every dynamic body gets our mass, centre and rotational inertia (b2Body::SetMassData), so
// a shape Box2D holds only approximately (a capsule, a rounded polygon: 2.4.1 leaves the skin
// out of the mass) does not change the dynamics.
// Joints: revolute (limit, motor), prismatic (limit, motor), distance (rigid, rope between
// min and max length, spring through b2LinearStiffness), weld (rigid, or an angular spring
// through b2AngularStiffness), wheel (limit, motor, suspension spring through
// b2LinearStiffness), motor joint, gear (on the translated joints) and pulley.
// b2LinearStiffness and b2AngularStiffness use Box2D's body masses (the angular one the
// inertia about the body origin), so a spring on a body whose centre is off its origin runs
// at a slightly different frequency than ours. The motor joint's correction factor is passed
// as it is: ours acts per substep, Box2D's per b2World::Step; and ours, when its force bound
// binds, brakes before the target where Box2D's overshoots. Break thresholds only report
// events and have no Box2D counterpart; they are left out.
struct Box2dScene {
  std::unique_ptr<b2World> world;
  std::vector<b2Body*> bodies;   // in scene order
  std::vector<b2Joint*> joints;  // in scene order
  b2Body* top = nullptr;         // the highest dynamic body at the start
};

// Throws InvalidArgumentError before any Box2D object is made for what 2.4.1 cannot hold:
// naming the body and shape for a hull with more vertices than a Box2D polygon holds (hulls are
// never truncated), a capsule of radius 5 mm or less, filter categories or a group beyond 16
// bits; naming the joint (`joints[3]`) for a setting without a 2.4.1 counterpart: a revolute or
// prismatic spring, a distance motor, a distance or wheel spring of 0 hertz, a wheel spring with
// a target, a weld's linear spring. Also throws what build_world throws for the scene (the
// masses are ours).
Box2dScene build_box2d_world(const SceneDef& scene);

}  // namespace mink::interop
