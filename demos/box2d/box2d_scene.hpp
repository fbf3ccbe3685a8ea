#pragma once

#include <memory>
#include <vector>

#include "mink/engine/scene.hpp"

class b2World;
class b2Body;

namespace mink::interop {

// The same scene in Box2D 2.4.1: every body and shape of the SceneDef (hull vertices as
// b2PolygonShape, at most b2_maxPolygonVertices each), same gravity, friction, density,
// restitution, and its revolute joints (limits and motors). Box2D keeps its own polygon skin
// (b2_polygonRadius), as it would for a user.
struct Box2dScene {
  std::unique_ptr<b2World> world;
  std::vector<b2Body*> bodies;  // in scene order
  b2Body* top = nullptr;        // the highest dynamic body at the start
};

// Throws InvalidArgumentError naming the first body whose hull has more vertices than a Box2D
// polygon holds (hulls are never truncated), or the first joint of another kind or with a
// spring, before any Box2D object is made.
Box2dScene build_box2d_world(const SceneDef& scene);

}  // namespace mink::interop
