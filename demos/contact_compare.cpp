#include "contact_compare.hpp"

#include <box2d/box2d.h>

#include <algorithm>
#include <string>

#include "box2d_distance.hpp"
#include "box2d_scene.hpp"
#include "gjk_crosscheck.hpp"
#include "mink/error.hpp"
#include "mink/narrowphase/gjk_distance.hpp"
#include "mink/narrowphase/gjk_overlap.hpp"
#include "mink/narrowphase/prepared_hull.hpp"

namespace mink::cli {

namespace {

struct OracleShape {
  std::size_t body_index;
  BodyId body;
  ShapeId shape;
  PreparedHull hull;
  bool dynamic;
};

bool box2d_overlap(std::span<const Vec2> a, const Pose& pose_a, std::span<const Vec2> b,
                   const Pose& pose_b) {
  const Vec2 origin = pose_a.position;
  // Taken relative to A's origin before rounding to float, so rounding does not blur the band.
  std::vector<Vec2> wa;
  std::vector<Vec2> wb;
  for (const Vec2& v : a) wa.push_back(pose_a.apply(v) - origin);
  for (const Vec2& v : b) wb.push_back(pose_b.apply(v) - origin);
  return interop::box2d_distance(wa, wb).overlap;
}

void run_oracle(const World& world, const std::vector<OracleShape>& shapes, long long step,
                double band, ContactComparison& result) {
  struct Entry {
    Aabb box;
    std::size_t index;
  };
  std::vector<Entry> entries;
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    entries.push_back({world.shape_aabb(shapes[i].shape), i});
  }
  std::sort(entries.begin(), entries.end(),
            [](const Entry& p, const Entry& q) { return p.box.lower.x() < q.box.lower.x(); });
  ++result.oracle_checks;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    for (std::size_t j = i + 1; j < entries.size(); ++j) {
      if (entries[j].box.lower.x() > entries[i].box.upper.x()) break;
      if (!entries[i].box.overlaps(entries[j].box)) continue;
      const OracleShape& a = shapes[std::min(entries[i].index, entries[j].index)];
      const OracleShape& b = shapes[std::max(entries[i].index, entries[j].index)];
      if (a.body == b.body || (!a.dynamic && !b.dynamic)) continue;
      const Pose pa = world.pose(a.body);
      const Pose pb = world.pose(b.body);
      const bool ours = gjk_overlap(a.hull, pa, b.hull, pb).overlap;
      const bool theirs = box2d_overlap(a.hull.vertices(), pa, b.hull.vertices(), pb);
      ++result.oracle_pairs;
      result.oracle_overlapping += ours;
      if (ours == theirs) continue;
      const double gap = signed_gap(gjk_distance(a.hull, pa, b.hull, pb), a.hull, pa, b.hull, pb);
      std::vector<Vec2> wa;
      std::vector<Vec2> wb;
      for (const Vec2& v : a.hull.vertices()) wa.push_back(pa.apply(v));
      for (const Vec2& v : b.hull.vertices()) wb.push_back(pb.apply(v));
      const bool exact = hulls_overlap_exact(wa, wb);
      OracleMismatch m{step, a.body_index,         b.body_index,  ours,         exact,
                       gap,  std::abs(gap) > band, std::move(wa), std::move(wb)};
      result.outside_band += m.outside_band;
      result.mismatches.push_back(std::move(m));
    }
  }
}

}  // namespace

ContactComparison compare_contacts(const SceneDef& scene, long long steps, int every, double band,
                                   const Box2dStepping& stepping, const CompareObserver& observe) {
  if (steps < 1) throw InvalidArgumentError("steps must be at least 1");
  if (every < 1) throw InvalidArgumentError("--every must be at least 1");
  if (stepping.substeps < 1 || stepping.velocity < 1 || stepping.position < 0) {
    throw InvalidArgumentError(
        "Box2D stepping: substeps and velocity iterations must be at least 1 and position "
        "iterations at least 0, got " +
        std::to_string(stepping.substeps) + ", " + std::to_string(stepping.velocity) + " and " +
        std::to_string(stepping.position));
  }
  // Refuses what Box2D cannot hold before anything runs.
  interop::Box2dScene rival = interop::build_box2d_world(scene);
  World world = build_world(scene);
  // Prepared once: hulls never change, only poses.
  std::vector<OracleShape> shapes;
  const std::vector<BodyId> bodies = world.bodies();
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    for (ShapeId shape : world.body_shapes(bodies[i])) {
      // The oracle checks the paper's GJK on hulls; other kinds' cores are points and segments.
      if (world.shape_type(shape) != ShapeType::polygon) continue;
      shapes.push_back({i, bodies[i], shape, PreparedHull(world.shape_hull(shape)),
                        world.body_type(bodies[i]) == BodyType::dynamic});
    }
  }
  ContactComparison result;
  const float dt = static_cast<float>(scene.world.time_step / stepping.substeps);
  if (observe) observe(0, world, rival);
  for (long long step = 1; step <= steps; ++step) {
    world.step();
    for (int k = 0; k < stepping.substeps; ++k) {
      rival.world->Step(dt, stepping.velocity, stepping.position);
    }
    if (observe) observe(step, world, rival);
    ContactCountRow row;
    row.step = step;
    row.mink_pairs = world.counters().broadphase_pairs;
    row.mink_contacts = world.counters().touching_contacts;
    for (const b2Contact* c = rival.world->GetContactList(); c != nullptr; c = c->GetNext()) {
      ++row.box2d_pairs;
      row.box2d_touching += c->IsTouching();
    }
    result.rows.push_back(row);
    if (step % every == 0 || step == steps) run_oracle(world, shapes, step, band, result);
  }
  return result;
}

}  // namespace mink::cli
