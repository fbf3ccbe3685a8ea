// Contacts: made when the broadphase reports a pair that may touch, updated by the
// narrowphase every step, ended with their pair; begin and end events.

#include "contact.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <vector>

#include "mink/narrowphase/collide.hpp"
#include "prefetch.hpp"
#include "world_state.hpp"

namespace mink {

using detail::Body;
using detail::Contact;
using detail::Shape;

namespace {

// How many contacts ahead the narrowphase asks for a contact's record (and half as many for
// its bodies and shapes).
constexpr std::uint32_t kCollideAhead = 8;
// Awake bodies ahead of the one whose contacts are being marked.
constexpr std::uint32_t kMarkAhead = 16;

// Lists the contact in the body's contacts; returns where.
std::uint32_t add_contact_to(Body& body, std::uint32_t contact, bool other_fixed) {
  body.contacts.push_back(contact);
  body.fixed_contacts += other_fixed ? 1 : 0;
  return static_cast<std::uint32_t>(body.contacts.size() - 1);
}

}  // namespace

// Takes the contact at `slot` out of body `index`'s list, the list's last taking its place.
void WorldState::remove_contact_from(std::uint32_t index, std::uint32_t slot, bool other_fixed) {
  Body& body = bodies[index];
  const std::uint32_t moved = body.contacts.back();
  body.contacts[slot] = moved;
  body.contacts.pop_back();
  contact_slots[moved][contacts[moved].body_a == index ? 0 : 1] = slot;
  body.fixed_contacts -= other_fixed ? 1 : 0;
}

void WorldState::rebuild_contact_slots() {
  contact_slots.assign(contacts.size(), {0, 0});
  for (std::uint32_t b = 0; b < bodies.size(); ++b) {
    const std::vector<std::uint32_t>& list = bodies[b].contacts;
    for (std::uint32_t k = 0; k < list.size(); ++k) {
      contact_slots[list[k]][contacts[list[k]].body_a == b ? 0 : 1] = k;
    }
  }
}

void WorldState::set_touching(Contact& c, bool touching) {
  if (c.touching == touching) return;
  c.touching = touching;
  if (touching) {
    ++touching_count;
  } else {
    --touching_count;
  }
}

void WorldState::update_color(std::uint32_t index) {
  Contact& c = contacts[index];
  const bool acting = c.manifold.point_count > 0;
  if (acting && c.color == detail::kNoColor) {
    newly_acting.push_back(index);
  } else if (!acting && c.color != detail::kNoColor) {
    graph.remove(c.color, c.body_a, c.a_fixed, c.body_b, c.b_fixed);
    c.color = detail::kNoColor;
  }
}

// Colours for the contacts that began acting this step, given in the order of their first
// dynamic body (then contact order): bodies made bottom row first then take the low colours
// bottom up, which Gauss-Seidel needs to carry a stack's weight down in few iterations.
void WorldState::assign_new_colors() {
  const auto key = [&](std::uint32_t index) {
    const Contact& c = contacts[index];
    return bodies[c.body_a].type == BodyType::dynamic ? c.body_a : c.body_b;
  };
  std::sort(newly_acting.begin(), newly_acting.end(), [&](std::uint32_t x, std::uint32_t y) {
    const std::uint32_t kx = key(x), ky = key(y);
    return kx != ky ? kx < ky : x < y;
  });
  for (const std::uint32_t index : newly_acting) {
    Contact& c = contacts[index];
    c.color = graph.add(c.body_a, c.a_fixed, c.body_b, c.b_fixed);
  }
  newly_acting.clear();
}

void WorldState::destroy_contact(std::uint32_t index) {
  Contact& c = contacts[index];
  if (c.color != detail::kNoColor) {
    graph.remove(c.color, c.body_a, c.a_fixed, c.body_b, c.b_fixed);
  }
  if (c.touching && c.events) end_events.push_back({shape_id(c.shape_a), shape_id(c.shape_b)});
  set_touching(c, false);
  contact_index.erase(detail::pair_key(c.proxy_a, c.proxy_b));
  remove_contact_from(c.body_a, contact_slots[index][0], c.b_fixed);
  remove_contact_from(c.body_b, contact_slots[index][1], c.a_fixed);
  const std::uint32_t last = static_cast<std::uint32_t>(contacts.size() - 1);
  if (index != last) {
    contacts[index] = contacts[last];
    contact_impulses[index] = contact_impulses[last];
    contact_slots[index] = contact_slots[last];
    const Contact& moved = contacts[index];
    contact_index.set(detail::pair_key(moved.proxy_a, moved.proxy_b), index);
    bodies[moved.body_a].contacts[contact_slots[index][0]] = index;
    bodies[moved.body_b].contacts[contact_slots[index][1]] = index;
  }
  contacts.pop_back();
  contact_impulses.pop_back();
  contact_slots.pop_back();
}

namespace {

// Destroys the contacts of `body` that `doomed` picks, waking their bodies. Highest index
// first, so the swap-removal never moves a contact still to be visited.
template <typename Pick>
void destroy_body_contacts(WorldState& w, std::uint32_t body, Pick doomed) {
  std::vector<std::uint32_t> picked;
  for (const std::uint32_t i : w.bodies[body].contacts) {
    if (doomed(w.contacts[i])) picked.push_back(i);
  }
  std::sort(picked.begin(), picked.end(), std::greater<>());
  for (const std::uint32_t i : picked) {
    w.wake(w.bodies[w.contacts[i].body_a]);
    w.wake(w.bodies[w.contacts[i].body_b]);
    w.destroy_contact(i);
  }
}

}  // namespace

void WorldState::destroy_shape_contacts(std::uint32_t shape_index) {
  destroy_body_contacts(*this, shapes[shape_index].body, [&](const Contact& c) {
    return c.shape_a == shape_index || c.shape_b == shape_index;
  });
}

void WorldState::destroy_contacts_between(std::uint32_t body_a, std::uint32_t body_b) {
  destroy_body_contacts(*this, body_a, [&](const Contact& c) {
    return (c.body_a == body_a && c.body_b == body_b) || (c.body_a == body_b && c.body_b == body_a);
  });
}

// Sensors never make contacts (they are tested in the sensor pass), and neither do two
// shapes of one body, two bodies that cannot move, or shapes their filters keep apart.
bool WorldState::should_make_contact(std::uint32_t sa, std::uint32_t sb) const {
  const Shape& shape_a = shapes[sa];
  const Shape& shape_b = shapes[sb];
  if (shape_a.sensor || shape_b.sensor || shape_a.body == shape_b.body) return false;
  const Body& body_a = bodies[shape_a.body];
  const Body& body_b = bodies[shape_b.body];
  if (body_a.type != BodyType::dynamic && body_b.type != BodyType::dynamic) return false;
  if (shape_a.type == ShapeType::chain && shape_b.type == ShapeType::chain) return false;
  if (!should_collide(shape_a.filter, shape_b.filter)) return false;
  return !joint_prevents_contact(shape_a.body, shape_b.body);
}

void WorldState::update_pairs() {
  for (ProxyId proxy : pending_proxy_destroys) broadphase.destroy_proxy(proxy);
  pending_proxy_destroys.clear();
  pair_events.begun.clear();
  pair_events.ended.clear();
  SweepAndPrune::Ranges ranges;
  ranges.workers = tasks.workers();
  ranges.run = [&](std::uint32_t count, std::uint32_t min_range,
                   const SweepAndPrune::RangeBody& body) {
    tasks.parallel_for(count, min_range,
                       [&](std::uint32_t begin, std::uint32_t end, std::uint32_t worker) {
                         body(begin, end, worker);
                       });
  };
  broadphase.update_pairs(pair_events, ranges);
  // The broadphase reports pairs in its sweep order, which follows the coordinates rounded to
  // floats; taken in id order instead, contacts are made and removed, and so coloured and
  // solved, in an order that does not depend on where the scene lies (10^7 m from the origin
  // float keys tie where they did not at the origin).
  const auto by_ids = [](const ProxyPair& x, const ProxyPair& y) {
    return x.a != y.a ? x.a < y.a : x.b < y.b;
  };
  std::sort(pair_events.ended.begin(), pair_events.ended.end(), by_ids);
  std::sort(pair_events.begun.begin(), pair_events.begun.end(), by_ids);

  for (const ProxyPair& pair : pair_events.ended) {
    const std::uint32_t found = contact_index.find(detail::pair_key(pair.a, pair.b));
    if (found != detail::ContactMap::kNone) destroy_contact(found);
  }
  for (const ProxyPair& pair : pair_events.begun) {
    const auto sa = static_cast<std::uint32_t>(broadphase.user_data(pair.a));
    const auto sb = static_cast<std::uint32_t>(broadphase.user_data(pair.b));
    const Shape& shape_a = shapes[sa];
    const Shape& shape_b = shapes[sb];
    if (!shape_a.alive || !shape_b.alive || shape_a.proxy != pair.a || shape_b.proxy != pair.b) {
      continue;
    }
    if (!should_make_contact(sa, sb)) continue;
    const std::uint64_t key = detail::pair_key(pair.a, pair.b);
    if (contact_index.contains(key)) continue;
    Contact c;
    c.shape_a = sa;
    c.shape_b = sb;
    c.body_a = shape_a.body;
    c.body_b = shape_b.body;
    c.proxy_a = pair.a;
    c.proxy_b = pair.b;
    c.friction = detail::mix_friction(shape_a.friction, shape_b.friction);
    c.restitution = detail::mix_restitution(shape_a.restitution, shape_b.restitution);
    c.events = shape_a.contact_events && shape_b.contact_events;
    c.hit_events = shape_a.hit_events || shape_b.hit_events;
    c.sharp_polygons = detail::sharp_polygon_pair(shape_a, shape_b);
    c.a_fixed = bodies[c.body_a].type != BodyType::dynamic;
    c.b_fixed = bodies[c.body_b].type != BodyType::dynamic;
    const auto index = static_cast<std::uint32_t>(contacts.size());
    contact_index.set(key, index);
    contacts.push_back(c);
    contact_impulses.emplace_back();
    contact_slots.push_back({add_contact_to(bodies[c.body_a], index, c.b_fixed),
                             add_contact_to(bodies[c.body_b], index, c.a_fixed)});
  }
}

namespace {

// The fastest normal approach over the manifold's points, from the velocities before the
// solve (a hit is judged by how fast the shapes met, not by what the solver left).
void measure_approach(Contact& c, const Body& a, const Body& b) {
  c.approach_speed = 0;
  for (int j = 0; j < c.manifold.point_count; ++j) {
    const Vec2& p = c.manifold.points[static_cast<std::size_t>(j)].point;
    const Vec2 ra = p - a.center, rb = p - b.center;
    const Vec2 va = a.velocity + a.angular_velocity * Vec2(-ra.y(), ra.x());
    const Vec2 vb = b.velocity + b.angular_velocity * Vec2(-rb.y(), rb.x());
    const Real approach = -(vb - va).dot(c.manifold.normal);
    if (approach > c.approach_speed) {
      c.approach_speed = approach;
      c.approach_point = p;
    }
  }
}

}  // namespace

// One contact's narrowphase (collide() below): its manifold, warm-start impulses and
// manifold cache, written to the contact alone so contacts can be collided in parallel.
// Returns whether the shapes now touch.
bool WorldState::update_manifold(Contact& c, detail::ContactImpulses& impulses) const {
  const Real touching_distance = 4 * def.linear_slop;
  const bool reuse = def.reuse_manifolds;
  // A pair not yet touching must not miss its contact: it may move at most the touching
  // distance.
  const Real reuse_tolerance = c.touching
                                   ? def.manifold_reuse_distance
                                   : std::min(def.manifold_reuse_distance, touching_distance);
  const Body& body_a = bodies[c.body_a];
  const Body& body_b = bodies[c.body_b];
  const Shape& shape_a = shapes[c.shape_a];
  const Shape& shape_b = shapes[c.shape_b];
  // The pair is measured from A's origin, not the world's, so that where it lies does not
  // round what is found (world_grid.hpp); its points go back to the world on the grid.
  const Vec2 frame_origin = body_a.origin;
  const Pose pose_a{Vec2(0, 0), body_a.rotation};
  const Pose pose_b{body_b.origin - frame_origin, body_b.rotation};
  const auto to_world = [&](const Vec2& p) -> Vec2 { return frame_origin + detail::on_grid(p); };
  const Rotation& ra = pose_a.rotation;
  const Pose relative = relative_pose(pose_a, pose_b);
  detail::ManifoldCache& cache = c.cache;
  bool same_features = false;
  if (reuse && cache.valid) {
    const Rotation& then = cache.relative.rotation;
    const Rotation& now = relative.rotation;
    const Real turn = std::abs(then.cos * now.sin - then.sin * now.cos);  // sin of the change
    const Vec2 moved = relative.position - cache.relative.position;
    const Real shift = std::abs(moved.x()) + std::abs(moved.y());
    same_features = shift + turn * (body_a.extent + body_b.extent) < reuse_tolerance;
  }

  c.features_kept = same_features;
  if (same_features) {
    // Move the stored surface points with their bodies and measure again; the impulses
    // stay.
    const Vec2 normal = ra.apply(cache.normal);
    c.manifold.normal = normal;
    for (int j = 0; j < c.manifold.point_count; ++j) {
      const Vec2 on_a = pose_a.apply(cache.on_a[j]);
      const Vec2 on_b = pose_b.apply(cache.on_b[j]);
      ManifoldPoint& p = c.manifold.points[static_cast<std::size_t>(j)];
      p.separation = normal.dot(on_b - on_a);
      p.point = to_world(0.5 * (on_a + on_b));
    }
  } else {
    const Manifold old = c.manifold;
    const detail::ContactImpulses old_impulses = impulses;
    // Speculative distance: the base margin plus how far the pair may close this step.
    const Vec2 dv = body_b.velocity - body_a.velocity;
    const Real closing = dv.norm() + std::abs(body_a.angular_velocity) * body_a.extent +
                         std::abs(body_b.angular_velocity) * body_b.extent;
    const Real speculative = touching_distance + dt * closing;
    // The boxes hold the shapes and the base margin: apart by more than the closing, no points.
    // A fast body's boxes are bare (finish_body): the margin they lack is added here.
    const Real bare = touching_distance * ((shape_a.bare_box ? 1 : 0) + (shape_b.bare_box ? 1 : 0));
    if (!shape_a.aabb.fattened(dt * closing + bare).overlaps(shape_b.aabb)) {
      c.manifold.point_count = 0;
    } else {
      if (c.sharp_polygons) {
        c.manifold =
            collide_hulls(std::get<RoundedPolygon>(shape_a.geometry).hull, pose_a,
                          std::get<RoundedPolygon>(shape_b.geometry).hull, pose_b, speculative);
        if (!shape_a.internal_edges.empty() || !shape_b.internal_edges.empty()) {
          smooth_seam(c, pose_a, pose_b, speculative);
        }
      } else {
        c.manifold =
            collide_shapes(shape_a.geometry, pose_a, shape_b.geometry, pose_b, speculative);
      }
    }
    cache.valid = c.manifold.point_count > 0;
    if (cache.valid) {
      cache.relative = relative;
      const Vec2 normal = c.manifold.normal;
      cache.normal = ra.apply_inverse(normal);
      for (int j = 0; j < c.manifold.point_count; ++j) {
        ManifoldPoint& p = c.manifold.points[static_cast<std::size_t>(j)];
        cache.on_a[j] = pose_a.apply_inverse(p.point - 0.5 * p.separation * normal);
        cache.on_b[j] = pose_b.apply_inverse(p.point + 0.5 * p.separation * normal);
        p.point = to_world(p.point);
      }
    }
    // Warm start: carry the impulses of the point with the same feature id.
    for (int j = 0; j < c.manifold.point_count; ++j) {
      const ManifoldPoint& p = c.manifold.points[static_cast<std::size_t>(j)];
      impulses.normal[j] = 0;
      impulses.tangent[j] = 0;
      for (int k = 0; k < old.point_count; ++k) {
        if (old.points[static_cast<std::size_t>(k)].id == p.id) {
          impulses.normal[j] = old_impulses.normal[k];
          impulses.tangent[j] = old_impulses.tangent[k];
          break;
        }
      }
    }
  }
  if (c.hit_events) measure_approach(c, body_a, body_b);

  bool touching = false;
  for (int j = 0; j < c.manifold.point_count; ++j) {
    const ManifoldPoint& p = c.manifold.points[static_cast<std::size_t>(j)];
    touching = touching || p.separation < touching_distance;
  }
  return touching;
}

// Marks the body's contacts as the step's, among `worker`'s marks.
void WorldState::mark_step_contacts(const Body& body, std::uint32_t worker) {
  for (const std::uint32_t ci : body.contacts) step_contact_marks.mark(ci, worker);
}

const LargeVector<WorldState::StepContactKey>& WorldState::current_step_contact_keys() {
  if (!step_contact_keys_valid) {
    step_contact_keys.resize(step_contacts.size());
    step_contact_seeds.resize(step_contacts.size());
    for (std::size_t k = 0; k < step_contacts.size(); ++k) {
      step_contact_keys[k] = step_contact_key(contacts[step_contacts[k]]);
      if (step_contact_keys[k].acting()) {
        step_contact_seeds[k] = step_contact_seed(step_contacts[k]);
      }
    }
    step_contact_keys_valid = true;
  }
  return step_contact_keys;
}

void WorldState::collect_step_contacts() {
  step_contacts.clear();
  step_contact_keys_valid = false;
  step_contact_marks.for_each_marked([&](std::uint32_t c) { step_contacts.push_back(c); });
}

// What a manifold's update reads of its pair's bodies (pose, velocity, extent) and shapes
// (geometry and box).
void WorldState::prefetch_pair(const Contact& c) const {
  static_assert(offsetof(Body, extent) + sizeof(Real) <= 128);
  detail::prefetch_bytes(&bodies[c.body_a], offsetof(Body, extent) + sizeof(Real));
  detail::prefetch_bytes(&bodies[c.body_b], offsetof(Body, extent) + sizeof(Real));
  detail::prefetch_bytes(&shapes[c.shape_a], offsetof(Shape, bare_box) + 1);
  detail::prefetch_bytes(&shapes[c.shape_b], offsetof(Shape, bare_box) + 1);
}

// The polygons' arrays of a pair (their first lines: all of a small polygon's), unless its
// manifold kept its features last step: resting pairs then leave them alone.
void WorldState::prefetch_hulls(const Contact& c) const {
  constexpr std::size_t kHullBytesAhead = 512;
  if (c.features_kept) return;
  for (const std::uint32_t s : {c.shape_a, c.shape_b}) {
    detail::prefetch_polygon(shapes[s], kHullBytesAhead);
  }
}

// Narrowphase for every contact with a moving body. A pair whose relative pose has moved
// less than a tenth of the linear slop since its manifold was computed keeps the manifold's
// features and only has its separations measured again (as persistent-manifold engines do):
// resting stacks then cost a few multiplies per point instead of a collision.
void WorldState::collide() {
  // The contacts of moving bodies, in contact order (the order events and the solver use),
  // marked from the bodies in parallel.
  compact_awake_list();
  step_contact_marks.reset(contacts.size(), tasks.workers());
  tasks.parallel_for(static_cast<std::uint32_t>(awake_list.size()), 256,
                     [&](std::uint32_t begin, std::uint32_t end, std::uint32_t worker) {
                       for (std::uint32_t k = begin; k < end; ++k) {
                         detail::prefetch_list_ahead(
                             k, end, kMarkAhead, [&](std::size_t i) -> const auto& {
                               return bodies[awake_list[i]].contacts;
                             });
                         mark_step_contacts(bodies[awake_list[k]], worker);
                       }
                     });
  collect_step_contacts();
  counters.collided_contacts = step_contacts.size();
  // Manifolds in parallel (each writes only its own contact), then what is shared (colours,
  // the touching count, events) in contact order, for the contacts whose state changed.
  enum : std::uint8_t { kColorChange = 1, kTouchingChange = 2 };
  collide_changes.resize(step_contacts.size());
  step_contact_keys.resize(step_contacts.size());
  step_contact_seeds.resize(step_contacts.size());
  tasks.parallel_for(static_cast<std::uint32_t>(step_contacts.size()), 64,
                     [&](std::uint32_t begin, std::uint32_t end, std::uint32_t) {
                       for (std::uint32_t k = begin; k < end; ++k) {
                         // Contacts (and their impulses, kept apart), then their bodies and
                         // shapes, asked for ahead: records scattered over memory, where the
                         // manifolds otherwise wait.
                         if (k + kCollideAhead < end) {
                           const std::uint32_t ahead = step_contacts[k + kCollideAhead];
                           detail::prefetch_bytes(&contacts[ahead], sizeof(Contact));
                           detail::prefetch_line(&contact_impulses[ahead]);
                         }
                         if (k + kCollideAhead / 2 < end) {
                           prefetch_pair(contacts[step_contacts[k + kCollideAhead / 2]]);
                         }
                         if (k + kCollideAhead / 4 < end) {
                           prefetch_hulls(contacts[step_contacts[k + kCollideAhead / 4]]);
                         }
                         const std::uint32_t ci = step_contacts[k];
                         Contact& c = contacts[ci];
                         const bool was_touching = c.touching;
                         const bool touching = update_manifold(c, contact_impulses[ci]);
                         const bool acting = c.manifold.point_count > 0;
                         collide_changes[k] = static_cast<std::uint8_t>(
                             (acting != (c.color != detail::kNoColor) ? kColorChange : 0) |
                             (touching != was_touching ? kTouchingChange : 0));
                         StepContactKey& key = step_contact_keys[k];
                         key = step_contact_key(c);
                         key.touching = touching;  // c.touching follows below
                         if (acting) step_contact_seeds[k] = step_contact_seed(ci);
                       }
                     });
  for (std::size_t k = 0; k < step_contacts.size(); ++k) {
    if (collide_changes[k] == 0) continue;
    const std::uint32_t ci = step_contacts[k];
    if (collide_changes[k] & kColorChange) update_color(ci);
    if (!(collide_changes[k] & kTouchingChange)) continue;
    Contact& c = contacts[ci];
    const bool touching = !c.touching;
    set_touching(c, touching);
    if (!c.events) continue;
    if (touching) {
      begin_events.push_back({shape_id(c.shape_a), shape_id(c.shape_b), c.manifold});
    } else {
      end_events.push_back({shape_id(c.shape_a), shape_id(c.shape_b)});
    }
  }
  assign_new_colors();
  // The colours just given or taken back, into the keys.
  for (std::size_t k = 0; k < step_contacts.size(); ++k) {
    if (collide_changes[k] & kColorChange) {
      step_contact_keys[k].color = contacts[step_contacts[k]].color;
    }
  }
  step_contact_keys_valid = true;
}

}  // namespace mink
