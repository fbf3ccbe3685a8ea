// Minkowski's side of bench/run_large_world.sh: large_pyramid (sleeping on) and ragdolls at the
// origin and 10^7 m out, settled side by side (large_world.hpp). The origin's run starts from
// the positions the far one can hold, each moved out and back, so both are the same scene.

#include <string>

#include "large_world.hpp"
#include "mink/engine/scene.hpp"
#include "mink/engine/world.hpp"

namespace mink::bench {
namespace {

class MinkSettlingWorld final : public SettlingWorld {
 public:
  explicit MinkSettlingWorld(const SceneDef& scene) : world_(build_world(scene)) {}
  void step() override { world_.step(); }
  bool asleep() const override {
    for (const BodyId id : world_.bodies()) {
      if (world_.body_type(id) == BodyType::dynamic && world_.is_awake(id)) return false;
    }
    return true;
  }
  std::vector<BodyPlace> places() const override {
    std::vector<BodyPlace> out;
    for (const BodyId id : world_.bodies()) {
      const Vec2 p = world_.position(id);
      out.push_back({p.x(), p.y(), world_.angle(id)});
    }
    return out;
  }

 private:
  World world_;
};

void run(const std::string& name) {
  SceneDef scene = builtin_scene(name);
  scene.world.enable_sleep = true;
  const Vec2 offset(kLargeWorldOffset, kLargeWorldOffset);
  shift_scene(scene, offset);
  shift_scene(scene, -offset);
  MinkSettlingWorld origin(scene);
  shift_scene(scene, offset);
  MinkSettlingWorld far(scene);
  print_settle_row(name, "mink", settle_side_by_side(origin, far));
}

}  // namespace
}  // namespace mink::bench

int main() {
  mink::bench::run("large_pyramid");
  mink::bench::run("ragdolls");
}
