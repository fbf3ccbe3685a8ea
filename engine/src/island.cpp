// Islands and sleep: bodies joined by touching contacts sleep and wake together.

#include <algorithm>

#include "world_state.hpp"

namespace mink {

using detail::Body;
using detail::Contact;

// Islands are found from the awake bodies only: a walk over contacts with points and joints
// between dynamic bodies gathers each island that holds an awake body (sleeping members included,
// so that they wake with it), and an island of sleeping bodies is never visited: it costs nothing.
// An island sleeps when all its bodies have been slow for time_to_sleep, and wakes as a whole when
// any member is moving (woken by the API, hit by an awake body or a moving kinematic body).
void WorldState::update_islands() {
  if (island_stamp.size() < bodies.size()) island_stamp.resize(bodies.size(), ~std::uint64_t{0});
  // A moving kinematic body keeps what it touches awake.
  for (const std::uint32_t ci : step_contacts) {
    const Contact& c = contacts[ci];
    if (!c.touching) continue;
    Body& a = bodies[c.body_a];
    Body& b = bodies[c.body_b];
    if (a.type != BodyType::kinematic && b.type != BodyType::kinematic) continue;
    Body& kinematic = a.type == BodyType::kinematic ? a : b;
    Body& other = a.type == BodyType::kinematic ? b : a;
    if (kinematic.velocity.squaredNorm() > 0 || kinematic.angular_velocity != 0) {
      other.sleep_time = 0;
    }
  }
  woken.clear();
  // An island falls asleep only once every member has rested for time_to_sleep. While no
  // awake body has, none can: then the islands need not be walked, only counted, and what
  // awake bodies reach woken (most steps of a busy scene; the walk below cost as much as the
  // narrowphase there).
  const bool some_rested = std::any_of(awake_list.begin(), awake_list.end(), [&](std::uint32_t i) {
    const Body& b = bodies[i];
    return b.type == BodyType::dynamic && b.allow_sleep && b.sleep_time >= def.time_to_sleep;
  });
  if (!some_rested) {
    wake_reached_islands();
    return;
  }
  std::size_t islands = 0;
  // Indexed: waking appends to the list, and the woken are reached by the walk anyway.
  for (std::size_t k = 0, listed = awake_list.size(); k < listed; ++k) {
    const std::uint32_t start = awake_list[k];
    const Body& first = bodies[start];
    if (first.type != BodyType::dynamic || island_stamp[start] == step_count) continue;
    island_members.clear();
    island_stack.assign(1, start);
    island_stamp[start] = step_count;
    Real min_sleep = def.time_to_sleep;
    while (!island_stack.empty()) {
      const std::uint32_t i = island_stack.back();
      island_stack.pop_back();
      island_members.push_back(i);
      Body& b = bodies[i];
      min_sleep = std::min(min_sleep, b.allow_sleep ? b.sleep_time : Real{0});
      const auto reach = [&](std::uint32_t j) {
        const Body& other = bodies[j];
        if (other.type != BodyType::dynamic || !other.enabled || island_stamp[j] == step_count) {
          return;
        }
        island_stamp[j] = step_count;
        island_stack.push_back(j);
      };
      // Contacts with points link bodies, speculative ones included: a body closing on a
      // sleeping one wakes it before they meet, rather than meeting it as if it were static.
      for (const std::uint32_t ci : b.contacts) {
        const Contact& c = contacts[ci];
        if (c.manifold.point_count > 0) reach(c.body_a == i ? c.body_b : c.body_a);
      }
      for (const std::uint32_t ji : b.joints) {
        const detail::Joint& joint = joints[ji];
        for (int m = 0; m < joint.body_count; ++m) {
          const Body& other = bodies[joint.body[m]];
          // A moving kinematic body keeps what it is jointed to awake, as what it touches.
          if (other.type == BodyType::kinematic &&
              (other.velocity.squaredNorm() > 0 || other.angular_velocity != 0)) {
            b.sleep_time = 0;
            min_sleep = 0;
          }
          reach(joint.body[m]);
        }
      }
    }
    const bool awake = min_sleep < def.time_to_sleep;
    if (awake) ++islands;
    for (const std::uint32_t i : island_members) {
      Body& b = bodies[i];
      if (awake && !b.awake) {
        b.awake = true;
        add_to_awake_list(b);
        woken.push_back(i);
      } else if (!awake && b.awake) {
        b.velocity = Vec2(0, 0);
        b.angular_velocity = 0;
        b.awake = false;
        fell_asleep.push_back(i);
      }
    }
  }
  std::sort(fell_asleep.begin(), fell_asleep.end());
  join_woken_contacts();
  counters.islands = islands;
}

// Contacts among the bodies this pass woke join the step (with the manifolds they slept with).
void WorldState::join_woken_contacts() {
  if (woken.empty()) return;
  for (const std::uint32_t i : woken) mark_step_contacts(bodies[i]);
  collect_step_contacts();
}

// The island pass when every island stays awake: it wakes every sleeping body that an awake
// one reaches through contacts with points and joints (as the walk does, islands of awake
// bodies being awake), and counts the islands by joining bodies along the same links.
void WorldState::wake_reached_islands() {
  island_parent.resize(bodies.size());
  const auto find = [&](std::uint32_t i) {
    while (island_parent[i] != i) i = island_parent[i] = island_parent[island_parent[i]];
    return i;
  };
  const auto join = [&](std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a != b) island_parent[std::max(a, b)] = std::min(a, b);
  };
  const auto links = [&](const Body& b) { return b.type == BodyType::dynamic && b.enabled; };
  for (const std::uint32_t i : awake_list) {
    if (bodies[i].type != BodyType::dynamic) continue;
    island_parent[i] = i;
    island_stamp[i] = step_count;
  }
  // A sleeping body reached wakes with everything its sleeping island holds.
  const auto wake_from = [&](std::uint32_t start) {
    island_stack.assign(1, start);
    island_stamp[start] = step_count;
    island_parent[start] = start;
    while (!island_stack.empty()) {
      const std::uint32_t i = island_stack.back();
      island_stack.pop_back();
      Body& b = bodies[i];
      b.awake = true;
      add_to_awake_list(b);
      woken.push_back(i);
      const auto reach = [&](std::uint32_t j) {
        if (!links(bodies[j])) return;
        if (island_stamp[j] != step_count) {
          island_stamp[j] = step_count;
          island_parent[j] = j;
          island_stack.push_back(j);
        }
        join(i, j);
      };
      for (const std::uint32_t ci : b.contacts) {
        const Contact& c = contacts[ci];
        if (c.manifold.point_count > 0) reach(c.body_a == i ? c.body_b : c.body_a);
      }
      for (const std::uint32_t ji : b.joints) {
        const detail::Joint& joint = joints[ji];
        for (int m = 0; m < joint.body_count; ++m) {
          const Body& other = bodies[joint.body[m]];
          if (other.type == BodyType::kinematic &&
              (other.velocity.squaredNorm() > 0 || other.angular_velocity != 0)) {
            b.sleep_time = 0;
          }
          reach(joint.body[m]);
        }
      }
    }
  };
  const auto link = [&](std::uint32_t a, std::uint32_t b) {
    if (!links(bodies[a]) || !links(bodies[b])) return;
    if (island_stamp[a] != step_count) wake_from(a);
    if (island_stamp[b] != step_count) wake_from(b);
    join(a, b);
  };
  for (const std::uint32_t ci : step_contacts) {
    const Contact& c = contacts[ci];
    if (c.manifold.point_count > 0) link(c.body_a, c.body_b);
  }
  for (std::size_t k = 0, listed = awake_list.size(); k < listed; ++k) {
    const std::uint32_t i = awake_list[k];
    Body& b = bodies[i];
    if (b.type != BodyType::dynamic) continue;
    for (const std::uint32_t ji : b.joints) {
      const detail::Joint& joint = joints[ji];
      for (int m = 0; m < joint.body_count; ++m) {
        const Body& other = bodies[joint.body[m]];
        // A moving kinematic body keeps what it is jointed to awake, as the walk has it.
        if (other.type == BodyType::kinematic &&
            (other.velocity.squaredNorm() > 0 || other.angular_velocity != 0)) {
          b.sleep_time = 0;
        }
        link(i, joint.body[m]);
      }
    }
  }
  std::size_t islands = 0;
  for (const std::uint32_t i : awake_list) {
    if (bodies[i].type == BodyType::dynamic && island_stamp[i] == step_count && find(i) == i) {
      ++islands;
    }
  }
  join_woken_contacts();
  counters.islands = islands;
}

}  // namespace mink
