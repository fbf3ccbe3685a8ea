// Islands and sleep: bodies joined by touching contacts sleep and wake together.

#include <algorithm>

#include "union_find.hpp"
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
  const auto find = [&](std::uint32_t i) { return detail::find_set(island_parent, i); };
  const auto join = [&](std::uint32_t a, std::uint32_t b) {
    detail::join_sets(island_parent, a, b);
  };
  const auto links = [&](const Body& b) { return b.type == BodyType::dynamic && b.enabled; };
  const auto enter = [&](std::uint32_t i) {
    island_stamp[i] = step_count;
    island_parent[i] = i;
    island_sleep[i] = def.time_to_sleep;
    island_members.push_back(i);
  };
  const auto reached = [&](std::uint32_t i) { return island_stamp[i] == step_count; };
  // A moving kinematic body keeps what it touches or is jointed to awake.
  const auto moving_kinematic = [](const Body& b) {
    return b.type == BodyType::kinematic &&
           (b.velocity.squaredNorm() > 0 || b.angular_velocity != 0);
  };
  const auto driven = [&](const detail::JointBodies& joint) {
    return std::any_of(joint.body.begin(), joint.body.begin() + joint.count,
                       [&](std::uint32_t m) { return moving_kinematic(bodies[m]); });
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
        if (!reached(j)) {
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
        if (driven(joint)) b.sleep_time = 0;
        for (std::uint32_t m = 0; m < joint.count; ++m) reach(joint.body[m]);
      }
    }
  };
  const auto join_dynamic = [&](std::uint32_t a, std::uint32_t b) {
    if (!reached(a)) enter_sleeping_island(a);
    if (!reached(b)) enter_sleeping_island(b);
    join(a, b);
  };
  const auto link = [&](std::uint32_t a, std::uint32_t b) {
    if (links(bodies[a]) && links(bodies[b])) join_dynamic(a, b);
  };
  // A contact between two dynamic bodies (both enabled: disabling a body destroys its
  // contacts) links them by its flags alone, without a read of either body's record; the
  // flags come from the compact keys, in order.
  for (const StepContactKey& c : current_step_contact_keys()) {
    if (!c.a_fixed && !c.b_fixed) {
      if (c.acting()) join_dynamic(c.body_a, c.body_b);
      continue;
    }
    if (!c.touching) continue;
    Body& a = bodies[c.body_a];
    Body& b = bodies[c.body_b];
    const bool a_kinematic = a.type == BodyType::kinematic;
    if (moving_kinematic(a_kinematic ? a : b)) (a_kinematic ? b : a).sleep_time = 0;
  }
  // Joints in slot order from their compact copies, not through each body's list (a cache
  // miss on the joint's record per visit): a joint with a body in an island links its bodies
  // to each other. A body a link enters had its joints walked then.
  for (const detail::JointBodies& joint : joint_bodies) {
    const auto first = joint.body.begin(), last = first + joint.count;
    if (std::none_of(first, last, reached)) continue;
    if (driven(joint)) {
      for (auto i = first; i != last; ++i) {
        if (reached(*i)) bodies[*i].sleep_time = 0;
      }
    }
    for (auto i = first; i != last; ++i) {
      for (auto j = i + 1; j != last; ++j) link(*i, *j);
    }
  }

  // Each island's shortest rest, then its fate.
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
      awake_list_compact = false;
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
