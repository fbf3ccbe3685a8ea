// Continuous collision: after the solve, every body whose step moved it far for its size is
// swept from where it started to where it ended, against what it could pass through, and put
// back at its first touch. Speculative contacts already stop bodies that are near something
// when the step begins; the sweep catches what they cannot see coming: a body crossing a thin
// wall, a terrain edge or another fast body within one step.
//
// What sweeps against what: a fast dynamic body against static and kinematic shapes; a bullet
// against every shape; and, beyond that, fast dynamic bodies against each other, so two
// thrown bodies meet even without the bullet flag. A pair already within contact range when
// the step began is left to its contact (sweeping it would stall a body sliding along a
// surface). Each fast body's first touch is found from the sweeps of the step as solved, so
// the bodies can be swept in parallel and in any order with the same result; a body stopped
// short keeps its velocity, and its contact next step does the rest.
//
// Where fast bodies meet only still shapes (continuous_fast_pairs off, no sensors), most are
// settled as their step finishes, in parallel, while their records are at hand
// (passes_unswept): nothing in the way, or only static shapes the cheap tests show them to
// pass. Only the others get a record and a place in solve_continuous.

#include "continuous.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <span>
#include <variant>

#include "prefetch.hpp"
#include "world_state.hpp"

namespace mink {

using detail::Body;
using detail::FastBody;
using detail::Shape;
using detail::SweepEnds;

// Where the centre of mass of a body the solver moved this step was when the step began (as
// write_back moved it).
Vec2 WorldState::start_center(std::uint32_t solver_index) const {
  const detail::SolverBody& sb = solver_bodies[solver_index];
  return bodies[solver_to_body[solver_index]].center - detail::on_grid(Vec2(sb.dpx, sb.dpy));
}

// The sweep of a body the solver moved this step, from the solver's record of it.
Sweep WorldState::solver_sweep(std::uint32_t solver_index) const {
  const Body& b = bodies[solver_to_body[solver_index]];
  const detail::SolverBody& sb = solver_bodies[solver_index];
  Sweep sweep;
  sweep.local_center = b.local_center;
  sweep.center1 = b.center;
  sweep.center0 = start_center(solver_index);
  // (qc, qs) is the step's rotation exactly, up to whole turns; the summed angle tells how
  // many (it differs from the exact turn by far less than half a turn).
  const Real exact = std::atan2(sb.qs, sb.qc);
  const Real whole = std::round((sb.turn - exact) / (2 * std::numbers::pi));
  const Real angle0 = b.previous_rotation.angle();
  sweep.angle0 = angle0;
  sweep.angle1 = angle0 + exact + 2 * std::numbers::pi * whole;
  return sweep;
}

Sweep WorldState::body_sweep(std::uint32_t body) const {
  const std::int32_t si = body < body_solver_index.size() ? body_solver_index[body] : -1;
  if (si >= 0) return solver_sweep(static_cast<std::uint32_t>(si));
  const Body& b = bodies[body];
  Sweep still;
  still.local_center = b.local_center;
  still.center0 = still.center1 = b.center;
  still.angle0 = still.angle1 = b.rotation.angle();
  return still;
}

namespace {

// Fast bodies' records asked for this many ahead of the one being swept.
constexpr std::uint32_t kFastBodyAhead = 8;
// A fast body's box this many times wider than the middle one's is scanned apart.
constexpr Real kWideFactor = 8;
// No body yet: the sweep loop's first shape finds its body's sweep.
constexpr std::uint32_t kNoBody = ~std::uint32_t{0};
// What a body may close on a chain segment in a step, as a share of its thinnest half-width,
// for the speculative contact alone to hold it (Box2D v3's core fraction).
constexpr Real kCoreFraction = 0.25;
// What the cheap tests read of a still polygon found in a fast body's way: the vertices and
// normals of a box.
constexpr std::size_t kFacesBytes = 128;

// A shape's middle: the point a chain segment tells its front from its back by.
Vec2 shape_middle(const ShapeGeometry& geometry) {
  struct Middle {
    Vec2 operator()(const Circle& c) const { return c.center; }
    Vec2 operator()(const Capsule& c) const { return 0.5 * (c.center1 + c.center2); }
    Vec2 operator()(const Segment& s) const { return 0.5 * (s.point1 + s.point2); }
    Vec2 operator()(const ChainSegment& s) const { return (*this)(s.segment); }
    Vec2 operator()(const RoundedPolygon& p) const { return p.hull.centroid(); }
  };
  return std::visit(Middle{}, geometry);
}

// A small circle about the shape's middle, half as wide as the shape is thin: where a shape
// already near something at the start of a step must not go, whatever the contact did.
std::optional<Circle> middle_circle(const ShapeGeometry& geometry) {
  const Real thin = detail::shape_min_extent(geometry);
  if (!(thin > 0)) return std::nullopt;
  return Circle{shape_middle(geometry), 0.5 * thin};
}

// A chain segment where `pose` puts it: its first end, the way to its second, and its length.
struct SegmentLine {
  Vec2 a, e;
  Real length;
  SegmentLine(const ChainSegment& chain, const Pose& pose)
      : a(pose.apply(chain.segment.point1)),
        e(pose.apply(chain.segment.point2) - a),
        length(e.norm()) {}
  // How far `point` lies in front of the line, along its right perpendicular (the side the
  // segment faces).
  Real in_front(const Vec2& point) const {
    const Vec2 p = point - a;
    return (p.x() * e.y() - p.y() * e.x()) / length;
  }
  // How far along the segment `point` lies, in units of its length squared.
  Real along(const Vec2& point) const { return (point - a).dot(e); }
};

// A moving body's shape carried from `ends.start` to `ends.end` (`local_center`: the body's
// centre of mass in its frame), as the tests below read it; its core only if it has few points.
detail::QuickShape quick_shape(const ShapeGeometry& geometry, const SweepEnds& ends,
                               const Vec2& local_center) {
  detail::QuickShape q;
  q.radius = detail::shape_radius(geometry);
  const Vec2 middle = shape_middle(geometry);
  q.middle_start = ends.start.apply(middle);
  q.middle_end = ends.end.apply(middle);
  q.middle_stray = ends.stray(middle, local_center);
  const auto* polygon = std::get_if<RoundedPolygon>(&geometry);
  if (polygon != nullptr && polygon->hull.vertices().size() > detail::kQuickPoints) return q;
  detail::for_each_core_point(geometry, [&](const Vec2& p) {
    q.start[q.count] = ends.start.apply(p);
    q.end[q.count] = ends.end.apply(p);
    q.stray[q.count] = ends.stray(p, local_center);
    ++q.count;
  });
  q.has_core = true;
  return q;
}

// Whether a moving shape only grazes the still chain segment `chain`: its middle starts behind
// the segment (one-sided, it passes), or closes on the segment's line by less than `core` and
// ends farther than `core` in front of it, however it turns on the way. The speculative
// contact then holds it, and no time of impact is needed: a body sliding fast along a chain
// costs none (Box2D v3's early out, with the turn's dip counted).
bool grazes_chain(const detail::QuickShape& moving, const ChainSegment& chain,
                  const Pose& chain_pose, Real core) {
  const SegmentLine line(chain, chain_pose);
  if (!(line.length > 0)) return false;
  const Real start = line.in_front(moving.middle_start);
  const Real end = line.in_front(moving.middle_end);
  return start < 0 || (start - end < core && end - moving.middle_stray > core);
}

// The fraction of the step at which `middle` (a point in the moving body's frame), starting in
// front of the chain segment `chain`, would first lie over the segment closer to its line than
// `tolerance`, or than half its start distance if that is less; 1 when it never does. A shape
// whose middle gets behind a chain segment passes through it (the segment is one-sided), so a
// body pressed into a chain so deep that its middle circle already overlaps it is still kept
// from crossing.
Real middle_crossing(const Vec2& middle, const Sweep& moving_sweep, const SweepEnds& ends,
                     const ChainSegment& chain, const Sweep& chain_sweep, const Pose& chain_start,
                     bool chain_still, Real tolerance) {
  // At fraction t: the middle's signed distance in front of the segment's line less the
  // target, and how far it lies past the segment's first end and short of its second (along
  // the segment, in units of its squared length). The middle is too close where all three
  // are at most, at least and at least zero.
  struct Place {
    Real closer, past_first, short_of_second;
  };
  Real target = 0;
  const Pose& still_wall = chain_start;
  const auto place_at = [&](const Pose& moving, const Pose& wall) {
    const SegmentLine line(chain, wall);
    const Vec2 point = moving.apply(middle);
    const Real along = line.along(point);
    return Place{line.in_front(point) - target, along, line.e.squaredNorm() - along};
  };
  const auto place = [&](Real t) {
    return place_at(moving_sweep.pose_at(t), chain_still ? still_wall : chain_sweep.pose_at(t));
  };
  const auto too_close = [](const Place& p) {
    return p.closer <= 0 && p.past_first >= 0 && p.short_of_second >= 0;
  };
  const Real start = place_at(ends.start, still_wall).closer;
  if (!(start > 0)) return 1;
  target = std::min(tolerance, 0.5 * start);
  // Beside a still chain the middle strays from the straight line between its ends by at
  // most its turn's dip (see clear_of_a_face): ends far enough in front keep it in front.
  if (chain_still) {
    const Real stray = ends.stray(middle, moving_sweep.local_center);
    if (std::min(start, place_at(ends.end, still_wall).closer + target) - stray > target) return 1;
  }
  // Each of the three is nearly linear in t (the middle's path bends only by the body's turn):
  // between samples, where none changes sign, whether the middle is too close does not
  // change either; where one does, bisection finds the place.
  constexpr int kSamples = 8;
  Place previous = place(0);
  Real before = 0;
  for (int k = 1; k <= kSamples; ++k) {
    const Real t = static_cast<Real>(k) / kSamples;
    const Place next = place(t);
    const auto flips = [](Real x, Real y) { return (x > 0) != (y > 0) || (x < 0) != (y < 0); };
    if (flips(previous.closer, next.closer) || flips(previous.past_first, next.past_first) ||
        flips(previous.short_of_second, next.short_of_second) || too_close(next)) {
      // The pieces between the sign changes, in order: the first one too close ends the
      // motion at its start.
      Real from = before;
      for (int piece = 0; piece < 3 && from < t; ++piece) {
        // The end of the piece starting at `from`: the first sign change after it.
        const Place at_from = place(from);
        Real lo = from, hi = t;
        for (int i = 0; i < 24; ++i) {
          const Real mid = 0.5 * (lo + hi);
          const Place m = place(mid);
          const bool same = !flips(at_from.closer, m.closer) &&
                            !flips(at_from.past_first, m.past_first) &&
                            !flips(at_from.short_of_second, m.short_of_second);
          (same ? lo : hi) = mid;
        }
        if (too_close(place(hi))) return lo;
        from = hi;
      }
    }
    previous = next;
    before = t;
  }
  return 1;
}

// Calls face(nx, ny, offset) for each face of a shape standing still at `pose`: the shape lies
// where (nx, ny) . x <= offset. Polygons up to kFaceLimit faces and segments have faces worth
// testing; a circle has none. In scalars, as clear_of_a_face reads them: a Vec2 made in memory
// and read back whole stalls the store buffer, and this runs for every still shape near a fast
// body.
constexpr std::size_t kFaceLimit = 16;

template <typename Face>
void for_each_face(const ShapeGeometry& geometry, const Pose& pose, Face&& face) {
  struct Point {
    Real x, y;
  };
  const Real c = pose.rotation.cos, s = pose.rotation.sin;
  // As Rotation::apply and Pose::apply.
  const auto turned = [&](const Vec2& v) {
    return Point{c * v.x() - s * v.y(), s * v.x() + c * v.y()};
  };
  const auto placed = [&](const Vec2& v) {
    const Point t = turned(v);
    return Point{t.x + pose.position.x(), t.y + pose.position.y()};
  };
  const auto line = [&](const Vec2& p1, const Vec2& p2, Real radius) {
    const Point a = placed(p1), b = placed(p2);
    const Real ex = b.x - a.x, ey = b.y - a.y;
    const Real length = std::sqrt(ex * ex + ey * ey);
    if (!(length > 0)) return;
    const Real nx = ey / length, ny = -ex / length;
    const Real along = nx * a.x + ny * a.y;
    face(nx, ny, along + radius);
    face(-nx, -ny, -along + radius);  // both sides: a segment is a face either way
  };
  if (const auto* seg = std::get_if<Segment>(&geometry)) {
    line(seg->point1, seg->point2, 0);
  } else if (const auto* chain = std::get_if<ChainSegment>(&geometry)) {
    line(chain->segment.point1, chain->segment.point2, 0);
  } else if (const auto* k = std::get_if<Capsule>(&geometry)) {
    line(k->center1, k->center2, k->radius);
  } else if (const auto* p = std::get_if<RoundedPolygon>(&geometry)) {
    const std::span<const Vec2> v = p->hull.vertices();
    const std::span<const Vec2> n = p->hull.normals();
    if (v.size() > kFaceLimit) return;
    for (std::size_t i = 0; i < v.size(); ++i) {
      const Point normal = turned(n[i]), vertex = placed(v[i]);
      face(normal.x, normal.y, normal.x * vertex.x + normal.y * vertex.y + p->radius);
    }
  }
}

// Whether a moving shape stays farther than `clearance` outside one face of the still shape
// `still` over the whole step: then they cannot touch, and no time of impact is needed. A
// sweep moves the centre of mass along a line and turns the body evenly, so along a normal a
// point at distance r from the centre of mass dips below the straight line between its ends by
// at most r (1 - cos(turn / 2)) (a turn within half a revolution; 2 r beyond).
bool clear_of_a_face(const detail::QuickShape& moving, const ShapeGeometry& still,
                     const Pose& still_pose, Real clearance) {
  if (!moving.has_core) return false;
  // The face the shape's middle stays farthest outside of is tried first: when a face clears
  // the shape, it mostly is that one.
  std::array<Real, kFaceLimit> normal_x, normal_y, offsets;
  std::size_t count = 0, first = 0;
  Real widest = -std::numeric_limits<Real>::infinity();
  const auto along = [](Real nx, Real ny, const Vec2& p) { return nx * p.x() + ny * p.y(); };
  for_each_face(still, still_pose, [&](Real nx, Real ny, Real offset) {
    const Real gap =
        std::min(along(nx, ny, moving.middle_start), along(nx, ny, moving.middle_end)) - offset;
    if (gap > widest) {
      widest = gap;
      first = count;
    }
    normal_x[count] = nx;
    normal_y[count] = ny;
    offsets[count] = offset;
    ++count;
  });
  const auto clears = [&](std::size_t face) {
    const Real nx = normal_x[face], ny = normal_y[face];
    Real nearest = std::numeric_limits<Real>::infinity();
    for (std::size_t i = 0; i < moving.count; ++i) {
      nearest =
          std::min(nearest, std::min(along(nx, ny, moving.start[i]), along(nx, ny, moving.end[i])) -
                                moving.stray[i]);
    }
    return nearest - moving.radius > offsets[face] + clearance;
  };
  if (count == 0) return false;
  if (clears(first)) return true;
  for (std::size_t face = 0; face < count; ++face) {
    if (face != first && clears(face)) return true;
  }
  return false;
}

// Body `b`'s pose with its centre of mass at `center` and turned by `rotation`, measured from
// `frame_origin`.
Pose pose_in_frame(const Vec2& center, const Rotation& rotation, const Body& b,
                   const Vec2& frame_origin) {
  return {(center - frame_origin) - rotation.apply(b.local_center), rotation};
}

// A fast body's ends from its records, without the angles its sweep needs, in the frame its
// pairs are swept in (measured from where its centre of mass starts, `frame_origin`): its
// rotation before and after the step, and its turn's dip from the solver's rotation over the
// step (taken as 2 for a turn near half a revolution or beyond, as it may be).
SweepEnds quick_ends(const Body& b, const detail::SolverBody& sb, const Vec2& frame_origin) {
  const Pose start = pose_in_frame(frame_origin, b.previous_rotation, b, frame_origin);
  const Pose end = pose_in_frame(b.center, b.rotation, b, frame_origin);
  constexpr Real kSureTurn = 3;  // below pi by more than the summed angle can be off
  Real dip = 2;
  if (std::abs(sb.turn) < kSureTurn) {
    const Real cos_turn = sb.qc / std::sqrt(sb.qc * sb.qc + sb.qs * sb.qs);
    dip = 1 - std::sqrt(std::max(Real{0}, 0.5 * (1 + cos_turn)));
  }
  return {start, end, dip};
}

// How far a point of `moving` can travel in `frame`'s body frame over the step: its centre's
// travel there plus its turn against that frame at its extent. A body slow in another's frame
// is the speculative contacts' to keep from it, as a slow body is beside a still one: bodies
// carried round by a turning kinematic body, or falling together, need no time of impact.
// `start` and `end`: the frame's rotations at the ends of its sweep.
Real travel_relative_to(const Sweep& moving, Real extent, const Sweep& frame, const Rotation& start,
                        const Rotation& end) {
  const Vec2 travel = end.apply_inverse(moving.center1 - frame.center1) -
                      start.apply_inverse(moving.center0 - frame.center0);
  const Real turn = (moving.angle1 - moving.angle0) - (frame.angle1 - frame.angle0);
  return travel.norm() + std::abs(turn) * extent;
}
Real travel_relative_to(const Sweep& moving, Real extent, const Sweep& frame) {
  return travel_relative_to(moving, extent, frame, Rotation::from_angle(frame.angle0),
                            Rotation::from_angle(frame.angle1));
}

// Whether `passing` (WorldState::passing_shapes) holds every one of a body's `shape_count`
// shapes: a body with more than 64 is always swept.
bool all_pass(std::uint64_t passing, std::size_t shape_count) {
  return shape_count > 0 && shape_count <= 64 &&
         passing == (~std::uint64_t{0} >> (64 - shape_count));
}

}  // namespace

// The first touch of `fast`'s shapes with `other_shape` moving by `other_world_sweep`, if it
// comes before `fast.fraction`; the shapes marked in `settled` (by their place among the
// body's) were seen to pass it by already (clear_of_a_face, grazes_chain). A pair already
// within contact range when the step began is the contact's to keep apart (sweeping the
// surfaces would stop a body sliding along a floor at once); the sweep then only keeps the
// shape's middle from crossing the other shape, which a fast-spinning or corner-sliding body
// can otherwise do within one step.
void WorldState::sweep_pair(FastBody& fast, const detail::LocalSweep& local,
                            std::uint32_t other_shape, const detail::FramedSweep& other,
                            std::uint64_t settled) const {
  const Shape& o = shapes[other_shape];
  // Both sweeps measured from where the fast body starts, so that where the pair lies does not
  // round what is found (world_grid.hpp).
  const Sweep& fast_sweep = local.sweep;
  const Sweep& other_sweep = other.sweep;
  const bool still = other.still;
  const Pose& other_start = other.start;
  const std::vector<std::uint32_t>& fast_shapes = bodies[fast.body].shapes;
  for (std::size_t k = 0; k < fast_shapes.size(); ++k) {
    if (k < 64 && (settled >> k & 1) != 0) continue;
    const std::uint32_t s = fast_shapes[k];
    const Shape& f = shapes[s];
    const Real tolerance = 0.25 * def.linear_slop;
    const Real target = slop_target(f.geometry, o.geometry, def.linear_slop);
    const auto* chain = std::get_if<ChainSegment>(&o.geometry);
    // After the cheap tests, which settle most pairs: this one reads the bodies' records and
    // joint lists.
    if (!should_make_contact(s, other_shape)) continue;
    const ShapeDistance start =
        shape_distance(f.geometry, local.ends.start, o.geometry, other_start);
    const bool near = start.overlap || start.distance < 4 * def.linear_slop;
    ShapeGeometry middle;
    if (near) {
      if (chain != nullptr) {
        const Real crossing = middle_crossing(shape_middle(f.geometry), fast_sweep, local.ends,
                                              *chain, other_sweep, other_start, still, tolerance);
        if (crossing > 0 && crossing < fast.fraction) fast.fraction = crossing;
      }
      const std::optional<Circle> circle = middle_circle(f.geometry);
      if (!circle) continue;
      middle = *circle;
      if (still && clear_of_a_face(quick_shape(middle, local.ends, fast_sweep.local_center),
                                   o.geometry, other_start, 3 * tolerance)) {
        continue;
      }
    }
    TimeOfImpactInput input;
    input.shape_a = near ? &middle : &f.geometry;
    input.sweep_a = fast_sweep;
    input.shape_b = &o.geometry;
    input.sweep_b = other_sweep;
    input.max_fraction = fast.fraction;
    input.tolerance = tolerance;
    // The middle stops only when it would touch: the shape is half its thinness deep then,
    // past anything a contact would allow.
    input.target = near ? 2 * input.tolerance : target;
    const TimeOfImpactOutput out = time_of_impact(input);
    // A touch at the very start is the contact's: stopping there would hold the body still.
    if ((out.state == ToiState::hit || out.state == ToiState::gave_up) && out.fraction > 0 &&
        out.fraction < fast.fraction) {
      fast.fraction = out.fraction;
    }
  }
}

// The static and kinematic shapes (every other shape, for a bullet) whose broadphase boxes meet
// a fast body's box over the step, in shape order, each once (the order is fixed so the work
// done is too, and a shape met by several of the body's shapes is swept once): from its
// contacts when its shapes stayed within their broadphase boxes (the broadphase paired them
// with all of those), else from queries.
const std::vector<std::uint32_t>& WorldState::fixed_candidates(std::uint32_t fast_body,
                                                               const Aabb& box, bool covered,
                                                               bool bullet, std::uint32_t worker) {
  std::vector<std::uint32_t>& found = continuous.candidates[worker];
  found.clear();
  if (covered && !bullet) {
    const Body& body = bodies[fast_body];
    // Up to the last of its contacts with something static or kinematic.
    std::uint32_t left = body.fixed_contacts;
    for (std::size_t k = 0; left > 0; ++k) {
      const detail::Contact& contact = contacts[body.contacts[k]];
      const bool a_is_fast = contact.body_a == fast_body;
      if (!(a_is_fast ? contact.b_fixed : contact.a_fixed)) continue;
      --left;
      const std::uint32_t index = a_is_fast ? contact.shape_b : contact.shape_a;
      if (broadphase.fat_aabb(shapes[index].proxy).overlaps(box)) found.push_back(index);
    }
  } else {
    // A body that left its broadphase boxes (a fast body mostly has: they are fattened by a
    // few centimetres only), or a bullet, which meets dynamic shapes too.
    const auto add_shape = [&](ProxyId proxy, std::uint64_t user_data) {
      const auto index = static_cast<std::uint32_t>(user_data);
      if (index >= shapes.size()) return;
      const Shape& o = shapes[index];
      if (!o.alive || o.proxy != proxy || o.body == fast_body) return;
      if (bullet || bodies[o.body].type != BodyType::dynamic) {
        found.push_back(index);
        // The cheap tests read its faces next, which live apart from the shape record.
        detail::prefetch_polygon(o, kFacesBytes);
      }
    };
    if (bullet) {
      std::vector<ProxyId>& proxies = continuous.proxies[worker];
      proxies.clear();
      broadphase.query(box, proxies);
      for (const ProxyId proxy : proxies) add_shape(proxy, broadphase.user_data(proxy));
    } else {
      // The box is the body's own swept box, well formed.
      broadphase.for_each_fixed(box, add_shape);
    }
  }
  std::sort(found.begin(), found.end());
  found.erase(std::unique(found.begin(), found.end()), found.end());
  return found;
}

// A fast body's shapes carried over its step, in the worker's list, in the frame its pairs are
// swept in: measured from where its centre of mass starts, which is returned.
Vec2 WorldState::quick_shapes(std::uint32_t solver_index, std::uint32_t worker) {
  const Body& b = bodies[solver_to_body[solver_index]];
  const Vec2 frame_origin = start_center(solver_index);
  const SweepEnds ends = quick_ends(b, solver_bodies[solver_index], frame_origin);
  std::vector<detail::QuickShape>& quick = continuous.quick[worker];
  quick.resize(b.shapes.size());
  for (std::size_t k = 0; k < b.shapes.size(); ++k) {
    quick[k] = quick_shape(shapes[b.shapes[k]].geometry, ends, b.local_center);
  }
  return frame_origin;
}

// Which of a fast body's shapes (a bit each by their place among the body's, the first 64;
// `quick` the body's quick_shapes) the cheap tests show to pass by the still shape `still` at
// `still_pose` without touching it: clear of one of its faces, or grazing a chain.
std::uint64_t WorldState::passing_shapes(const Body& fast_body,
                                         const std::vector<detail::QuickShape>& quick,
                                         const ShapeGeometry& still, const Pose& still_pose) const {
  const Real tolerance = 0.25 * def.linear_slop;
  const auto* chain = std::get_if<ChainSegment>(&still);
  std::uint64_t passing = 0;
  for (std::size_t k = 0; k < fast_body.shapes.size() && k < 64; ++k) {
    const bool passes =
        (chain != nullptr &&
         grazes_chain(quick[k], *chain, still_pose, kCoreFraction * fast_body.min_extent)) ||
        clear_of_a_face(
            quick[k], still, still_pose,
            slop_target(shapes[fast_body.shapes[k]].geometry, still, def.linear_slop) + tolerance);
    passing |= std::uint64_t{passes} << k;
  }
  return passing;
}

// From record_fast_body: whether the cheap tests show that every shape in a fast body's way
// (not a bullet's) passes it by, so that it needs no sweep. Only static shapes are tested: a
// kinematic body may be finishing its own step on another worker, and a body with one in its
// way is left to solve_continuous.
bool WorldState::passes_unswept(std::uint32_t solver_index, const Aabb& box, bool covered,
                                std::uint32_t worker) {
  // Most fast bodies are far from every obstacle, and the broadphase tells so at once.
  if (!covered && !broadphase.may_meet_fixed(box)) return true;
  const std::uint32_t body = solver_to_body[solver_index];
  const std::vector<std::uint32_t>& found = fixed_candidates(body, box, covered, false, worker);
  if (found.empty()) return true;
  const Vec2 frame_origin = quick_shapes(solver_index, worker);
  const std::vector<detail::QuickShape>& quick = continuous.quick[worker];
  const Body& fast_body = bodies[body];
  std::uint32_t other_body = kNoBody;
  Pose other_start;
  for (const std::uint32_t index : found) {
    const Shape& still = shapes[index];
    const Body& o = bodies[still.body];
    if (o.type != BodyType::static_body) return false;
    if (still.body != other_body) {
      other_body = still.body;
      other_start = pose_in_frame(o.center, o.rotation, o, frame_origin);
    }
    if (!all_pass(passing_shapes(fast_body, quick, still.geometry, other_start),
                  fast_body.shapes.size())) {
      return false;
    }
  }
  return true;
}

// A body moved fast: translation plus turn at the extent against its thinnest half-width.
bool WorldState::moved_fast(std::uint32_t si) const {
  const Body& b = bodies[solver_to_body[si]];
  if (b.type != BodyType::dynamic || b.shapes.empty()) return false;
  if (b.bullet) return true;
  const detail::SolverBody& sb = solver_bodies[si];
  const Real limit = b.continuous_threshold * b.min_extent;
  if (detail::travels_beyond(sb.dpx, sb.dpy, std::abs(sb.turn) * b.extent, 1, limit)) return true;
  // Box2D v3 counts a body fast also when its velocity would carry it far in a step (a body
  // just struck has barely moved yet): which bodies' boxes are bare follows it.
  return !def.fast_body_margin &&
         detail::travels_beyond(sb.vx, sb.vy, std::abs(sb.w) * b.extent, dt, limit);
}

// From finish_body, while the body's records are at hand: a fast body's record, with its box
// over the step and whether its broadphase boxes cover it.
void WorldState::record_fast_body(std::uint32_t solver_index, const Aabb& swept, bool covered,
                                  std::uint32_t worker) {
  const Body& b = bodies[solver_to_body[solver_index]];
  // Most fast bodies meet nothing a sweep is needed for: found here, while their records are
  // at hand, they cost solve_continuous nothing. Fast bodies meeting each other, and sensors,
  // need every fast body's sweep.
  if (!b.bullet && !def.continuous_fast_pairs && sensors.empty() &&
      passes_unswept(solver_index, swept, covered, worker)) {
    continuous.is_fast[solver_index] = detail::ContinuousState::kClear;
    return;
  }
  continuous.is_fast[solver_index] = detail::ContinuousState::kSwept;
  FastBody& record = continuous.fast[solver_index];
  record.body = solver_to_body[solver_index];
  record.solver_index = solver_index;
  record.fraction = 1;
  record.slow = b.continuous_threshold * b.min_extent;
  record.extent = b.extent;
  record.box = swept;
  record.bullet = b.bullet;
  record.covered = covered;
  // Fast bodies meet each other on both their sweeps: every sweep is needed then (else it
  // waits until its body has something to meet, which most, in free flight, do not).
  record.has_sweep = def.continuous_fast_pairs;
  if (record.has_sweep) {
    record.sweep = solver_sweep(solver_index);
    record.rotation0 = Rotation::from_angle(record.sweep.angle0);
    record.rotation1 = Rotation::from_angle(record.sweep.angle1);
  }
}

void WorldState::solve_continuous() {
  continuous.hits = 0;
  counters.continuous_hits = 0;
  // The marked bodies, in body order (solver bodies are), so sensors meet them in a fixed
  // order.
  std::vector<std::uint32_t>& fast_list = continuous.fast_list;
  fast_list.clear();
  std::size_t clear = 0;
  for (std::uint32_t si = 0; si < continuous.is_fast.size(); ++si) {
    const std::uint8_t mark = continuous.is_fast[si];
    if (mark == detail::ContinuousState::kSwept) fast_list.push_back(si);
    clear += mark == detail::ContinuousState::kClear ? 1 : 0;
  }
  counters.fast_bodies = fast_list.size() + clear;
  if (fast_list.empty()) return;

  const auto count = static_cast<std::uint32_t>(fast_list.size());
  // Fast bodies against each other: their boxes by lower x, so each finds its neighbours by a
  // short scan, those many times wider than the middle one apart.
  continuous.fast_by_x.clear();
  continuous.fast_wide.clear();
  if (def.continuous_fast_pairs) {
    std::vector<Real>& widths = continuous.widths;
    std::vector<Real>& lower_x = continuous.lower_x;
    widths.resize(count);
    lower_x.resize(count);
    for (std::uint32_t i = 0; i < count; ++i) {
      const Aabb& box = continuous.fast_body(i).box;
      widths[i] = box.upper.x() - box.lower.x();
      lower_x[i] = box.lower.x();
    }
    const auto middle = widths.begin() + count / 2;
    std::nth_element(widths.begin(), middle, widths.end());
    const Real wide = kWideFactor * *middle;
    for (std::uint32_t i = 0; i < count; ++i) {
      const Aabb& box = continuous.fast_body(i).box;
      (box.upper.x() - box.lower.x() > wide ? continuous.fast_wide : continuous.fast_by_x)
          .push_back(i);
    }
    std::sort(continuous.fast_by_x.begin(), continuous.fast_by_x.end(),
              [&](std::uint32_t x, std::uint32_t y) {
                return lower_x[x] != lower_x[y] ? lower_x[x] < lower_x[y] : x < y;
              });
    // Where a body's scan may start: no box before the first place whose running largest
    // upper x reaches the body's lower x can overlap it.
    continuous.fast_boxes_by_x.resize(continuous.fast_by_x.size());
    continuous.fast_reach_x.resize(continuous.fast_by_x.size());
    Real reach = -std::numeric_limits<Real>::infinity();
    for (std::size_t k = 0; k < continuous.fast_by_x.size(); ++k) {
      const Aabb& box = continuous.fast_body(continuous.fast_by_x[k]).box;
      continuous.fast_boxes_by_x[k] = box;
      reach = std::max(reach, box.upper.x());
      continuous.fast_reach_x[k] = reach;
    }
  }

  continuous.stopped.reset(continuous.is_fast.size(), tasks.workers());
  tasks.parallel_for(count, 4, [&](std::uint32_t begin, std::uint32_t end, std::uint32_t worker) {
    detail::LocalSweep local;
    for (std::uint32_t i = begin; i < end; ++i) {
      // Its first line only: the rest is read for the few with something in the way.
      if (i + kFastBodyAhead < end)
        detail::prefetch_line(&continuous.fast_body(i + kFastBodyAhead));
      FastBody& fast = continuous.fast_body(i);
      // The sweep from the body's start, found for its first pair swept; the other body's in
      // its frame, for the first of that body's shapes.
      bool has_local = false;
      detail::FramedSweep framed;
      bool has_framed = false;
      const auto ensure_sweep = [&] {
        if (fast.has_sweep) return;
        fast.sweep = solver_sweep(fast.solver_index);
        fast.has_sweep = true;
      };
      const auto sweep_with = [&](std::uint32_t shape, const Sweep& other_sweep,
                                  std::uint64_t settled) {
        ensure_sweep();
        if (!has_local) local = detail::LocalSweep(fast.sweep);
        has_local = true;
        if (!has_framed) framed = detail::FramedSweep(other_sweep, fast.sweep.center0);
        has_framed = true;
        sweep_pair(fast, local, shape, framed, settled);
      };
      const std::vector<std::uint32_t>& found =
          fixed_candidates(fast.body, fast.box, fast.covered, fast.bullet, worker);
      const Real slow = fast.slow;
      const Body& fast_record = bodies[fast.body];
      const std::vector<std::uint32_t>& fast_shapes = fast_record.shapes;
      // Beside a still shape most pairs are settled by cheap tests (clear_of_a_face,
      // grazes_chain) on the body's shapes at the ends of its step, found from its records for
      // the first such pair; its sweep, with the arc tangents of its angles, waits for a pair
      // they leave.
      const std::vector<detail::QuickShape>& quick = continuous.quick[worker];
      bool has_quick = false;
      Vec2 frame_origin{0, 0};
      const auto ensure_quick = [&] {
        if (has_quick) return;
        has_quick = true;
        frame_origin = quick_shapes(fast.solver_index, worker);
      };
      // A body's shapes lie side by side in `found` (shape indices of one body mostly are):
      // what is found of the body is found once for them. A static body stands still, and its
      // sweep is needed only for a pair the cheap tests leave.
      std::uint32_t other_body = kNoBody;
      Sweep other;
      bool has_other = false, other_still = false;
      Pose other_start;  // a still body's pose in the frame
      for (const std::uint32_t index : found) {
        const std::uint32_t body = shapes[index].body;
        if (body != other_body) {
          other_body = body;
          has_framed = false;
          has_other = bodies[body].type != BodyType::static_body;
          if (has_other) other = body_sweep(body);
          other_still = !has_other || detail::is_still(other);
          if (other_still) {
            ensure_quick();
            const Body& o = bodies[body];
            other_start = pose_in_frame(o.center, o.rotation, o, frame_origin);
          }
        }
        if (!other_still) {
          ensure_sweep();
          if (!fast.bullet && travel_relative_to(fast.sweep, fast.extent, other) <= slow) continue;
          sweep_with(index, other, 0);
          continue;
        }
        const std::uint64_t settled =
            passing_shapes(fast_record, quick, shapes[index].geometry, other_start);
        if (all_pass(settled, fast_shapes.size())) continue;
        if (!has_other) {
          other = body_sweep(body);
          has_other = true;
        }
        sweep_with(index, other, settled);
      }
      // Other fast bodies (a bullet has met every dynamic shape already).
      const auto meet = [&](std::uint32_t j) {
        const FastBody& other = continuous.fast_body(j);
        if (j == i || other.bullet) return;
        const Real limit = std::min(slow, other.slow);
        if (travel_relative_to(fast.sweep, fast.extent, other.sweep, other.rotation0,
                               other.rotation1) <= limit &&
            travel_relative_to(other.sweep, other.extent, fast.sweep, fast.rotation0,
                               fast.rotation1) <= limit) {
          return;
        }
        has_framed = false;
        for (const std::uint32_t s : bodies[other.body].shapes) sweep_with(s, other.sweep, 0);
      };
      if (!fast.bullet && def.continuous_fast_pairs) {
        const auto first = std::lower_bound(continuous.fast_reach_x.begin(),
                                            continuous.fast_reach_x.end(), fast.box.lower.x());
        for (auto k = static_cast<std::size_t>(first - continuous.fast_reach_x.begin());
             k < continuous.fast_by_x.size(); ++k) {
          const Aabb& box = continuous.fast_boxes_by_x[k];
          if (box.lower.x() > fast.box.upper.x()) break;
          if (box.overlaps(fast.box)) meet(continuous.fast_by_x[k]);
        }
        for (const std::uint32_t j : continuous.fast_wide) {
          if (continuous.fast_body(j).box.overlaps(fast.box)) meet(j);
        }
      }
      if (fast.fraction < 1) continuous.stopped.mark(fast_list[i], worker);
    }
  });

  // Sensors see fast bodies along their sweeps.
  if (!sensors.empty()) {
    for (const std::uint32_t si : fast_list) {
      FastBody& fast = continuous.fast[si];
      if (!fast.has_sweep) {
        fast.sweep = solver_sweep(si);
        fast.has_sweep = true;
      }
    }
  }
  // Stopped bodies go back to where they first touched, keeping their velocity, and their
  // shapes' boxes with them: the few the workers marked, in body order (solver order is).
  continuous.stopped.for_each_marked([&](std::uint32_t si) {
    const FastBody& fast = continuous.fast[si];
    ++continuous.hits;
    Body& b = bodies[fast.body];
    // As Sweep::pose_at, with the way to the touch on the grid (world_grid.hpp).
    const Sweep& sweep = fast.sweep;
    b.rotation = sweep.pose_at(fast.fraction).rotation;
    b.center = sweep.center0 + detail::on_grid(fast.fraction * (sweep.center1 - sweep.center0));
    detail::place_origin(b);
    for (const std::uint32_t s : b.shapes) update_shape_aabb(shapes[s], b);
    boxes_left[fast.solver_index] = 1;
  });
  counters.continuous_hits = continuous.hits;
}

}  // namespace mink
