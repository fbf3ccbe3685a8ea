// Shapes: the engine's shape records, their boxes and proxies, and the shape half of the
// World API.

#include "shape.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "checks.hpp"
#include "mink/error.hpp"
#include "record_scope.hpp"
#include "world_state.hpp"

namespace mink {

using detail::Body;
using detail::Shape;

namespace detail {

ShapeGeometry make_geometry(const ShapeDef& def) {
  switch (def.type) {
    case ShapeType::circle:
      return Circle{def.points[0], def.radius};
    case ShapeType::capsule:
      return Capsule{def.points[0], def.points[1], def.radius};
    case ShapeType::segment:
      return Segment{def.points[0], def.points[1]};
    case ShapeType::polygon:
      return RoundedPolygon{PreparedHull(make_shape_hull(def)), def.radius};
    case ShapeType::chain:
      break;
  }
  throw InvalidArgumentError("a chain is made by World::create_chain, not create_shape");
}

Real shape_radius(const ShapeGeometry& geometry) {
  switch (kind_of(geometry)) {
    case ShapeKind::circle:
      return std::get<Circle>(geometry).radius;
    case ShapeKind::capsule:
      return std::get<Capsule>(geometry).radius;
    case ShapeKind::polygon:
      return std::get<RoundedPolygon>(geometry).radius;
    case ShapeKind::segment:
    case ShapeKind::chain_segment:
      break;
  }
  return 0;
}

Real shape_extent(const ShapeGeometry& geometry, const Vec2& center) {
  Real extent = 0;
  for_each_core_point(geometry,
                      [&](const Vec2& p) { extent = std::max(extent, (p - center).norm()); });
  return extent + shape_radius(geometry);
}

Real shape_min_extent(const ShapeGeometry& geometry) {
  struct Visitor {
    Real operator()(const Circle& c) const { return c.radius; }
    Real operator()(const Capsule& c) const { return c.radius; }
    Real operator()(const Segment&) const { return 0; }
    Real operator()(const ChainSegment&) const { return 0; }
    Real operator()(const RoundedPolygon& p) const {
      Real nearest = std::numeric_limits<Real>::infinity();
      const auto normals = p.hull.normals();
      const auto offsets = p.hull.face_offsets();
      for (std::size_t i = 0; i < normals.size(); ++i) {
        nearest = std::min(nearest, offsets[i] - normals[i].dot(p.hull.centroid()));
      }
      return std::max(nearest, Real{0}) + p.radius;
    }
  };
  return std::visit(Visitor{}, geometry);
}

Real broadphase_size(const ShapeGeometry& geometry) {
  struct Visitor {
    Real operator()(const Circle& c) const { return c.radius; }
    Real operator()(const Capsule& c) const {
      return 0.5 * (c.center2 - c.center1).norm() + c.radius;
    }
    Real operator()(const Segment& s) const { return 0.5 * (s.point2 - s.point1).norm(); }
    Real operator()(const ChainSegment& c) const { return (*this)(c.segment); }
    Real operator()(const RoundedPolygon& p) const { return p.hull.radius(); }
  };
  return std::visit(Visitor{}, geometry);
}

}  // namespace detail

// The box the broadphase sees: the shape at the current pose grown by the speculative
// distance, or by nothing (with_margin false).
Aabb WorldState::shape_box(const Shape& s, const Body& b, bool with_margin) const {
  const Pose pose = b.pose();
  const Real c = pose.rotation.cos, sn = pose.rotation.sin;
  Real lx = 0, ly = 0, ux = 0, uy = 0;
  bool first = true;
  detail::for_each_core_point(s.geometry, [&](const Vec2& v) {
    const Real x = c * v.x() - sn * v.y();
    const Real y = sn * v.x() + c * v.y();
    if (first) {
      lx = ux = x;
      ly = uy = y;
      first = false;
    } else {
      lx = std::min(lx, x), ux = std::max(ux, x);
      ly = std::min(ly, y), uy = std::max(uy, y);
    }
  });
  const Real grown = detail::shape_radius(s.geometry) + (with_margin ? 4 * def.linear_slop : 0);
  Aabb box;
  box.lower = Vec2(pose.position.x() + lx - grown, pose.position.y() + ly - grown);
  box.upper = Vec2(pose.position.x() + ux + grown, pose.position.y() + uy + grown);
  return box;
}

void WorldState::update_shape_aabb(Shape& s, const Body& b, bool with_margin) {
  s.aabb = shape_box(s, b, with_margin);
  s.bare_box = !with_margin;
}

// A box is bare exactly when it is its shape's bare box at its body's pose: every step and
// call that sets one leaves it so. (With no margin at all the two boxes are one, and which it
// is called changes nothing.)
void WorldState::find_bare_boxes() {
  for (std::uint32_t i = 0; i < shapes.size(); ++i) {
    Shape& s = shapes[i];
    if (!s.alive) continue;
    const Aabb bare = shape_box(s, bodies[s.body], false);
    s.bare_box = s.aabb.lower == bare.lower && s.aabb.upper == bare.upper;
  }
}

void WorldState::create_proxy(std::uint32_t shape_index) {
  Shape& s = shapes[shape_index];
  const Body& b = bodies[s.body];
  update_shape_aabb(s, b);
  s.proxy = broadphase.create_proxy(s.aabb,
                                    b.type == BodyType::static_body ? ProxyKind::static_body
                                    : b.type == BodyType::kinematic ? ProxyKind::kinematic
                                                                    : ProxyKind::moving,
                                    shape_index, detail::broadphase_size(s.geometry));
}

void WorldState::destroy_proxy(Shape& s) {
  if (s.proxy == null_proxy) return;
  pending_proxy_destroys.push_back(s.proxy);
  s.proxy = null_proxy;
}

void WorldState::refresh_proxy(std::uint32_t shape_index) {
  destroy_shape_contacts(shape_index);
  destroy_proxy(shapes[shape_index]);
  if (bodies[shapes[shape_index].body].enabled) create_proxy(shape_index);
}

namespace {

std::uint32_t attach_shape(WorldState& w, std::uint32_t body_index, const ShapeDef& def,
                           ShapeGeometry geometry) {
  const std::uint32_t index = w.shapes.allocate();
  Shape& s = w.shapes[index];
  s.geometry = std::move(geometry);
  s.type = def.type;
  s.density = def.density;
  s.friction = def.friction;
  s.restitution = def.restitution;
  s.filter = def.filter;
  s.sensor = def.is_sensor;
  s.contact_events = def.enable_contact_events;
  s.sensor_events = def.enable_sensor_events;
  s.hit_events = def.enable_hit_events;
  s.algorithm = def.algorithm;
  s.user_data = def.user_data;
  s.body = body_index;
  w.bodies[body_index].shapes.push_back(index);
  if (s.sensor) {
    const auto at = std::lower_bound(
        w.sensors.begin(), w.sensors.end(), index,
        [](const detail::SensorState& state, std::uint32_t i) { return state.shape < i; });
    w.sensors.insert(at, detail::SensorState{index, {}});
  }
  return index;
}

void finish_attach(WorldState& w, std::uint32_t body_index, std::span<const std::uint32_t> added) {
  Body& b = w.bodies[body_index];
  b.mass_override = false;
  w.update_mass(b);
  if (b.enabled) {
    for (std::uint32_t index : added) w.create_proxy(index);
    for (std::uint32_t index : added) w.update_seams(index, false);
  }
  w.wake(b);
}

}  // namespace

void detail::check_shape_mass(const ShapeGeometry& geometry, Real density,
                              const std::string& what) {
  if (density == 0) return;
  const MassData m = compute_mass(geometry, density);
  if (!(m.mass <= max_mass_property && m.rotational_inertia <= max_mass_property)) {
    throw InvalidArgumentError(what + ": density " + exact_number(density) + " gives mass " +
                               exact_number(m.mass) + " kg and rotational inertia " +
                               exact_number(m.rotational_inertia) +
                               " kg m^2, beyond max_mass_property (1e30)");
  }
  if (m.mass > 0 && (m.mass < min_mass_property || m.rotational_inertia < min_mass_property)) {
    throw InvalidArgumentError(what + ": density " + std::to_string(density) + " gives mass " +
                               exact_number(m.mass) + " kg and rotational inertia " +
                               exact_number(m.rotational_inertia) +
                               " kg m^2, below min_mass_property (1e-30)");
  }
}

ShapeId World::create_shape(BodyId body_id, const ShapeDef& def) {
  const detail::RecordScope record(*this, detail::Call::create_shape, body_id, def);
  WorldState& w = *state_;
  w.body(body_id);  // validates before any work
  if (def.type == ShapeType::chain) {
    throw InvalidArgumentError("create_shape: a chain is made by World::create_chain");
  }
  check_shape_def(def);
  ShapeGeometry geometry = detail::make_geometry(def);
  detail::check_shape_mass(geometry, def.density, "create_shape on " + to_string(body_id));
  const std::uint32_t index = attach_shape(w, body_id.index, def, std::move(geometry));
  finish_attach(w, body_id.index, std::span(&index, 1));
  return w.shape_id(index);
}

std::vector<ShapeId> World::create_chain(BodyId body_id, const ShapeDef& def) {
  const detail::RecordScope record(*this, detail::Call::create_chain, body_id, def);
  WorldState& w = *state_;
  w.body(body_id);
  if (def.type != ShapeType::chain) {
    throw InvalidArgumentError("create_chain: ShapeDef.type must be chain, got " +
                               std::string(to_string(def.type)));
  }
  check_shape_def(def);
  const std::vector<Vec2>& p = def.points;
  const std::size_t n = p.size();
  const std::size_t edges = def.loop ? n : n - 1;
  const std::uint32_t chain = w.next_chain++;
  std::vector<std::uint32_t> added;
  added.reserve(edges);
  for (std::size_t i = 0; i < edges; ++i) {
    // Ghosts: the neighbours along the chain. At an open chain's ends the ghost turns a right
    // angle towards the chain's back (the side it does not collide on): a convex corner, so a
    // shape past the end is pushed outwards rather than up.
    const Vec2& a = p[i];
    const Vec2& b = p[(i + 1) % n];
    const Vec2 away(-(b - a).y(), (b - a).x());  // towards the back: the left perpendicular
    const Vec2 ghost1 = def.loop ? p[(i + n - 1) % n] : (i == 0 ? Vec2(a + away) : p[i - 1]);
    const Vec2 ghost2 = def.loop ? p[(i + 2) % n] : (i + 2 < n ? p[i + 2] : Vec2(b + away));
    const std::uint32_t index =
        attach_shape(w, body_id.index, def, ChainSegment{ghost1, Segment{a, b}, ghost2});
    w.shapes[index].chain = chain;
    w.shapes[index].chain_loop = def.loop;
    added.push_back(index);
  }
  finish_attach(w, body_id.index, added);
  std::vector<ShapeId> ids;
  for (std::uint32_t index : added) ids.push_back(w.shape_id(index));
  return ids;
}

void World::destroy_shape(ShapeId id) {
  const detail::RecordScope record(*this, detail::Call::destroy_shape, id);
  WorldState& w = *state_;
  Shape& s = w.shape(id);
  w.destroy_shape_contacts(id.index);
  w.update_seams(id.index, true);
  if (s.sensor) w.destroy_sensor(id.index);
  w.destroy_proxy(s);
  Body& b = w.bodies[s.body];
  b.shapes.erase(std::find(b.shapes.begin(), b.shapes.end(), id.index));
  s.geometry = Circle{};  // frees a polygon's arrays now
  w.shapes.release(id.index);
  b.mass_override = false;
  w.update_mass(b);
  w.wake(b);
}

bool World::is_valid(ShapeId id) const noexcept {
  return state_->shapes.valid(id, state_->serial);
}

std::size_t World::shape_count() const noexcept {
  return state_->shapes.live();
}

BodyId World::shape_body(ShapeId id) const {
  return state_->body_id(state_->shape(id).body);
}

ShapeType World::shape_type(ShapeId id) const {
  return state_->shape(id).type;
}

const ShapeGeometry& World::shape_geometry(ShapeId id) const {
  return state_->shape(id).geometry;
}

const ConvexHull& World::shape_hull(ShapeId id) const {
  const Shape& s = state_->shape(id);
  if (s.type != ShapeType::polygon) {
    throw InvalidArgumentError("shape_hull: " + to_string(id) + " is a " +
                               std::string(to_string(s.type)) + ", not a polygon");
  }
  return std::get<RoundedPolygon>(s.geometry).hull.hull();
}

Real World::shape_radius(ShapeId id) const {
  return detail::shape_radius(state_->shape(id).geometry);
}
const Filter& World::shape_filter(ShapeId id) const {
  return state_->shape(id).filter;
}
bool World::is_sensor(ShapeId id) const {
  return state_->shape(id).sensor;
}
std::uint64_t World::shape_user_data(ShapeId id) const {
  return state_->shape(id).user_data;
}
bool World::shape_contact_events(ShapeId id) const {
  return state_->shape(id).contact_events;
}
bool World::shape_sensor_events(ShapeId id) const {
  return state_->shape(id).sensor_events;
}
bool World::shape_hit_events(ShapeId id) const {
  return state_->shape(id).hit_events;
}
std::optional<ChainMembership> World::shape_chain(ShapeId id) const {
  const Shape& s = state_->shape(id);
  if (s.chain == detail::kNoChain) return std::nullopt;
  return ChainMembership{s.chain, s.chain_loop};
}
Real World::shape_density(ShapeId id) const {
  return state_->shape(id).density;
}
Real World::shape_friction(ShapeId id) const {
  return state_->shape(id).friction;
}
Real World::shape_restitution(ShapeId id) const {
  return state_->shape(id).restitution;
}
HullAlgorithm World::shape_algorithm(ShapeId id) const {
  return state_->shape(id).algorithm;
}

Aabb World::shape_aabb(ShapeId id) const {
  const Shape& s = state_->shape(id);
  return compute_aabb(s.geometry, state_->bodies[s.body].pose());
}

void World::set_shape_density(ShapeId id, Real density) {
  const detail::RecordScope record(*this, detail::Call::set_shape_density, id, density);
  detail::check_density(density, "set_shape_density of " + to_string(id));
  WorldState& w = *state_;
  Shape& s = w.shape(id);
  detail::check_shape_mass(s.geometry, density, "set_shape_density of " + to_string(id));
  s.density = density;
  Body& b = w.bodies[s.body];
  b.mass_override = false;
  w.update_mass(b);
  w.wake(b);
}

namespace {

// Mixes the shape's material into its contacts again.
void remix_contacts(WorldState& w, std::uint32_t shape_index) {
  for (const std::uint32_t ci : w.bodies[w.shapes[shape_index].body].contacts) {
    detail::Contact& c = w.contacts[ci];
    if (c.shape_a != shape_index && c.shape_b != shape_index) continue;
    const Shape& a = w.shapes[c.shape_a];
    const Shape& b = w.shapes[c.shape_b];
    c.friction = detail::mix_friction(a.friction, b.friction);
    c.restitution = detail::mix_restitution(a.restitution, b.restitution);
  }
}

}  // namespace

void World::set_shape_friction(ShapeId id, Real friction) {
  const detail::RecordScope record(*this, detail::Call::set_shape_friction, id, friction);
  detail::check_coefficient(friction, "set_shape_friction of " + to_string(id));
  state_->shape(id).friction = friction;
  remix_contacts(*state_, id.index);
}

void World::set_shape_restitution(ShapeId id, Real restitution) {
  const detail::RecordScope record(*this, detail::Call::set_shape_restitution, id, restitution);
  detail::check_coefficient(restitution, "set_shape_restitution of " + to_string(id));
  state_->shape(id).restitution = restitution;
  remix_contacts(*state_, id.index);
}

void World::set_shape_filter(ShapeId id, const Filter& filter) {
  const detail::RecordScope record(*this, detail::Call::set_shape_filter, id, filter);
  WorldState& w = *state_;
  Shape& s = w.shape(id);
  if (s.filter == filter) return;
  s.filter = filter;
  // As in Box2D: a new proxy makes the broadphase report every overlapping pair again.
  w.refresh_proxy(id.index);
  w.wake(w.bodies[s.body]);
}

}  // namespace mink
