// The C++ side of the Python batch-array benchmark (bench/python/batch_bench.py): the same
// loop as the Python one, here in C++. Loads SCENE, then for each of STEPS steps measures the
// thread's CPU time of one step and of reading every body's position, angle and velocities
// into arrays (what World.positions(), angles(), linear_velocities() and
// angular_velocities() do), and prints "step_ns,read_ns" per step.
#include <time.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "mink/engine/scene_file.hpp"
#include "mink/engine/world.hpp"

namespace {

std::int64_t thread_cpu_ns() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return std::int64_t{now.tv_sec} * 1'000'000'000 + now.tv_nsec;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s SCENE.json STEPS\n", argv[0]);
    return 2;
  }
  try {
    mink::World world = mink::build_world(mink::load_scene_file(argv[1]));
    const long steps = std::stol(argv[2]);
    std::vector<double> positions, angles, velocities, spins;
    double checksum = 0;
    for (long i = 0; i < steps; ++i) {
      const std::int64_t start = thread_cpu_ns();
      world.step();
      const std::int64_t stepped = thread_cpu_ns();
      const std::vector<mink::BodyId> bodies = world.bodies();
      positions.assign(2 * bodies.size(), 0);
      angles.assign(bodies.size(), 0);
      velocities.assign(2 * bodies.size(), 0);
      spins.assign(bodies.size(), 0);
      for (std::size_t b = 0; b < bodies.size(); ++b) {
        const mink::Vec2 p = world.position(bodies[b]);
        const mink::Vec2 v = world.linear_velocity(bodies[b]);
        positions[2 * b] = p.x();
        positions[2 * b + 1] = p.y();
        angles[b] = world.angle(bodies[b]);
        velocities[2 * b] = v.x();
        velocities[2 * b + 1] = v.y();
        spins[b] = world.angular_velocity(bodies[b]);
      }
      const std::int64_t read = thread_cpu_ns();
      checksum += positions[1] + angles.back() + velocities[0] + spins.back();
      std::printf("%lld,%lld\n", static_cast<long long>(stepped - start),
                  static_cast<long long>(read - stepped));
    }
    // The reads must not be optimised away; the checksum is not a result.
    std::fprintf(stderr, "checksum %.17g\n", checksum);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "%s: %s\n", argv[0], error.what());
    return 2;
  }
  return 0;
}
