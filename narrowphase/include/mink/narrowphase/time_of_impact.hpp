#pragma once

#include <cstdint>

#include "mink/narrowphase/pose.hpp"
#include "mink/narrowphase/shape_geometry.hpp"

namespace mink {

/// @file
/// @brief Time of impact: the first time two moving shapes come within a target separation,
/// found by conservative advancement on the GJK distance between their cores.
///
/// The search is rigorous for any spin, several turns a step included. At a time t the cores
/// are d apart along the unit normal n (A towards B); B's core lies beyond A's along n by
/// s = min over B's core points of n.b - max over A's of n.a, and s <= d. With
/// v = center1 - center0 and w = angle1 - angle0 (both per unit of the fraction t) and rho the
/// largest distance from a body's local centre to a point of its core (its longest arm), no
/// point of A moves along n faster than n.v_A + |w_A| rho_A and none of B against it faster
/// than -n.v_B + |w_B| rho_B, so over a further time h, s (and with it d) shrinks by at most
///
///   mu h,  mu = n.(v_A - v_B) + |w_A| rho_A + |w_B| rho_B,
///
/// and also, while neither body turns more than half a turn, by at most
///
///   n.(v_A - v_B) h + sum over the bodies of |w| e h + w^2 f h^2 / 2,
///
/// where e is how far the body's arms reach along n turned a quarter turn against its spin
/// (the arms there swing towards n) and f how far they reach back from n, both from -n for B:
/// a body pointing its long axis at the other gains little by turning. The next time is the later of the two
/// bounds' crossings of the target: the shapes cannot come closer than the target before it.
/// When neither bound ever crosses, they cannot come closer at all. Radii ride on the cores and
/// are subtracted at the end.

/// @brief How a body moves over a step: its centre of mass on a straight line and its angle at
/// a constant rate, both linear in the fraction t of the step (0 at the start, 1 at the end).
/// Unlike an interpolated rotation, the angles may differ by several turns.
struct Sweep {
  Vec2 local_center{0, 0};  ///< the centre of mass in the body's frame: what it turns about
  Vec2 center0{0, 0};       ///< world centre of mass at t = 0
  Vec2 center1{0, 0};       ///< world centre of mass at t = 1
  Real angle0 = 0;          ///< radians at t = 0
  Real angle1 = 0;          ///< radians at t = 1

  /// @brief The body's pose (the origin of its frame and its rotation) at fraction t.
  Pose pose_at(Real t) const;
};

/// @brief What time_of_impact found.
enum class ToiState : std::uint8_t {
  hit,         ///< came within target (plus or minus tolerance) at `fraction`
  separated,   ///< never closer than target - tolerance over [0, max_fraction]
  overlapped,  ///< already closer than target - tolerance at t = 0
  gave_up,     ///< the iteration cap stopped the search: `fraction` is the last safe time
};

/// @brief A time of impact query. The shapes are borrowed: they must outlive the call.
struct TimeOfImpactInput {
  const ShapeGeometry* shape_a = nullptr;  ///< in A's body frame
  Sweep sweep_a;                           ///< A's motion
  const ShapeGeometry* shape_b = nullptr;  ///< in B's body frame
  Sweep sweep_b;                           ///< B's motion
  Real max_fraction = 1;                   ///< the search covers [0, max_fraction], in [0, 1]
  /// Surface separation (radii included) to stop at. Negative lets rounded shapes sink into
  /// each other a little, but the cores must stay apart: target + both radii > tolerance.
  Real target = 0.005;
  Real tolerance = 0.00125;  ///< > 0: how far from target a hit may land
  int max_iterations = 500;  ///< distance evaluations allowed, >= 1
};

/// What time_of_impact found, and where. Positions are at `fraction`, world coordinates;
/// for `separated` only `fraction` (max_fraction) and `iterations` are set.
///
/// Guarantees (up to rounding in the distance, far below any useful tolerance):
/// - hit: the separation at `fraction` lies in [target - tolerance, target + tolerance] and
///   at every earlier time in [0, fraction) it was at least target - tolerance (by the bound
///   above, in fact at least target).
/// - separated: the separation stayed at least target - tolerance over all of [0, max_fraction].
/// - gave_up: as for hit over [0, fraction], with the separation at `fraction` still above
///   target + tolerance; a caller may advance the bodies that far safely.
/// - overlapped: the separation at t = 0 is below target - tolerance; `fraction` is 0.
struct TimeOfImpactOutput {
  ToiState state = ToiState::separated;  ///< see ToiState
  Real fraction = 0;                     ///< the time t, a fraction of the step
  /// Surface separation (radii included). When the cores themselves overlap (only possible
  /// for `overlapped`) it reads minus both radii, not a depth.
  Real separation = 0;
  Vec2 point_a{0, 0};  ///< nearest point of A's surface
  Vec2 point_b{0, 0};  ///< nearest point of B's surface
  Vec2 normal{0, 0};   ///< unit, A towards B; zero when the cores overlap
  int iterations = 0;  ///< distance evaluations made
};

/// A slop-based target in the manner of Box2D: the cores stop `linear_slop` apart, or, when the
/// radii are large enough, the surfaces sink `linear_slop` into each other, so a contact is
/// found at once after the impact.
/// @throws InvalidArgumentError for a linear_slop that is not finite and > 0
Real slop_target(const ShapeGeometry& a, const ShapeGeometry& b, Real linear_slop);

/// The first time in [0, max_fraction] at which the shapes come within `target` of each other,
/// by conservative advancement (see the file comment). Always terminates: it stops at a hit,
/// when the bound proves no hit can come, at max_fraction, or at max_iterations, and says which.
/// A chain segment counts as its two-sided segment.
/// @throws InvalidArgumentError naming the input: a null shape, a non-finite sweep,
/// max_fraction outside [0, 1], a tolerance not > 0, target + radii not > tolerance, or
/// max_iterations < 1
TimeOfImpactOutput time_of_impact(const TimeOfImpactInput& input);

}  // namespace mink
