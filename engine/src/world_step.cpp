// One fixed step: pair update -> narrowphase -> islands and sleep -> soft-step solver ->
// broadphase boxes for the next step.

#include <algorithm>
#include <chrono>
#include <cmath>

#include "world_state.hpp"

namespace mink {

using detail::Body;
using detail::Contact;
using detail::Shape;

namespace {

bool moves(const Body& b) {
  return b.type != BodyType::static_body && b.awake;
}

}  // namespace

// The box the broadphase sees: the hull at the current pose, grown by the speculative
// distance and by how far the body may move in the next step, so pairs exist before the
// shapes meet even at speed.
void WorldState::update_shape_aabb(Shape& s, const Body& b, Real dt) {
  const Pose pose = b.pose();
  const auto vertices = s.hull->vertices();
  const Real c = pose.rotation.cos, sn = pose.rotation.sin;
  Real lx = 0, ly = 0, ux = 0, uy = 0;
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const Real x = c * vertices[i].x() - sn * vertices[i].y();
    const Real y = sn * vertices[i].x() + c * vertices[i].y();
    if (i == 0) {
      lx = ux = x;
      ly = uy = y;
    } else {
      lx = std::min(lx, x), ux = std::max(ux, x);
      ly = std::min(ly, y), uy = std::max(uy, y);
    }
  }
  const Real margin = 4 * def.linear_slop + dt * std::abs(b.angular_velocity) * b.extent;
  const Real sx = dt * b.velocity.x(), sy = dt * b.velocity.y();
  s.aabb.lower = Vec2(pose.position.x() + lx - margin + std::min(sx, Real{0}),
                      pose.position.y() + ly - margin + std::min(sy, Real{0}));
  s.aabb.upper = Vec2(pose.position.x() + ux + margin + std::max(sx, Real{0}),
                      pose.position.y() + uy + margin + std::max(sy, Real{0}));
}

void WorldState::destroy_contact(std::uint32_t index) {
  Contact& c = contacts[index];
  if (c.touching) end_events.push_back({shape_id(c.shape_a), shape_id(c.shape_b)});
  contact_index.erase(detail::pair_key(c.proxy_a, c.proxy_b));
  const std::uint32_t last = static_cast<std::uint32_t>(contacts.size() - 1);
  if (index != last) {
    contacts[index] = contacts[last];
    contact_index[detail::pair_key(contacts[index].proxy_a, contacts[index].proxy_b)] = index;
  }
  contacts.pop_back();
}

void WorldState::destroy_shape_contacts(std::uint32_t shape_index) {
  // Destruction is rare: a scan keeps contacts free of per-shape lists.
  for (std::uint32_t i = static_cast<std::uint32_t>(contacts.size()); i-- > 0;) {
    Contact& c = contacts[i];
    if (c.shape_a != shape_index && c.shape_b != shape_index) continue;
    wake(bodies[c.body_a]);
    wake(bodies[c.body_b]);
    destroy_contact(i);
  }
}

void WorldState::update_pairs() {
  for (ProxyId proxy : pending_proxy_destroys) broadphase.destroy_proxy(proxy);
  pending_proxy_destroys.clear();
  pair_events.begun.clear();
  pair_events.ended.clear();
  broadphase.update_pairs(pair_events);

  for (const ProxyPair& pair : pair_events.ended) {
    const auto found = contact_index.find(detail::pair_key(pair.a, pair.b));
    if (found != contact_index.end()) destroy_contact(found->second);
  }
  for (const ProxyPair& pair : pair_events.begun) {
    const auto sa = static_cast<std::uint32_t>(broadphase.user_data(pair.a));
    const auto sb = static_cast<std::uint32_t>(broadphase.user_data(pair.b));
    const Shape& shape_a = shapes[sa];
    const Shape& shape_b = shapes[sb];
    if (!shape_a.alive || !shape_b.alive || shape_a.proxy != pair.a || shape_b.proxy != pair.b) {
      continue;
    }
    if (shape_a.body == shape_b.body) continue;
    const Body& body_a = bodies[shape_a.body];
    const Body& body_b = bodies[shape_b.body];
    if (body_a.type != BodyType::dynamic && body_b.type != BodyType::dynamic) continue;
    const std::uint64_t key = detail::pair_key(pair.a, pair.b);
    if (contact_index.contains(key)) continue;
    Contact c;
    c.shape_a = sa;
    c.shape_b = sb;
    c.body_a = shape_a.body;
    c.body_b = shape_b.body;
    c.proxy_a = pair.a;
    c.proxy_b = pair.b;
    // Mixing rules as in Box2D: geometric mean of friction, the larger restitution.
    c.friction = std::sqrt(shape_a.friction * shape_b.friction);
    c.restitution = std::max(shape_a.restitution, shape_b.restitution);
    contact_index.emplace(key, static_cast<std::uint32_t>(contacts.size()));
    contacts.push_back(c);
  }
}

// Narrowphase for every contact with a moving body. A pair whose relative pose has moved
// less than a tenth of the linear slop since its manifold was computed keeps the manifold's
// features and only has its separations measured again (as persistent-manifold engines do):
// resting stacks then cost a few multiplies per point instead of a hull collision.
void WorldState::collide() {
  const Real dt = def.time_step;
  const Real touching_distance = 4 * def.linear_slop;
  const bool reuse = def.reuse_manifolds;
  const Real reuse_tolerance = 0.1 * def.linear_slop;
  for (Contact& c : contacts) {
    const Body& body_a = bodies[c.body_a];
    const Body& body_b = bodies[c.body_b];
    if (!moves(body_a) && !moves(body_b)) continue;  // asleep or static: keep as is
    const Shape& shape_a = shapes[c.shape_a];
    const Shape& shape_b = shapes[c.shape_b];
    const bool was_touching = c.touching;
    const Pose pose_a = body_a.pose(), pose_b = body_b.pose();
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

    if (same_features) {
      // Move the stored surface points with their bodies and measure again; the impulses stay.
      const Vec2 normal = ra.apply(cache.normal);
      c.manifold.normal = normal;
      for (int j = 0; j < c.manifold.point_count; ++j) {
        const Vec2 on_a = pose_a.apply(cache.on_a[j]);
        const Vec2 on_b = pose_b.apply(cache.on_b[j]);
        ManifoldPoint& p = c.manifold.points[static_cast<std::size_t>(j)];
        p.separation = normal.dot(on_b - on_a);
        p.point = 0.5 * (on_a + on_b);
      }
    } else {
      const Manifold old = c.manifold;
      const Real old_normal[2] = {c.normal_impulse[0], c.normal_impulse[1]};
      const Real old_tangent[2] = {c.tangent_impulse[0], c.tangent_impulse[1]};
      if (!shape_a.aabb.overlaps(shape_b.aabb)) {
        c.manifold.point_count = 0;
      } else {
        // Speculative distance: the base margin plus how far the pair may close this step.
        const Vec2 dv = body_b.velocity - body_a.velocity;
        const Real closing = dv.norm() + std::abs(body_a.angular_velocity) * body_a.extent +
                             std::abs(body_b.angular_velocity) * body_b.extent;
        c.manifold = collide_hulls(*shape_a.hull, pose_a, *shape_b.hull, pose_b,
                                   touching_distance + dt * closing);
      }
      cache.valid = c.manifold.point_count > 0;
      if (cache.valid) {
        cache.relative = relative;
        const Vec2 normal = c.manifold.normal;
        cache.normal = ra.apply_inverse(normal);
        for (int j = 0; j < c.manifold.point_count; ++j) {
          const ManifoldPoint& p = c.manifold.points[static_cast<std::size_t>(j)];
          cache.on_a[j] = pose_a.apply_inverse(p.point - 0.5 * p.separation * normal);
          cache.on_b[j] = pose_b.apply_inverse(p.point + 0.5 * p.separation * normal);
        }
      }
      // Warm start: carry the impulses of the point with the same feature id.
      for (int j = 0; j < c.manifold.point_count; ++j) {
        const ManifoldPoint& p = c.manifold.points[static_cast<std::size_t>(j)];
        c.normal_impulse[j] = 0;
        c.tangent_impulse[j] = 0;
        for (int k = 0; k < old.point_count; ++k) {
          if (old.points[static_cast<std::size_t>(k)].id == p.id) {
            c.normal_impulse[j] = old_normal[k];
            c.tangent_impulse[j] = old_tangent[k];
            break;
          }
        }
      }
    }

    bool touching = false;
    for (int j = 0; j < c.manifold.point_count; ++j) {
      const ManifoldPoint& p = c.manifold.points[static_cast<std::size_t>(j)];
      touching = touching || p.separation < touching_distance;
    }
    c.touching = touching;
    if (touching && !was_touching) {
      begin_events.push_back({shape_id(c.shape_a), shape_id(c.shape_b)});
    } else if (!touching && was_touching) {
      end_events.push_back({shape_id(c.shape_a), shape_id(c.shape_b)});
    }
  }
}

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
    if (!b.alive || b.type != BodyType::dynamic) continue;
    const std::uint32_t root = find_root(island_parent, i);
    island_min_sleep[root] = std::min(island_min_sleep[root], b.allow_sleep ? b.sleep_time : 0);
  }
  std::size_t islands = 0;
  for (std::uint32_t i = 0; i < n; ++i) {
    Body& b = bodies[i];
    if (!b.alive || b.type != BodyType::dynamic) continue;
    const std::uint32_t root = find_root(island_parent, i);
    const bool awake = island_min_sleep[root] < def.time_to_sleep;
    if (awake && root == i) ++islands;
    if (!awake && b.awake) {
      b.velocity = Vec2(0, 0);
      b.angular_velocity = 0;
    }
    b.awake = awake;
  }
  counters.islands = islands;
}

void WorldState::prepare_contacts() {
  const Real dt = def.time_step;
  const Real h = dt / def.substeps;

  // Solver bodies: every awake body that moves, then one still body standing in for static
  // and sleeping ones.
  solver_bodies.clear();
  solver_params.clear();
  solver_to_body.clear();
  solver_info.clear();
  body_solver_index.resize(bodies.size());
  for (std::uint32_t i = 0; i < bodies.size(); ++i) {
    const Body& b = bodies[i];
    body_solver_index[i] = -1;
    if (!b.alive || !moves(b)) continue;
    body_solver_index[i] = static_cast<std::int32_t>(solver_bodies.size());
    solver_info.push_back({b.center.x(), b.center.y(), b.inv_mass, b.inv_inertia});
    detail::SolverBody sb;
    sb.vx = b.velocity.x();
    sb.vy = b.velocity.y();
    sb.w = b.angular_velocity;
    solver_bodies.push_back(sb);
    detail::SolverBodyParams p;
    if (b.type == BodyType::dynamic) {
      const Vec2 dv = h * (b.inv_mass * b.force + b.gravity_scale * def.gravity);
      p.dvx = dv.x();
      p.dvy = dv.y();
      p.dw = h * b.inv_inertia * b.torque;
      p.linear_damping = 1 / (1 + h * b.linear_damping);
      p.angular_damping = 1 / (1 + h * b.angular_damping);
    }
    solver_params.push_back(p);
    solver_to_body.push_back(i);
  }
  const auto still = static_cast<std::int32_t>(solver_bodies.size());
  solver_bodies.emplace_back();
  solver_params.emplace_back();
  counters.awake_bodies = solver_to_body.size();

  const Real contact_hertz = std::min(def.contact_hertz, 0.25 * def.substeps / dt);
  const detail::Softness soft = detail::make_softness(contact_hertz, def.contact_damping_ratio, h);
  const detail::Softness static_soft =
      detail::make_softness(2 * contact_hertz, def.contact_damping_ratio, h);

  // Which contacts become constraints, and between which solver bodies: the solver colours
  // them first, then each constraint is built straight into its slot.
  constraint_contacts.clear();
  constraint_bodies.clear();
  for (std::uint32_t ci = 0; ci < contacts.size(); ++ci) {
    const Contact& c = contacts[ci];
    if (c.manifold.point_count == 0) continue;
    const std::int32_t ia = body_solver_index[c.body_a], ib = body_solver_index[c.body_b];
    if (ia < 0 && ib < 0) continue;
    constraint_contacts.push_back(ci);
    // The still body is fixed as well (the colouring relies on it), so only the records of
    // moving bodies are read.
    constraint_bodies.push_back({ia < 0 ? still : ia, ib < 0 ? still : ib,
                                 ia < 0 || bodies[c.body_a].type != BodyType::dynamic,
                                 ib < 0 || bodies[c.body_b].type != BodyType::dynamic});
  }
  // Constraints in order of their first moving body (a stable counting sort): neighbouring
  // constraints then touch neighbouring bodies and the solver's gathers stay in cache.
  {
    const std::size_t n = constraint_contacts.size();
    sort_count.assign(solver_bodies.size() + 1, 0);
    const auto key = [&](const detail::ConstraintBodies& cb) {
      return static_cast<std::size_t>(cb.a == still ? cb.b : cb.a);
    };
    for (const detail::ConstraintBodies& cb : constraint_bodies) ++sort_count[key(cb) + 1];
    for (std::size_t i = 1; i < sort_count.size(); ++i) sort_count[i] += sort_count[i - 1];
    sorted_contacts.resize(n);
    sorted_bodies.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint32_t at = sort_count[key(constraint_bodies[i])]++;
      sorted_contacts[at] = constraint_contacts[i];
      sorted_bodies[at] = constraint_bodies[i];
    }
    constraint_contacts.swap(sorted_contacts);
    constraint_bodies.swap(sorted_bodies);
  }
  contact_solver.begin(constraint_bodies, still, solver_bodies.size(), def.simd_solver);

  // Per-constraint body data comes from the compact solver arrays, not the body records.
  const auto info = [&](std::uint32_t body, std::int32_t index) {
    if (index != still) return solver_info[static_cast<std::size_t>(index)];
    return detail::SolverBodyInfo{bodies[body].center.x(), bodies[body].center.y(), 0, 0};
  };
  detail::ContactConstraint k;
  for (std::uint32_t r = 0; r < constraint_contacts.size(); ++r) {
    const Contact& c = contacts[constraint_contacts[r]];
    const detail::ConstraintBodies& cb = constraint_bodies[r];
    const detail::SolverBodyInfo a = info(c.body_a, cb.a), b = info(c.body_b, cb.b);
    k.body_a = cb.a;
    k.body_b = cb.b;
    k.inv_mass_a = a.inv_mass;
    k.inv_inertia_a = a.inv_inertia;
    k.inv_mass_b = b.inv_mass;
    k.inv_inertia_b = b.inv_inertia;
    k.nx = c.manifold.normal.x();
    k.ny = c.manifold.normal.y();
    k.dx = a.cx - b.cx;
    k.dy = a.cy - b.cy;
    k.friction = c.friction;
    k.restitution = c.restitution;
    const detail::Softness& s = (k.inv_mass_a == 0 || k.inv_mass_b == 0) ? static_soft : soft;
    k.bias_rate = s.bias_rate;
    k.mass_scale = s.mass_scale;
    k.impulse_scale = s.impulse_scale;
    k.point_count = c.manifold.point_count;
    const Real tx = k.ny, ty = -k.nx;
    const detail::SolverBody& sa = solver_bodies[static_cast<std::size_t>(k.body_a)];
    const detail::SolverBody& sb = solver_bodies[static_cast<std::size_t>(k.body_b)];
    if (k.point_count < 2) k.points[1] = detail::ContactConstraintPoint{};
    for (int j = 0; j < k.point_count; ++j) {
      const ManifoldPoint& mp = c.manifold.points[static_cast<std::size_t>(j)];
      detail::ContactConstraintPoint& p = k.points[j];
      p.ax = mp.point.x() - a.cx;
      p.ay = mp.point.y() - a.cy;
      // Through the centre offset, as the wide solver recomputes it (same bits).
      p.bx = p.ax + k.dx;
      p.by = p.ay + k.dy;
      p.base_separation = mp.separation - ((p.bx - p.ax) * k.nx + (p.by - p.ay) * k.ny);
      const Real rna = p.ax * k.ny - p.ay * k.nx;
      const Real rnb = p.bx * k.ny - p.by * k.nx;
      const Real kn =
          k.inv_mass_a + k.inv_mass_b + k.inv_inertia_a * rna * rna + k.inv_inertia_b * rnb * rnb;
      p.normal_mass = kn > 0 ? 1 / kn : 0;
      const Real rta = p.ax * ty - p.ay * tx;
      const Real rtb = p.bx * ty - p.by * tx;
      const Real kt =
          k.inv_mass_a + k.inv_mass_b + k.inv_inertia_a * rta * rta + k.inv_inertia_b * rtb * rtb;
      p.tangent_mass = kt > 0 ? 1 / kt : 0;
      p.normal_impulse = c.normal_impulse[j];
      p.tangent_impulse = c.tangent_impulse[j];
      p.max_normal_impulse = 0;
      const Real dvx = (sb.vx - sb.w * p.by) - (sa.vx - sa.w * p.ay);
      const Real dvy = (sb.vy + sb.w * p.bx) - (sa.vy + sa.w * p.ax);
      p.relative_velocity = dvx * k.nx + dvy * k.ny;
    }
    contact_solver.set(r, k);
  }
  contact_solver.finish();

  counters.constraint_colors = contact_solver.color_count();
  counters.overflow_constraints = contact_solver.overflow_count();
}

void WorldState::solve() {
  const Real h = def.time_step / def.substeps;
  detail::SolverSettings settings;
  settings.h = h;
  settings.inv_h = 1 / h;
  settings.max_linear_speed = def.max_linear_speed;
  settings.contact_push_max_velocity = def.contact_push_max_velocity;
  settings.restitution_threshold = def.restitution_threshold;
  settings.substeps = def.substeps;
  contact_solver.solve(solver_bodies, solver_params, settings);

  for (std::uint32_t r = 0; r < constraint_contacts.size(); ++r) {
    Contact& c = contacts[constraint_contacts[r]];
    contact_solver.impulses(r, c.normal_impulse, c.tangent_impulse);
  }

  // Write poses back: centre moved by dp, rotation composed with the step's rotation.
  for (std::size_t si = 0; si < solver_to_body.size(); ++si) {
    Body& b = bodies[solver_to_body[si]];
    const detail::SolverBody& sb = solver_bodies[si];
    b.velocity = Vec2(sb.vx, sb.vy);
    b.angular_velocity = sb.w;
    b.center += Vec2(sb.dpx, sb.dpy);
    const Real c = sb.qc * b.rotation.cos - sb.qs * b.rotation.sin;
    const Real s = sb.qs * b.rotation.cos + sb.qc * b.rotation.sin;
    const Real inv_length = 1 / std::sqrt(c * c + s * s);
    b.rotation = {c * inv_length, s * inv_length};
    b.origin = b.center - b.rotation.apply(b.local_center);
    b.force = Vec2(0, 0);
    b.torque = 0;
  }
}

void WorldState::finish_step() {
  const Real dt = def.time_step;
  const Real linear_tolerance_squared = def.linear_sleep_tolerance * def.linear_sleep_tolerance;
  const Real angular_tolerance_squared = def.angular_sleep_tolerance * def.angular_sleep_tolerance;
  for (const std::uint32_t i : solver_to_body) {
    Body& b = bodies[i];
    for (std::uint32_t s : b.shapes) {
      update_shape_aabb(shapes[s], b, dt);
      broadphase.move_proxy(shapes[s].proxy, shapes[s].aabb);
    }
    if (!def.enable_sleep || !b.allow_sleep || b.type != BodyType::dynamic ||
        b.velocity.squaredNorm() > linear_tolerance_squared ||
        b.angular_velocity * b.angular_velocity > angular_tolerance_squared) {
      b.sleep_time = 0;
    } else {
      b.sleep_time += dt;
    }
  }
  std::size_t touching = 0;
  for (const Contact& c : contacts) touching += c.touching ? 1 : 0;
  counters.broadphase_pairs = broadphase.pairs().size();
  counters.contacts = contacts.size();
  counters.touching_contacts = touching;
}

void World::run_step(bool clear_events) {
  WorldState& w = *state_;
  if (clear_events) {
    w.begin_events.clear();
    w.end_events.clear();
  }
  using Clock = std::chrono::steady_clock;
  const auto ms = [](Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double, std::milli>(b - a).count();
  };
  const auto t0 = Clock::now();
  w.update_pairs();
  const auto t1 = Clock::now();
  w.collide();
  const auto t2 = Clock::now();
  if (w.def.enable_sleep) {
    w.update_islands();
  } else {
    w.counters.islands = 0;
  }
  const auto t3 = Clock::now();
  w.prepare_contacts();
  const auto t4 = Clock::now();
  w.solve();
  const auto t5 = Clock::now();
  w.finish_step();
  const auto t6 = Clock::now();
  w.profile = {ms(t0, t1), ms(t1, t2), ms(t2, t3), ms(t3, t4), ms(t4, t5), ms(t5, t6)};
  w.time += w.def.time_step;
  ++w.step_count;
}

}  // namespace mink
