// The snapshot loader's checks (snapshot_checks.hpp).

#include "snapshot_checks.hpp"

#include <cmath>
#include <iterator>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "checks.hpp"
#include "joint.hpp"
#include "snapshot_io.hpp"

namespace mink::detail {

namespace {

// Every index the step follows without checking must name a slot that exists: a snapshot
// that passes its checksum but was made by hand is refused here rather than read out of range.
void check_indices(const WorldState& w, ByteReader& in) {
  const std::size_t bodies = w.bodies.size(), shapes = w.shapes.size();
  const std::size_t joints = w.joints.size(), contacts = w.contacts.size();
  const auto below = [&](std::size_t index, std::size_t bound, const char* what) {
    if (index >= bound) in.fail(std::string(what) + " " + std::to_string(index) + " out of range");
  };
  const auto color_ok = [](std::uint8_t c) { return c <= kOverflowColor || c == kNoColor; };
  for (std::size_t i = 0; i < bodies; ++i) {
    const Body& b = w.bodies[i];
    for (const std::uint32_t s : b.shapes) below(s, shapes, "a body's shape");
    for (const std::uint32_t c : b.contacts) below(c, contacts, "a body's contact");
    for (const std::uint32_t j : b.joints) below(j, joints, "a body's joint");
  }
  for (std::size_t i = 0; i < shapes; ++i) {
    const Shape& s = w.shapes[i];
    below(s.body, bodies, "a shape's body");
    // A live shape's proxy, if it has one, is a live proxy that names it back.
    if (s.alive && s.proxy != null_proxy &&
        (!w.broadphase.is_proxy(s.proxy) || w.broadphase.user_data(s.proxy) != i)) {
      in.fail("shape " + std::to_string(i) + "'s broadphase proxy " + std::to_string(s.proxy) +
              " is not one of its own");
    }
    // Its box lies within its proxy's, as after every step and call: continuous collision
    // takes a body's broadphase boxes to cover it over a step that left none of them.
    if (s.alive && s.proxy != null_proxy && !w.broadphase.fat_aabb(s.proxy).contains(s.aabb)) {
      in.fail("shape " + std::to_string(i) + "'s box is not within its broadphase box");
    }
  }
  for (const Contact& c : w.contacts) {
    below(c.body_a, bodies, "a contact's body");
    below(c.body_b, bodies, "a contact's body");
    below(c.shape_a, shapes, "a contact's shape");
    below(c.shape_b, shapes, "a contact's shape");
    if (!color_ok(c.color)) in.fail("a contact colour out of range");
    // A contact is found by its shapes' proxies (ended pairs, the contact map): they must be
    // the live shapes' own.
    const Shape& a = w.shapes[c.shape_a];
    const Shape& b = w.shapes[c.shape_b];
    if (!a.alive || !b.alive || a.proxy != c.proxy_a || b.proxy != c.proxy_b ||
        c.proxy_a == null_proxy || c.proxy_b == null_proxy) {
      in.fail("a contact whose proxies are not its live shapes' own");
    }
    // The narrowphase takes a contact flagged as between sharp polygons to hold two hulls.
    if (c.sharp_polygons != sharp_polygon_pair(a, b)) {
      in.fail("a contact flagged unlike its shapes' kinds");
    }
  }
  for (const Joint& j : w.joints) {
    if (j.body_count < 2 || j.body_count > 4) in.fail("a joint with a bad body count");
    for (int k = 0; k < j.body_count; ++k) below(j.body[k], bodies, "a joint's body");
    for (const std::uint32_t g : j.gear_joints) below(g, joints, "a gear's joint");
    for (const std::uint32_t g : j.gears) below(g, joints, "a joint's gear");
    if (!color_ok(j.color)) in.fail("a joint colour out of range");
  }
  // Each contact is listed once by each of its two bodies, a body lists only its own, and it
  // counts those with something static or kinematic right: the step walks and edits the lists
  // by these counts without looking further.
  std::vector<std::uint32_t> listed(contacts, 0);
  for (std::size_t i = 0; i < bodies; ++i) {
    const Body& b = w.bodies[i];
    std::uint32_t fixed = 0;
    for (const std::uint32_t c : b.contacts) {
      const Contact& contact = w.contacts[c];
      if (contact.body_a != i && contact.body_b != i) {
        in.fail("body " + std::to_string(i) + " lists contact " + std::to_string(c) +
                ", which is not its own");
      }
      ++listed[c];
      fixed += (contact.body_a == i ? contact.b_fixed : contact.a_fixed) ? 1 : 0;
    }
    if (fixed != b.fixed_contacts) {
      in.fail("body " + std::to_string(i) + " counts " + std::to_string(b.fixed_contacts) +
              " contacts with something fixed and lists " + std::to_string(fixed));
    }
  }
  for (std::size_t c = 0; c < contacts; ++c) {
    const Contact& contact = w.contacts[c];
    if (contact.body_a == contact.body_b || listed[c] != 2) {
      in.fail("contact " + std::to_string(c) + " is not listed once by each of its two bodies");
    }
    // The island pass links two bodies by these flags alone, without reading the bodies: a
    // contact is between enabled bodies (disabling one destroys its contacts), and it flags
    // exactly those that are not dynamic.
    const Body& a = w.bodies[contact.body_a];
    const Body& b = w.bodies[contact.body_b];
    if (!a.enabled || !b.enabled) {
      in.fail("contact " + std::to_string(c) + " touches a disabled body");
    }
    if (contact.a_fixed != (a.type != BodyType::dynamic) ||
        contact.b_fixed != (b.type != BodyType::dynamic)) {
      in.fail("contact " + std::to_string(c) + " flags its bodies' types wrongly");
    }
  }
  for (const SensorState& s : w.sensors) below(s.shape, shapes, "a sensor shape");
  for (const std::uint32_t i : w.awake_list) below(i, bodies, "an awake body");
  for (const std::uint32_t i : w.newly_acting) below(i, contacts, "a contact waiting for a colour");
}

// The constraint graph's colours as the step takes them: no two constraints of a colour share
// a body the solver moves (a colour's are solved side by side, in SIMD lanes and on several
// workers), and the graph's bits are exactly those bodies (new constraints take their colour
// from them). A restored world keeps its colours, which fix the order of the solve.
void check_colours(const WorldState& w, ByteReader& in) {
  ConstraintGraph rebuilt;
  const auto place = [&](std::uint8_t color, std::uint32_t body_a, bool a_fixed,
                         std::uint32_t body_b, bool b_fixed, const char* kind, std::size_t index) {
    if (color >= kGraphColors || rebuilt.place(color, body_a, a_fixed, body_b, b_fixed)) return;
    in.fail(std::string(kind) + " " + std::to_string(index) + " shares colour " +
            std::to_string(color) + " with another constraint on one of its bodies");
  };
  for (std::size_t c = 0; c < w.contacts.size(); ++c) {
    const Contact& contact = w.contacts[c];
    place(contact.color, contact.body_a, contact.a_fixed, contact.body_b, contact.b_fixed,
          "contact", c);
  }
  for (std::size_t i = 0; i < w.joints.size(); ++i) {
    const Joint& j = w.joints.slots()[i];
    if (!j.alive || j.color == kNoColor) continue;
    if (j.body_count == 4) {
      // A gear's four bodies do not fit the graph's pairs: it is solved one at a time.
      if (j.color != kOverflowColor)
        in.fail("joint " + std::to_string(i) + ", a gear, is not in the overflow");
      continue;
    }
    if (j.a_fixed != (w.bodies[j.body[0]].type != BodyType::dynamic) ||
        j.b_fixed != (w.bodies[j.body[1]].type != BodyType::dynamic)) {
      in.fail("joint " + std::to_string(i) + " flags its bodies' types wrongly");
    }
    place(j.color, j.body[0], j.a_fixed, j.body[1], j.b_fixed, "joint", i);
  }
  if (!w.graph.same_colours(rebuilt)) {
    in.fail("the constraint graph's colours are not its constraints' bodies");
  }
}

// Walks a record's fields as the snapshot does and notes whether every floating-point one is
// finite. (Blocks of plain numbers go past unchecked; no record holds one of floats.)
struct FiniteWalk {
  static constexpr bool loading = false;
  struct {
    void raw(const void*, std::size_t) {}
  } out;
  bool finite = true;
  template <typename T>
  void operator()(const T& field) {
    if constexpr (std::is_floating_point_v<T>) {
      finite = finite && std::isfinite(field);
    } else if constexpr (!std::is_arithmetic_v<T> && !std::is_enum_v<T>) {
      using mink::io;  // the library types' (vectors, Vec2), which argument lookup misses here
      io(*this, const_cast<T&>(field));
    }
  }
  void count(std::size_t) {}
};

template <typename Record>
bool all_finite(const Record& record) {
  FiniteWalk walk;
  walk(record);
  return walk.finite;
}

bool unit(const Vec2& v) {
  return std::abs(v.squaredNorm() - 1) <= Real(1e-6);
}
bool unit(const Rotation& r) {
  return unit(Vec2(r.cos, r.sin));
}

// What no API call leaves in a live body. Its thinnest extent is infinite while it has no
// shape, and its continuous threshold may be infinite (never fast).
void check_body(const Body& body, const std::string& what, ByteReader& in) {
  Body finite_part = body;
  finite_part.min_extent = 0;
  finite_part.continuous_threshold = 0;
  if (!all_finite(finite_part)) in.fail(what + " holds a non-finite value");
  if (body.type > BodyType::dynamic) in.fail(what + " has no body type");
  // Shape points and mass centres lie within max_world_coordinate of their body's origin,
  // so its centre and extent reach at most a few times that far (a shape far out moves the
  // centre of an origin near the limit past it).
  if (!within_reach(body.center) || !within_world(body.origin) ||
      !within_world(body.previous_origin) || !within_world(body.local_center) ||
      body.extent > 4 * max_world_coordinate) {
    in.fail(what + " lies or reaches beyond max_world_coordinate");
  }
  if (!unit(body.rotation) || !unit(body.previous_rotation)) {
    in.fail(what + "'s rotation is not a rotation");
  }
  // (Not its rotational inertia: taken about the origin less the parallel axis term, it can
  // round below zero, and then the body does not turn.)
  const std::pair<const char*, Real> non_negative[] = {
      {"inverse mass", body.inv_mass},
      {"inverse inertia", body.inv_inertia},
      {"mass", body.mass},
      {"extent", body.extent},
      {"linear damping", body.linear_damping},
      {"angular damping", body.angular_damping},
      {"sleep time", body.sleep_time},
      {"thinnest extent", body.min_extent},
      {"continuous threshold", body.continuous_threshold}};
  for (const auto& [name, v] : non_negative) {
    if (!(v >= 0)) in.fail(what + " has a negative " + name + ", " + exact_number(v));
  }
  // The solver inverts in single precision: set_mass_data refuses less than this.
  if (body.inv_mass > 1 / min_mass_property || body.inv_inertia > 1 / min_mass_property) {
    in.fail(what + "'s mass or rotational inertia is below min_mass_property");
  }
}

void check_geometry(const ShapeGeometry& geometry, const std::string& what, ByteReader& in) {
  std::visit(
      [&](const auto& g) {
        using G = std::decay_t<decltype(g)>;
        if constexpr (std::is_same_v<G, Circle>) {
          if (!(g.radius > 0)) in.fail(what + " is a circle without a positive radius");
        } else if constexpr (std::is_same_v<G, Capsule>) {
          if (!(g.radius > 0) || g.center1 == g.center2) {
            in.fail(what + " is a capsule without a positive radius and two centres");
          }
        } else if constexpr (std::is_same_v<G, Segment>) {
          if (g.point1 == g.point2) in.fail(what + " is a segment of one point");
        } else if constexpr (std::is_same_v<G, ChainSegment>) {
          if (g.segment.point1 == g.segment.point2) in.fail(what + " is a chain link of one point");
        } else {
          if (!(g.radius >= 0)) in.fail(what + " is a polygon with a negative radius");
        }
      },
      geometry);
}

void check_shape(const Shape& shape, const std::string& what, ByteReader& in) {
  if (!all_finite(shape)) in.fail(what + " holds a non-finite value");
  if (shape.type > ShapeType::chain) in.fail(what + " has no shape type");
  // The type decides how contacts read the geometry.
  static constexpr ShapeType kTypeOf[] = {ShapeType::circle, ShapeType::capsule, ShapeType::segment,
                                          ShapeType::chain, ShapeType::polygon};
  static_assert(std::variant_size_v<ShapeGeometry> == std::size(kTypeOf));
  if (kTypeOf[shape.geometry.index()] != shape.type) in.fail(what + " is not of its type");
  if (shape.algorithm > HullAlgorithm::monotone_chain) in.fail(what + " has no hull algorithm");
  if (!(shape.density >= 0 && valid_coefficient(shape.friction) &&
        valid_coefficient(shape.restitution))) {
    in.fail(what + " has a negative density, or a friction or restitution beyond the API's");
  }
  if (!(shape.aabb.lower.x() <= shape.aabb.upper.x() &&
        shape.aabb.lower.y() <= shape.aabb.upper.y())) {
    in.fail(what + "'s bounding box is inside out");
  }
  if (!within_reach(shape.aabb.lower) || !within_reach(shape.aabb.upper)) {
    in.fail(what + " reaches beyond max_world_coordinate");
  }
  check_geometry(shape.geometry, what, in);
  try {
    check_shape_mass(shape.geometry, shape.density, what);
  } catch (const Error& e) {
    in.fail(e.what());
  }
}

// A joint's definition passes create_joint's checks; its state is finite. Break limits may be
// infinite (never breaks).
void check_joint(const Joint& joint, const std::string& what, ByteReader& in) {
  try {
    check_joint_def(def_of(joint));
  } catch (const Error& e) {
    in.fail(what + ": " + e.what());
  }
  Joint finite_part = joint;
  base(finite_part).break_force = 0;
  base(finite_part).break_torque = 0;
  if (!all_finite(finite_part)) in.fail(what + " holds a non-finite value");
}

// A contact's points and cached poses lie in the world, its normals are unit vectors: the
// solver's lever arms and the manifold reuse take them as they are.
void check_contact(const Contact& c, const ContactImpulses& impulses, const std::string& what,
                   ByteReader& in) {
  FiniteWalk walk;
  contact_io(walk, const_cast<Contact&>(c), const_cast<ContactImpulses&>(impulses));
  if (!walk.finite || !(valid_coefficient(c.friction) && valid_coefficient(c.restitution))) {
    in.fail(what + " holds a non-finite or negative value");
  }
  const Manifold& m = c.manifold;
  bool in_world = within_reach(c.approach_point) && within_reach(c.cache.relative.position) &&
                  unit(c.cache.relative.rotation);
  for (int k = 0; k < 2; ++k) {
    in_world = in_world && within_reach(m.points[k].point) &&
               std::abs(m.points[k].separation) <= 4 * max_world_coordinate &&
               within_reach(c.cache.on_a[k]) && within_reach(c.cache.on_b[k]);
  }
  if (!in_world) in.fail(what + " reaches beyond max_world_coordinate");
  if ((m.point_count > 0 && !unit(m.normal)) || (c.cache.valid && !unit(c.cache.normal))) {
    in.fail(what + "'s normal is not a unit vector");
  }
}

void check_values(const WorldState& w, ByteReader& in) {
  const Real clock[] = {w.time, w.accumulator, w.dt};
  for (const Real v : clock) {
    if (!std::isfinite(v) || v < 0) in.fail("the world's clock is not finite and non-negative");
  }
  // The last step's length and substeps as step() takes them (none yet: 0 and 1).
  if (w.dt != 0 || w.substeps != 1) {
    try {
      check_step_length(w.dt, w.substeps, "the last step's ");
    } catch (const Error& e) {
      in.fail(e.what());
    }
  }
  for (std::size_t i = 0; i < w.bodies.size(); ++i) {
    if (w.bodies[i].alive) check_body(w.bodies[i], "body " + std::to_string(i), in);
  }
  for (std::size_t i = 0; i < w.shapes.size(); ++i) {
    if (w.shapes[i].alive) check_shape(w.shapes[i], "shape " + std::to_string(i), in);
  }
  for (std::size_t i = 0; i < w.joints.size(); ++i) {
    if (w.joints[i].alive) check_joint(w.joints[i], "joint " + std::to_string(i), in);
  }
  for (std::size_t i = 0; i < w.contacts.size(); ++i) {
    check_contact(w.contacts[i], w.contact_impulses[i], "contact " + std::to_string(i), in);
  }
}

}  // namespace

void check_snapshot_state(const WorldState& w, ByteReader& in) {
  check_indices(w, in);
  check_colours(w, in);
  check_values(w, in);
}

}  // namespace mink::detail
