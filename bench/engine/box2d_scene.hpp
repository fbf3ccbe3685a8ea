#pragma once

#include <memory>

#include "mink/engine/scene.hpp"

class b2World;
class b2Body;

namespace mink::bench {

// The same scene in Box2D 2.4.1: every body and shape of the SceneDef (hull vertices as
// b2PolygonShape, at most b2_maxPolygonVertices each), same gravity, friction, density,
// restitution. Box2D keeps its own polygon skin (b2_polygonRadius), as it would for a user.
struct Box2dScene {
  std::unique_ptr<b2World> world;
  b2Body* top = nullptr;  // the highest dynamic body at the start
};

Box2dScene build_box2d_world(const SceneDef& scene);

}  // namespace mink::bench
