// Box2D v3's side of bench/run_large_world.sh, built against its float build and against its
// double-precision (large world) build: Minkowski's large_pyramid and ragdolls scenes made with
// Box2D v3's API at Box2D v3's default settings (sleeping on), at the origin and 10^7 m out,
// settled side by side (large_world.hpp).

#include <cmath>
#include <string>
#include <vector>

#include "box2d/box2d.h"
#include "human.h"
#include "large_world.hpp"

namespace mink::bench {
namespace {

#if defined(BOX2D_DOUBLE_PRECISION)
constexpr const char* kImplementation = "box2d_v3_double";
#else
constexpr const char* kImplementation = "box2d_v3_float";
#endif

using Coordinate = decltype(b2Pos{}.x);

b2Pos at(double offset, double x, double y) {
  return {static_cast<Coordinate>(offset + x), static_cast<Coordinate>(offset + y)};
}

class Box2dSettlingWorld final : public SettlingWorld {
 public:
  Box2dSettlingWorld() {
    b2WorldDef def = b2DefaultWorldDef();
    def.workerCount = 1;
    world_ = b2CreateWorld(&def);
  }
  ~Box2dSettlingWorld() override { b2DestroyWorld(world_); }
  Box2dSettlingWorld(const Box2dSettlingWorld&) = delete;
  Box2dSettlingWorld& operator=(const Box2dSettlingWorld&) = delete;

  b2WorldId world() const { return world_; }
  void add_static_box(b2Pos position, float half_width, float half_height) {
    b2BodyDef body = b2DefaultBodyDef();
    body.position = position;
    const b2BodyId id = b2CreateBody(world_, &body);
    const b2Polygon box = b2MakeBox(half_width, half_height);
    const b2ShapeDef shape = b2DefaultShapeDef();
    b2CreatePolygonShape(id, &shape, &box);
    bodies_.push_back(id);
  }
  void add_box(b2Pos position, float half) {
    b2BodyDef body = b2DefaultBodyDef();
    body.type = b2_dynamicBody;
    body.position = position;
    const b2BodyId id = b2CreateBody(world_, &body);
    const b2Polygon box = b2MakeSquare(half);
    b2ShapeDef shape = b2DefaultShapeDef();
    shape.density = 1;
    b2CreatePolygonShape(id, &shape, &box);
    bodies_.push_back(id);
  }
  void add(b2BodyId id) { bodies_.push_back(id); }
#if defined(BOX2D_DOUBLE_PRECISION)
  // Every body moved to the position it would hold 10^7 m out, and back.
  void hold_only_far_positions() {
    for (const b2BodyId id : bodies_) {
      const b2Pos p = b2Body_GetPosition(id);
      const b2Pos held = {(p.x + kLargeWorldOffset) - kLargeWorldOffset,
                          (p.y + kLargeWorldOffset) - kLargeWorldOffset};
      b2Body_SetTransform(id, held, b2Body_GetRotation(id));
    }
  }
#endif

  void step() override {
    b2World_Step(world_, 1.0f / 60.0f, 4);
  }
  bool asleep() const override {
    for (const b2BodyId id : bodies_) {
      if (b2Body_GetType(id) == b2_dynamicBody && b2Body_IsAwake(id)) return false;
    }
    return true;
  }
  std::vector<BodyPlace> places() const override {
    std::vector<BodyPlace> out;
    for (const b2BodyId id : bodies_) {
      const b2Pos p = b2Body_GetPosition(id);
      out.push_back({static_cast<double>(p.x), static_cast<double>(p.y),
                     static_cast<double>(b2Rot_GetAngle(b2Body_GetRotation(id)))});
    }
    return out;
  }

 private:
  b2WorldId world_;
  std::vector<b2BodyId> bodies_;
};

// Box2D v3's large pyramid: 100 boxes of 1 m at the base, on a 200 m ground.
void large_pyramid(Box2dSettlingWorld& w, double offset) {
  w.add_static_box(at(offset, 0, -1), 100, 1);
  constexpr int kBase = 100;
  constexpr double kHalf = 0.5;
  for (int i = 0; i < kBase; ++i) {
    for (int j = i; j < kBase; ++j) {
      const double x = (i + 1) * kHalf + 2 * (j - i) * kHalf - kHalf * kBase;
      w.add_box(at(offset, x, (2 * i + 1) * kHalf), static_cast<float>(kHalf));
    }
  }
}

// Minkowski's ragdolls: twelve of Box2D v3's humans, six standing and six dropped on them.
void ragdolls(Box2dSettlingWorld& w, double offset) {
  w.add_static_box(at(offset, 0, -1), 20, 1);
  for (int i = 0; i < 12; ++i) {
    const double x = -6 + 1.1 * (i % 6) + 0.4 * (i / 6), y = 3.0 * (i / 6);
    Human human{};
    CreateHuman(&human, w.world(), at(offset, x, y), 1.0f, 0.05f, 5.0f, 0.5f, -(i + 1), nullptr,
                false);
    for (const Bone& bone : human.bones) w.add(bone.bodyId);
  }
}

void run(const std::string& name, void (*build)(Box2dSettlingWorld&, double)) {
  Box2dSettlingWorld origin, far;
  build(origin, 0);
  build(far, kLargeWorldOffset);
#if defined(BOX2D_DOUBLE_PRECISION)
  // The double build's origin run starts from the positions its far run can hold, as
  // Minkowski's does, so the two are the same scene. The float build cannot hold a scene
  // 10^7 m out at all (floats there are a metre apart): its origin run is the scene as defined.
  origin.hold_only_far_positions();
#endif
  print_settle_row(name, kImplementation, settle_side_by_side(origin, far));
}

}  // namespace
}  // namespace mink::bench

int main() {
  mink::bench::run("large_pyramid", mink::bench::large_pyramid);
  mink::bench::run("ragdolls", mink::bench::ragdolls);
}
