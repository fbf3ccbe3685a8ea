// Seams between static polygons. A floor of tiled boxes is flat, but each tile is a polygon of
// its own: a box sliding across the joint meets the next tile's corner, and the contact there
// may take the tile's side as its face and stop the box dead (a "ghost" collision). Edges that
// another static polygon covers exactly are marked internal when shapes are made; a contact
// whose normal only a covered edge could give is then built against the tile's top face as a
// chain segment would be, with a flat neighbour where the covered edge was, so the whole floor
// acts as one smooth surface (as a chain does).

#include <algorithm>
#include <cmath>

#include "mink/narrowphase/collide.hpp"
#include "world_state.hpp"

namespace mink {

using detail::Shape;

namespace {

// Edges are compared vertex by vertex; seams are smoothed up to a tenth of the linear slop.
constexpr std::size_t kMaxSeamWork = 1 << 16;  // vertex pairs compared for one shape pair

bool seam_candidate(const WorldState& w, const Shape& s) {
  return s.alive && s.type == ShapeType::polygon && !s.sensor &&
         w.bodies[s.body].type == BodyType::static_body && w.bodies[s.body].enabled &&
         std::get<RoundedPolygon>(s.geometry).radius == 0;
}

std::vector<Vec2> world_vertices(const WorldState& w, const Shape& s) {
  const Pose pose = w.bodies[s.body].pose();
  std::vector<Vec2> out;
  for (const Vec2& v : std::get<RoundedPolygon>(s.geometry).hull.vertices()) {
    out.push_back(pose.apply(v));
  }
  return out;
}

// Marks in `flags` the edges of `a` that an edge of `b` covers exactly (the same two vertices,
// in the opposite order, as neighbouring counter-clockwise polygons have them).
void mark_shared_edges(const std::vector<Vec2>& a, const std::vector<Vec2>& b, Real tolerance,
                       std::vector<std::uint8_t>& flags) {
  if (a.size() * b.size() > kMaxSeamWork) return;
  const auto near = [&](const Vec2& p, const Vec2& q) {
    return std::abs(p.x() - q.x()) <= tolerance && std::abs(p.y() - q.y()) <= tolerance;
  };
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Vec2& a0 = a[i];
    const Vec2& a1 = a[(i + 1) % a.size()];
    for (std::size_t j = 0; j < b.size(); ++j) {
      if (near(a0, b[(j + 1) % b.size()]) && near(a1, b[j])) flags[i] = 1;
    }
  }
}

}  // namespace

// Recomputes the internal edges of a shape and of the static polygons around it (all of them
// from scratch, so adding, moving and removing are one code path). `removing`: the shape is
// about to go, so it covers nothing any more.
void WorldState::update_seams(std::uint32_t shape_index, bool removing) {
  Shape& s = shapes[shape_index];
  if (s.type != ShapeType::polygon || bodies[s.body].type != BodyType::static_body) return;
  const Real tolerance = 0.1 * def.linear_slop;
  const auto neighbours_of = [&](std::uint32_t index) {
    std::vector<std::uint32_t> found;
    const Shape& shape = shapes[index];
    std::vector<ProxyId> proxies;
    broadphase.query(compute_aabb(shape.geometry, bodies[shape.body].pose()).fattened(tolerance),
                     proxies);
    for (ProxyId proxy : proxies) {
      const auto other = static_cast<std::uint32_t>(broadphase.user_data(proxy));
      if (other == index || other >= shapes.size() || shapes[other].proxy != proxy) continue;
      if (removing && other == shape_index) continue;
      if (seam_candidate(*this, shapes[other])) found.push_back(other);
    }
    return found;
  };
  const auto recompute = [&](std::uint32_t index) {
    Shape& shape = shapes[index];
    const std::vector<Vec2> own = world_vertices(*this, shape);
    std::vector<std::uint8_t> flags(own.size(), 0);
    for (std::uint32_t other : neighbours_of(index)) {
      mark_shared_edges(own, world_vertices(*this, shapes[other]), tolerance, flags);
    }
    if (std::find(flags.begin(), flags.end(), 1) == flags.end()) flags.clear();
    shape.internal_edges = std::move(flags);
  };
  if (s.proxy == null_proxy) return;
  const std::vector<std::uint32_t> around = neighbours_of(shape_index);
  if (removing || !seam_candidate(*this, s)) {
    s.internal_edges.clear();
  } else {
    recompute(shape_index);
  }
  for (std::uint32_t other : around) recompute(other);
}

// A contact of a sharp polygon with a seam: when the normal could only come from a covered
// edge (or a corner next to one), the manifold is built again against the nearest uncovered
// edge as a chain segment whose covered neighbours continue it flat. False when the manifold
// stands as it was. The poses are the bodies' in the frame the manifold is measured in.
bool WorldState::smooth_seam(detail::Contact& c, const Pose& pose_a, const Pose& pose_b,
                             Real speculative_distance) const {
  const bool seam_on_a = !shapes[c.shape_a].internal_edges.empty();
  const Shape& seam = shapes[seam_on_a ? c.shape_a : c.shape_b];
  const Shape& other = shapes[seam_on_a ? c.shape_b : c.shape_a];
  if (c.manifold.point_count == 0) return false;
  const PreparedHull& hull = std::get<RoundedPolygon>(seam.geometry).hull;
  const Pose& seam_pose = seam_on_a ? pose_a : pose_b;
  const Vec2 towards_other = seam_on_a ? c.manifold.normal : Vec2(-c.manifold.normal);
  const Vec2 local = seam_pose.rotation.apply_inverse(towards_other);
  const auto normals = hull.normals();
  const std::size_t n = normals.size();
  const std::vector<std::uint8_t>& internal = seam.internal_edges;
  // The edge whose normal is nearest the contact normal, and its neighbour on the normal's side.
  std::size_t best = 0;
  for (std::size_t i = 1; i < n; ++i) {
    if (normals[i].dot(local) > normals[best].dot(local)) best = i;
  }
  const std::size_t before = (best + n - 1) % n, after = (best + 1) % n;
  const std::size_t beside =
      normals[before].dot(local) > normals[after].dot(local) ? before : after;
  const bool on_face = normals[best].dot(local) >= 1 - 1e-9;
  const bool admissible = on_face ? !internal[best] : !internal[best] && !internal[beside];
  if (admissible) return false;
  std::size_t face = n;
  if (!internal[best]) {
    face = best;
  } else if (!on_face && !internal[beside]) {
    face = beside;
  }
  if (face == n) {
    c.manifold.point_count = 0;  // only covered edges here: the neighbour's contact holds it
    return true;
  }
  const auto v = hull.vertices();
  const Vec2& p1 = v[face];
  const Vec2& p2 = v[(face + 1) % n];
  const Vec2 ghost1 = internal[(face + n - 1) % n] ? Vec2(p1 + (p1 - p2)) : v[(face + n - 1) % n];
  const Vec2 ghost2 = internal[(face + 1) % n] ? Vec2(p2 + (p2 - p1)) : v[(face + 2) % n];
  const ShapeGeometry segment = ChainSegment{ghost1, Segment{p1, p2}, ghost2};
  const Pose& other_pose = seam_on_a ? pose_b : pose_a;
  c.manifold =
      seam_on_a
          ? collide_shapes(segment, seam_pose, other.geometry, other_pose, speculative_distance)
          : collide_shapes(other.geometry, other_pose, segment, seam_pose, speculative_distance);
  return true;
}

}  // namespace mink
