// GJK against Box2D 2.4.1: our boolean (the paper's GJK), our distance query and b2Distance on
// the same hull pairs, for hull sizes 4 ... 1024, cold and warm-started; and the contact
// manifold (collide_hulls against b2CollidePolygons) on boxes and octagons.
//
// Benchmark names are "case/size/implementation"; every iteration is one query, cycling
// through a fixed set of pairs. bench/run_gjk.sh turns the medians into bench/results/gjk.csv.

#include <benchmark/benchmark.h>
#include <box2d/b2_collision.h>
#include <box2d/b2_distance.h>
#include <box2d/b2_polygon_shape.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "mink/geometry/convex_hull.hpp"
#include "mink/geometry/point_sets.hpp"
#include "mink/narrowphase/gjk_distance.hpp"
#include "mink/narrowphase/gjk_overlap.hpp"
#include "mink/narrowphase/manifold.hpp"

namespace {

using mink::Pose;
using mink::PreparedHull;
using mink::Real;
using mink::Vec2;

constexpr std::size_t kPairs = 64;  // a power of two: the cycle index is masked
constexpr std::size_t kSizes[] = {4, 8, 16, 64, 256, 1024};

// A posed hull both libraries see identically: float local vertices, float pose values.
struct Body {
  PreparedHull hull;
  std::vector<b2Vec2> local;
  float x = 0;
  float y = 0;
  float angle = 0;

  Pose pose() const {
    Pose p;
    p.position = Vec2(x, y);
    p.rotation = mink::Rotation::from_angle(angle);
    return p;
  }
  b2Transform transform() const { return b2Transform(b2Vec2(x, y), b2Rot(angle)); }
};

PreparedHull float_hull(const std::vector<Vec2>& points, std::vector<b2Vec2>& local) {
  std::vector<Vec2> rounded;
  for (const Vec2& p : points) {
    rounded.emplace_back(static_cast<float>(p.x()), static_cast<float>(p.y()));
  }
  PreparedHull hull(mink::build_hull(rounded, mink::HullAlgorithm::monotone_chain));
  local.clear();
  for (const Vec2& v : hull.vertices()) {
    local.emplace_back(static_cast<float>(v.x()), static_cast<float>(v.y()));
  }
  return hull;
}

Body random_body(std::mt19937_64& rng, std::size_t n, Real spread) {
  std::uniform_real_distribution<Real> angle(-std::numbers::pi, std::numbers::pi);
  std::uniform_real_distribution<Real> position(-spread, spread);
  std::uniform_real_distribution<Real> stretch(0.5, 1.0);
  std::vector<Vec2> points = mink::generate_points(mink::PointDistribution::on_circle, n, rng());
  const Real sy = stretch(rng);
  for (Vec2& p : points) p.y() *= sy;
  std::vector<b2Vec2> local;
  PreparedHull hull = float_hull(points, local);
  Body body{std::move(hull), std::move(local)};
  body.x = static_cast<float>(position(rng));
  body.y = static_cast<float>(position(rng));
  body.angle = static_cast<float>(angle(rng));
  return body;
}

struct Pair {
  Body a;
  Body b;
  Body b_next;  // b a small step later, for warm starts
  mink::SimplexCache cache;
  b2SimplexCache box2d_cache{};
};

std::vector<Vec2> world_vertices(const Body& body) {
  const Pose pose = body.pose();
  std::vector<Vec2> world;
  for (const Vec2& v : body.hull.vertices()) world.push_back(pose.apply(v));
  return world;
}

// Exactly half the pairs overlap at every size (even pairs overlap, odd ones are apart, drawn
// by rejection with the exact test), so neither the early exit for separated pairs nor the
// full triangle search for overlapping ones dominates.
std::vector<Pair>& pairs_of_size(std::size_t n) {
  static std::vector<std::vector<Pair>> all(std::size(kSizes));
  std::size_t slot = 0;
  while (kSizes[slot] != n) ++slot;
  std::vector<Pair>& pairs = all[slot];
  if (pairs.empty()) {
    std::mt19937_64 rng(0x67ab + n);
    while (pairs.size() < kPairs) {
      Body a = random_body(rng, n, 0);
      Body b = random_body(rng, n, 2.0);
      const bool overlap = mink::hulls_overlap_exact(world_vertices(a), world_vertices(b));
      if (overlap != (pairs.size() % 2 == 0)) continue;
      Pair pair{a, b, b, {}, {}};
      pair.b_next.x += 1e-3f;
      pair.b_next.angle += 1e-3f;
      pairs.push_back(std::move(pair));
    }
  }
  return pairs;
}

b2DistanceInput box2d_input(const Body& a, const Body& b) {
  b2DistanceInput input;
  input.proxyA.Set(a.local.data(), static_cast<int32>(a.local.size()), 0.0f);
  input.proxyB.Set(b.local.data(), static_cast<int32>(b.local.size()), 0.0f);
  input.transformA = a.transform();
  input.transformB = b.transform();
  input.useRadii = false;
  return input;
}

void mink_boolean(benchmark::State& state, std::size_t n) {
  auto& pairs = pairs_of_size(n);
  std::vector<Pose> pa, pb;
  for (const Pair& p : pairs) {
    pa.push_back(p.a.pose());
    pb.push_back(p.b.pose());
  }
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        mink::gjk_overlap(pairs[i].a.hull, pa[i], pairs[i].b.hull, pb[i]).overlap);
    i = (i + 1) & (kPairs - 1);
  }
}

void mink_distance(benchmark::State& state, std::size_t n, bool warm) {
  auto& pairs = pairs_of_size(n);
  std::vector<Pose> pa, pb, pb_next;
  for (Pair& p : pairs) {
    pa.push_back(p.a.pose());
    pb.push_back(p.b.pose());
    pb_next.push_back(p.b_next.pose());
    p.cache = {};
    if (warm) (void)mink::gjk_distance(p.a.hull, pa.back(), p.b.hull, pb.back(), &p.cache);
  }
  std::size_t i = 0;
  std::size_t round = 0;
  for (auto _ : state) {
    Pair& p = pairs[i];
    // Warm: the pair moves a step and back, as between simulation steps.
    const Pose& b = (round & 1) != 0 ? pb_next[i] : pb[i];
    const mink::DistanceResult r =
        mink::gjk_distance(p.a.hull, pa[i], p.b.hull, b, warm ? &p.cache : nullptr);
    benchmark::DoNotOptimize(r.distance);
    i = (i + 1) & (kPairs - 1);
    round += i == 0;
  }
}

void box2d_distance(benchmark::State& state, std::size_t n, bool warm) {
  auto& pairs = pairs_of_size(n);
  std::vector<b2DistanceInput> inputs, inputs_next;
  for (Pair& p : pairs) {
    inputs.push_back(box2d_input(p.a, p.b));
    inputs_next.push_back(box2d_input(p.a, p.b_next));
    p.box2d_cache.count = 0;
    if (warm) {
      b2DistanceOutput output;
      b2Distance(&output, &p.box2d_cache, &inputs.back());
    }
  }
  std::size_t i = 0;
  std::size_t round = 0;
  for (auto _ : state) {
    b2SimplexCache cold{};
    b2SimplexCache& cache = warm ? pairs[i].box2d_cache : cold;
    b2DistanceOutput output;
    b2Distance(&output, &cache, (round & 1) != 0 ? &inputs_next[i] : &inputs[i]);
    benchmark::DoNotOptimize(output.distance);
    i = (i + 1) & (kPairs - 1);
    round += i == 0;
  }
}

// Contact pairs as a stack produces them: B resting on A, slightly penetrating, shifted and
// tilted a little.
struct ContactPair {
  PreparedHull a;
  PreparedHull b;
  Pose pa;
  Pose pb;
  b2PolygonShape shape_a;
  b2PolygonShape shape_b;
  b2Transform xa;
  b2Transform xb;
};

std::vector<ContactPair> contact_pairs(std::size_t sides) {
  std::mt19937_64 rng(0xb0c5 + sides);
  std::uniform_real_distribution<float> shift(-0.4f, 0.4f);
  std::uniform_real_distribution<float> tilt(-0.05f, 0.05f);
  std::uniform_real_distribution<float> gap(-0.02f, 0.005f);
  std::vector<b2Vec2> ring;
  std::vector<Vec2> points;
  for (std::size_t k = 0; k < sides; ++k) {
    const double t =
        2 * std::numbers::pi * (static_cast<double>(k) + 0.5) / static_cast<double>(sides) -
        std::numbers::pi / 2;
    const b2Vec2 v(static_cast<float>(0.5 * std::sqrt(2.0) * std::cos(t)),
                   static_cast<float>(0.5 * std::sqrt(2.0) * std::sin(t)));
    ring.push_back(v);
    points.emplace_back(v.x, v.y);
  }
  const PreparedHull hull(mink::build_hull(points, mink::HullAlgorithm::monotone_chain));
  Real bottom = 0;
  for (const Vec2& v : hull.vertices()) bottom = std::min(bottom, v.y());
  std::vector<ContactPair> out;
  for (std::size_t k = 0; k < kPairs; ++k) {
    ContactPair c{hull, hull, {}, {}, {}, {}, {}, {}};
    c.shape_a.Set(ring.data(), static_cast<int32>(ring.size()));
    c.shape_b.Set(ring.data(), static_cast<int32>(ring.size()));
    const float x = shift(rng);
    const float y = static_cast<float>(-2 * bottom) + gap(rng);
    const float angle = tilt(rng);
    c.xa = b2Transform(b2Vec2(0, 0), b2Rot(0));
    c.xb = b2Transform(b2Vec2(x, y), b2Rot(angle));
    c.pb.position = Vec2(x, y);
    c.pb.rotation = mink::Rotation::from_angle(angle);
    out.push_back(std::move(c));
  }
  return out;
}

// Box2D's polygons carry a skin of b2_polygonRadius each; its manifold reaches as far as the
// two skins, so ours gets the same speculative distance.
constexpr Real kSpeculative = 2 * b2_polygonRadius;

void mink_manifold(benchmark::State& state, std::size_t sides) {
  const auto pairs = contact_pairs(sides);
  std::size_t i = 0;
  for (auto _ : state) {
    const ContactPair& c = pairs[i];
    benchmark::DoNotOptimize(mink::collide_hulls(c.a, c.pa, c.b, c.pb, kSpeculative).point_count);
    i = (i + 1) & (kPairs - 1);
  }
}

void box2d_manifold(benchmark::State& state, std::size_t sides) {
  const auto pairs = contact_pairs(sides);
  std::size_t i = 0;
  for (auto _ : state) {
    const ContactPair& c = pairs[i];
    b2Manifold manifold;
    b2CollidePolygons(&manifold, &c.shape_a, c.xa, &c.shape_b, c.xb);
    benchmark::DoNotOptimize(manifold.pointCount);
    i = (i + 1) & (kPairs - 1);
  }
}

template <typename F>
void add(const std::string& name, F function) {
  benchmark::RegisterBenchmark(name.c_str(), function)
      ->Unit(benchmark::kNanosecond)
      ->MinTime(0.05)
      ->Repetitions(15)
      ->ReportAggregatesOnly(true);
}

}  // namespace

int main(int argc, char** argv) {
  for (std::size_t n : kSizes) {
    const std::string size = std::to_string(n);
    add("cold/" + size + "/mink-gjk-boolean", [n](benchmark::State& s) { mink_boolean(s, n); });
    add("cold/" + size + "/mink-gjk-distance",
        [n](benchmark::State& s) { mink_distance(s, n, false); });
    add("cold/" + size + "/box2d-b2distance",
        [n](benchmark::State& s) { box2d_distance(s, n, false); });
    add("warm/" + size + "/mink-gjk-distance",
        [n](benchmark::State& s) { mink_distance(s, n, true); });
    add("warm/" + size + "/box2d-b2distance",
        [n](benchmark::State& s) { box2d_distance(s, n, true); });
  }
  for (std::size_t sides : {4u, 8u}) {
    const std::string size = std::to_string(sides);
    add("manifold/" + size + "/mink-collide-hulls",
        [sides](benchmark::State& s) { mink_manifold(s, sides); });
    add("manifold/" + size + "/box2d-b2collidepolygons",
        [sides](benchmark::State& s) { box2d_manifold(s, sides); });
  }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
