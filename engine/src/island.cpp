// Islands and sleep: bodies joined by touching contacts sleep and wake together.

#include <algorithm>

#include "world_state.hpp"

namespace mink {

using detail::Body;
using detail::Contact;

// An island is a group of dynamic bodies linked by contacts with points (speculative ones
// included: a body closing on a sleeping one wakes it before they meet, rather than meeting it
// as if it were static) and by joints. An island sleeps when all its bodies have been slow for
// time_to_sleep, and wakes as a whole when any member is moving (woken by the API, hit by an
// awake body or a moving kinematic body).
//
// Islands are found from the awake bodies only, by union-find over the step's contacts and
// the awake bodies' joints: sequential passes over compact lists, where a walk from body to
// body through their contact lists cost as much as the narrowphase in busy scenes. A sleeping
// island is entered only where an awake body reaches it (its members then share the awake
// body's island and its fate); one that nothing reaches is never visited and costs nothing.
void WorldState::update_islands() {
  if (island_stamp.size() < bodies.size()) island_stamp.resize(bodies.size(), ~std::uint64_t{0});
  woken.clear();
  island_parent.resize(bodies.size());
  island_sleep.resize(bodies.size());
  island_members.clear();
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
  const auto enter = [&](std::uint32_t i) {
    island_stamp[i] = step_count;
    island_parent[i] = i;
    island_members.push_back(i);
  };
  // A moving kinematic body keeps what it is jointed to awake, as what it touches.
  const auto kept_awake_by_joint = [&](Body& b, const detail::JointBodies& joint) {
    for (std::uint32_t m = 0; m < joint.count; ++m) {
      const Body& other = bodies[joint.body[m]];
      if (other.type == BodyType::kinematic &&
          (other.velocity.squaredNorm() > 0 || other.angular_velocity != 0)) {
        b.sleep_time = 0;
      }
    }
  };
  const std::size_t listed = awake_list.size();
  for (std::size_t k = 0; k < listed; ++k) {
    if (bodies[awake_list[k]].type == BodyType::dynamic) enter(awake_list[k]);
  }
  // The sleeping island of `start`, reached from an awake body: its contacts are not among
  // the step's, so it is walked.
  const auto enter_sleeping_island = [&](std::uint32_t start) {
    island_stack.assign(1, start);
    enter(start);
    while (!island_stack.empty()) {
      const std::uint32_t i = island_stack.back();
      island_stack.pop_back();
      Body& b = bodies[i];
      const auto reach = [&](std::uint32_t j) {
        if (!links(bodies[j])) return;
        if (island_stamp[j] != step_count) {
          enter(j);
          island_stack.push_back(j);
        }
        join(i, j);
      };
      for (const std::uint32_t ci : b.contacts) {
        const Contact& c = contacts[ci];
        if (c.manifold.point_count > 0) reach(c.body_a == i ? c.body_b : c.body_a);
      }
      for (const std::uint32_t ji : b.joints) {
        const detail::JointBodies& joint = joint_bodies[ji];
        kept_awake_by_joint(b, joint);
        for (std::uint32_t m = 0; m < joint.count; ++m) reach(joint.body[m]);
      }
    }
  };
  const auto join_dynamic = [&](std::uint32_t a, std::uint32_t b) {
    if (island_stamp[a] != step_count) enter_sleeping_island(a);
    if (island_stamp[b] != step_count) enter_sleeping_island(b);
    join(a, b);
  };
  const auto link = [&](std::uint32_t a, std::uint32_t b) {
    if (links(bodies[a]) && links(bodies[b])) join_dynamic(a, b);
  };
  // A contact between two dynamic bodies (both enabled: disabling a body destroys its
  // contacts) links them by its flags alone, without a read of either body's record.
  for (const std::uint32_t ci : step_contacts) {
    const Contact& c = contacts[ci];
    if (!c.a_fixed && !c.b_fixed) {
      if (c.manifold.point_count > 0) join_dynamic(c.body_a, c.body_b);
      continue;
    }
    // A moving kinematic body keeps what it touches awake.
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
  // Joints in slot order from their compact copies, not through each body's list (a cache
  // miss on the joint's record per visit): each joint of a body in an island links it to its
  // other bodies. A body entered during this pass had its joints walked then; walking them
  // again changes nothing.
  for (const detail::JointBodies& joint : joint_bodies) {
    for (std::uint32_t k = 0; k < joint.count; ++k) {
      const std::uint32_t i = joint.body[k];
      if (island_stamp[i] != step_count) continue;
      kept_awake_by_joint(bodies[i], joint);
      for (std::uint32_t m = 0; m < joint.count; ++m) link(i, joint.body[m]);
    }
  }

  // Each island's shortest rest, then its fate.
  for (const std::uint32_t i : island_members) island_sleep[i] = def.time_to_sleep;
  for (const std::uint32_t i : island_members) {
    const Body& b = bodies[i];
    Real& rest = island_sleep[find(i)];
    rest = std::min(rest, b.allow_sleep ? b.sleep_time : Real{0});
  }
  std::size_t islands = 0;
  for (const std::uint32_t i : island_members) {
    const std::uint32_t root = find(i);
    const bool awake = island_sleep[root] < def.time_to_sleep;
    if (awake && root == i) ++islands;
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

}  // namespace mink
