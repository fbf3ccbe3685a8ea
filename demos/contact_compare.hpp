#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "mink/engine/scene.hpp"

namespace mink::interop {
struct Box2dScene;
}

namespace mink::cli {

// How Box2D 2.4.1 advances one of our steps: `substeps` calls of b2World::Step of a
// substep's time each, with these solver passes (its manual recommends 8 and 3).
struct Box2dStepping {
  int substeps = 1;
  int velocity = 8;
  int position = 3;
};

// Sees both engines after every step (and once before the first, as step 0).
using CompareObserver =
    std::function<void(long long step, const World& ours, const interop::Box2dScene& rival)>;

// One step of both engines: our broadphase pairs and touching contacts, Box2D's contact list
// (pairs whose fat boxes overlap) and how many of those touch.
struct ContactCountRow {
  long long step = 0;
  std::size_t mink_pairs = 0;
  std::size_t mink_contacts = 0;
  std::size_t box2d_pairs = 0;
  std::size_t box2d_touching = 0;
};

// A candidate pair on which our narrowphase and Box2D's b2Distance disagree. `gap` is our
// signed distance to touching (negative: penetration depth).
struct OracleMismatch {
  long long step = 0;
  std::size_t body_a = 0;  // scene body indices
  std::size_t body_b = 0;
  bool mink_overlap = false;
  bool exact_overlap = false;  // the slow exact verdict on the same double-precision vertices
  double gap = 0;
  bool outside_band = false;
  std::vector<Vec2> world_a;  // both hulls in world coordinates, to reproduce the case
  std::vector<Vec2> world_b;
};

struct ContactComparison {
  std::vector<ContactCountRow> rows;   // one per step, steps 1..N
  std::size_t oracle_checks = 0;       // configurations checked
  std::size_t oracle_pairs = 0;        // candidate pairs checked over all of them
  std::size_t oracle_overlapping = 0;  // of those, overlapping by our verdict
  std::vector<OracleMismatch> mismatches;
  std::size_t outside_band = 0;
};

// Steps `scene` in Minkowski and in Box2D 2.4.1 side by side (Box2D as `stepping` says),
// showing both to `observe` after every step. Every `every` steps (and after
// the last), the overlap oracle takes our current configuration and checks each candidate pair
// (polygon shapes of different bodies, at least one dynamic, whose tight boxes overlap) with our
// GJK verdict against b2Distance on radius-0 proxies of the same world vertices. The vertices are
// taken relative to the first shape's origin before rounding to float, so Box2D sees the same
// geometry to about 1e-7 of the shapes' size. A disagreement is outside the band when our
// distance to touching exceeds `band`. Throws InvalidArgumentError for a hull Box2D cannot hold.
// The scene's schedule is not run: Box2D could not follow it (`mink compare` refuses such scenes).
ContactComparison compare_contacts(const SceneDef& scene, long long steps, int every, double band,
                                   const Box2dStepping& stepping = {},
                                   const CompareObserver& observe = {});

}  // namespace mink::cli
