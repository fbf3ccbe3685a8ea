#pragma once

// Random moving shape pairs for the time of impact and shape cast tests, and what checking one
// against the sampled sweep (sweep_oracle.hpp) found.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <random>
#include <string>

#include "mink/error.hpp"
#include "sweep_oracle.hpp"

namespace mink_test {

// A slop-based target and tolerance in the manner of Box2D, as the engine will use them.
inline constexpr Real kSlop = 0.005;
inline constexpr Real kTolerance = 0.25 * kSlop;

// What `call` throws as an InvalidArgumentError, or "no error".
template <typename Call>
std::string invalid_argument_message(Call call) {
  try {
    call();
  } catch (const mink::InvalidArgumentError& e) {
    return e.what();
  }
  return "no error";
}

inline const char* kind_name(ShapeKind kind) {
  switch (kind) {
    case ShapeKind::circle:
      return "circle";
    case ShapeKind::capsule:
      return "capsule";
    case ShapeKind::segment:
      return "segment";
    case ShapeKind::chain_segment:
      return "chain";
    case ShapeKind::polygon:
      return "polygon";
  }
  return "?";
}

// The small, thin shapes that tunnel at speed: circles of radius 0.05, thin capsules, segments,
// walls 0.02 thick, boxes of 0.1 and triangles about 0.1 across.
inline ShapeGeometry thin_shape(std::mt19937_64& rng, ShapeKind kind) {
  std::uniform_real_distribution<Real> u(0, 1);
  switch (kind) {
    case ShapeKind::circle:
      return mink::Circle{Vec2(0, 0), 0.05};
    case ShapeKind::capsule: {
      const Real half = 0.05 + 0.2 * u(rng);
      return mink::Capsule{Vec2(-half, 0), Vec2(half, 0), 0.01 + 0.015 * u(rng)};
    }
    case ShapeKind::segment:
    case ShapeKind::chain_segment: {
      const Real half = 0.05 + 0.95 * u(rng);
      const mink::Segment s{Vec2(-half, 0), Vec2(half, 0)};
      if (kind == ShapeKind::segment) return s;
      return mink::ChainSegment{Vec2(-2 * half, 0.1), s, Vec2(2 * half, 0.1)};
    }
    case ShapeKind::polygon: {
      const int which = static_cast<int>(rng() % 3);
      if (which == 0) return mink::RoundedPolygon{box(0.25 + 0.75 * u(rng), 0.01), 0};
      if (which == 1) return mink::RoundedPolygon{box(0.05, 0.05), 0};
      std::vector<Vec2> corners;
      for (int i = 0; i < 3; ++i) {
        const Real angle = 2 * std::numbers::pi * (i + 0.3 * (u(rng) - 0.5)) / 3;
        const Real r = 0.05 + 0.02 * u(rng);
        corners.emplace_back(r * std::cos(angle), r * std::sin(angle));
      }
      return mink::RoundedPolygon{PreparedHull(mink::ConvexHull::from_ccw_vertices(corners)), 0};
    }
  }
  return mink::Circle{};
}

// How far a shape reaches from its local origin, radius included.
inline Real reach_of(const ShapeGeometry& shape) {
  const WorldCore core = world_core(shape, Pose{});
  Real reach = 0;
  for (const Vec2& p : core.points) reach = std::max(reach, p.norm());
  return reach + core.radius;
}

enum class Family {
  ordinary,   // shapes up to about 2 across, up to a quarter turn a step
  fast_spin,  // the same shapes turning up to three turns a step, each
  thin_fast,  // thin_shape at 50..500 m/s over a 1/60 s step, up to a turn a step
};

inline const char* family_name(Family f) {
  return f == Family::ordinary ? "ordinary" : f == Family::fast_spin ? "fast spin" : "thin fast";
}

struct SweepCase {
  ShapeGeometry a;
  ShapeGeometry b;
  Sweep sweep_a;
  Sweep sweep_b;
  Real max_fraction = 1;
};

inline Vec2 random_direction(std::mt19937_64& rng) {
  std::uniform_real_distribution<Real> angle(-std::numbers::pi, std::numbers::pi);
  const Real a = angle(rng);
  return Vec2(std::cos(a), std::sin(a));
}

// B is aimed to pass A at a random time, offset by up to about their joint reach, so that
// about half the pairs meet. With `spin` false neither turns (shape casts).
inline SweepCase random_sweep_case(std::mt19937_64& rng, ShapeKind ka, ShapeKind kb, Family family,
                                   bool spin = true) {
  std::uniform_real_distribution<Real> u(0, 1);
  SweepCase c{family == Family::thin_fast ? thin_shape(rng, ka) : random_shape(rng, ka),
              family == Family::thin_fast ? thin_shape(rng, kb) : random_shape(rng, kb),
              {},
              {},
              1};
  const Real reach_a = reach_of(c.a);
  const Real reach_b = reach_of(c.b);
  constexpr Real kStep = 1.0 / 60;
  const bool thin = family == Family::thin_fast;
  const Real speed_a = thin ? 500 * kStep * u(rng) : 2 * u(rng);
  const Real speed_b = thin ? (50 + 450 * u(rng)) * kStep : 1 + 5 * u(rng);
  const Real turns = family == Family::ordinary ? 0.25 : family == Family::fast_spin ? 3 : 1;
  const Vec2 va = speed_a * random_direction(rng);
  const Vec2 vb = speed_b * random_direction(rng);
  for (Sweep* s : {&c.sweep_a, &c.sweep_b}) {
    s->local_center = random_point(rng, 0.3 * (s == &c.sweep_a ? reach_a : reach_b));
    s->angle0 = std::numbers::pi * (2 * u(rng) - 1);
    s->angle1 = s->angle0 + (spin ? 2 * std::numbers::pi * turns * (2 * u(rng) - 1) : 0);
  }
  const Real when = 0.15 + u(rng);  // when B passes A's centre, offset
  const Vec2 offset = 1.2 * (reach_a + reach_b) * u(rng) * random_direction(rng);
  c.sweep_a.center0 = random_point(rng, 1);
  c.sweep_a.center1 = c.sweep_a.center0 + va;
  c.sweep_b.center0 = c.sweep_a.center0 + offset - when * (vb - va);
  c.sweep_b.center1 = c.sweep_b.center0 + vb;
  if (rng() % 10 == 0) c.max_fraction = 0.2 + 0.8 * u(rng);
  if (rng() % 2 == 0) {
    std::swap(c.a, c.b);
    std::swap(c.sweep_a, c.sweep_b);
  }
  return c;
}

// What checking many results against the oracle found, for one pair kind.
struct Agreement {
  int cases = 0, hits = 0, hits_at_start = 0, separated = 0, overlapped = 0, gave_up = 0;
  long long iterations = 0;
  int max_iterations = 0;
  // Separation at our t less target, over hits after t = 0 (a hit at 0 may lie anywhere in
  // the band).
  Real least_excess = 1, most_excess = -1;
  // The oracle's first time below target (over hits after 0) and below target - tolerance
  // (over all hits), less our t.
  Real margin_to_target = 1, margin_to_low = 1;
  long long oracle_evaluations = 0;
  double seconds = 0;  // in the queries under test alone

  void count_iterations(int k) {
    iterations += k;
    max_iterations = std::max(max_iterations, k);
  }

  void print(const std::string& what) const {
    std::printf(
        "%-26s %6d cases: %6d hit (%4d at 0) %6d separated %5d overlapped %d gave up; "
        "iterations mean %4.1f max %3d; sep - target in [%.1e, %.1e]; oracle below target "
        "%.1e, below target - tol %.1e after our t; %.2f us/query; %.0f oracle scans/case\n",
        what.c_str(), cases, hits, hits_at_start, separated, overlapped, gave_up,
        cases > 0 ? double(iterations) / cases : 0.0, max_iterations, least_excess, most_excess,
        margin_to_target, margin_to_low, cases > 0 ? 1e6 * seconds / cases : 0.0,
        cases > 0 ? double(oracle_evaluations) / cases : 0.0);
  }
};

// A result in the form both queries share: TimeOfImpactOutput's fields (a shape cast has no
// point on the moving shape; it is then not checked).
struct Reported {
  mink::ToiState state = mink::ToiState::separated;
  Real fraction = 0;
  Real separation = 0;
  Vec2 point_a{0, 0};
  std::optional<Vec2> point_b;
  Vec2 normal{0, 0};
  int iterations = 0;
};

inline std::string text(Real x) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

// Empty when `r` keeps every guarantee of TimeOfImpactOutput as far as the sampled sweep can
// tell; else what it broke. Adds the case to `agreement`.
inline std::string check_against_oracle(const SweepCase& c, Real target, Real tolerance,
                                        const Reported& r, Agreement& agreement) {
  using mink::ToiState;
  constexpr Real kRounding = 1e-9;  // the library's distance against the oracle's scans
  const SweptShape sa(c.a, c.sweep_a), sb(c.b, c.sweep_b);
  const SweepOracle oracle(sa, sb);
  const Real low = target - tolerance;
  const Real high = target + tolerance;
  const Real resolution = tolerance / 8;
  ++agreement.cases;
  agreement.count_iterations(r.iterations);
  const Real start = oracle.exact_separation(0);
  if (r.state == ToiState::overlapped) {
    ++agreement.overlapped;
    if (!(start < low + kRounding)) return "overlapped, but the separation at 0 is " + text(start);
    if (r.fraction != 0) return "overlapped at fraction " + text(r.fraction);
    return "";
  }
  if (start < low - kRounding) return "missed the overlap at 0: separation " + text(start);
  if (r.state == ToiState::separated) {
    ++agreement.separated;
    if (r.fraction != c.max_fraction) return "separated at fraction " + text(r.fraction);
    const Crossing x = oracle.first_below(low, 0, c.max_fraction, resolution);
    agreement.oracle_evaluations += x.evaluations;
    if (x.found) return "missed a hit: below target - tolerance at " + text(x.time);
    return "";
  }
  const Real t = r.fraction;
  if (!(t >= 0 && t <= c.max_fraction)) return "fraction " + text(t) + " out of range";
  const WorldCore wa = sa.world_at(t), wb = sb.world_at(t);
  const Real g = signed_gap(wa, wb).gap;
  if (std::abs(g - r.separation) > kRounding) {
    return "separation " + text(r.separation) + " at " + text(t) + ", the oracle has " + text(g);
  }
  if (std::abs(r.normal.norm() - 1) > kRounding) return "normal not unit";
  if (std::abs(point_signed_distance(wa, r.point_a)) > kRounding) return "point_a off A's surface";
  if (r.point_b) {
    if (std::abs(point_signed_distance(wb, *r.point_b)) > kRounding) {
      return "point_b off B's surface";
    }
    if ((*r.point_b - r.point_a - r.separation * r.normal).norm() > kRounding) {
      return "the points are not separation apart along the normal";
    }
  }
  if (r.state == ToiState::hit) {
    ++agreement.hits;
    if (g < low - kRounding || g > high + kRounding) {
      return "hit at " + text(t) + " with separation " + text(g);
    }
    if (t == 0) {
      ++agreement.hits_at_start;
    } else {
      agreement.least_excess = std::min(agreement.least_excess, g - target);
      agreement.most_excess = std::max(agreement.most_excess, g - target);
    }
  } else {
    ++agreement.gave_up;
    if (g < high - kRounding) return "gave up at " + text(t) + " within target: " + text(g);
  }
  // No earlier time below target - tolerance: the first time below target, then the first
  // below target - tolerance from there.
  const Crossing first = oracle.first_below(target, 0, c.max_fraction, resolution);
  const Crossing deep =
      first.found ? oracle.first_below(low, first.time, c.max_fraction, resolution) : first;
  agreement.oracle_evaluations += first.evaluations + (first.found ? deep.evaluations : 0);
  if (deep.found && deep.time < t) {
    return "below target - tolerance at " + text(deep.time) + ", before " + text(t);
  }
  if (r.state == ToiState::hit && first.found && t > 0) {
    agreement.margin_to_target = std::min(agreement.margin_to_target, first.time - t);
  }
  if (r.state == ToiState::hit && deep.found) {
    agreement.margin_to_low = std::min(agreement.margin_to_low, deep.time - t);
  }
  return "";
}

}  // namespace mink_test
