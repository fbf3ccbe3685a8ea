// Islands and sleep: bodies joined by touching contacts sleep and wake together.

#include <algorithm>

#include "world_state.hpp"

namespace mink {

using detail::Body;
using detail::Contact;

namespace {

std::uint32_t find_root(std::vector<std::uint32_t>& parent, std::uint32_t i) {
  while (parent[i] != i) {
    parent[i] = parent[parent[i]];  // path halving
    i = parent[i];
  }
  return i;
}

}  // namespace

// Islands by union-find over touching contacts between dynamic bodies, every step. An island
// sleeps when all its bodies have been slow for time_to_sleep, and wakes as a whole when any
// member is moving (woken by the API, hit by an awake body or a moving kinematic body).
void WorldState::update_islands() {
  const std::size_t n = bodies.size();
  island_parent.resize(n);
  island_min_sleep.assign(n, def.time_to_sleep);
  for (std::uint32_t i = 0; i < n; ++i) island_parent[i] = i;
  for (const Contact& c : contacts) {
    if (!c.touching) continue;
    Body& a = bodies[c.body_a];
    Body& b = bodies[c.body_b];
    if (a.type == BodyType::dynamic && b.type == BodyType::dynamic) {
      const std::uint32_t ra = find_root(island_parent, c.body_a);
      const std::uint32_t rb = find_root(island_parent, c.body_b);
      if (ra != rb) island_parent[std::max(ra, rb)] = std::min(ra, rb);
    } else if (a.type == BodyType::kinematic || b.type == BodyType::kinematic) {
      Body& kinematic = a.type == BodyType::kinematic ? a : b;
      Body& other = a.type == BodyType::kinematic ? b : a;
      if (kinematic.velocity.squaredNorm() > 0 || kinematic.angular_velocity != 0) {
        other.sleep_time = 0;
      }
    }
  }
  for (std::uint32_t i = 0; i < n; ++i) {
    const Body& b = bodies[i];
    if (!b.alive || !b.enabled || b.type != BodyType::dynamic) continue;
    const std::uint32_t root = find_root(island_parent, i);
    island_min_sleep[root] = std::min(island_min_sleep[root], b.allow_sleep ? b.sleep_time : 0);
  }
  std::size_t islands = 0;
  for (std::uint32_t i = 0; i < n; ++i) {
    Body& b = bodies[i];
    if (!b.alive || !b.enabled || b.type != BodyType::dynamic) continue;
    const std::uint32_t root = find_root(island_parent, i);
    const bool awake = island_min_sleep[root] < def.time_to_sleep;
    if (awake && root == i) ++islands;
    if (!awake && b.awake) {
      b.velocity = Vec2(0, 0);
      b.angular_velocity = 0;
      fell_asleep.push_back(i);
    }
    b.awake = awake;
  }
  counters.islands = islands;
}

}  // namespace mink
