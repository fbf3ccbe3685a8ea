// compute_mass against numeric integration over a fine grid, with the brute-force inside test
// of shape_oracle.hpp.

#include <gtest/gtest.h>

#include <numbers>

#include "mink/error.hpp"
#include "shape_oracle.hpp"

namespace {

using namespace mink_test;

#ifdef MINK_SANITIZED_BUILD
constexpr int kGrid = 500;
constexpr Real kTolerance = 4e-3;
#else
constexpr int kGrid = 1600;
constexpr Real kTolerance = 1e-3;
#endif

struct Integrated {
  Real mass = 0;
  Vec2 center{0, 0};
  Real inertia = 0;
};

// Midpoint rule over a kGrid x kGrid grid covering the shape (local frame).
Integrated integrate(const ShapeGeometry& shape, Real density) {
  const WorldCore core = world_core(shape, Pose{});
  Vec2 lo = core.points[0], hi = core.points[0];
  for (const Vec2& p : core.points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  lo -= Vec2(core.radius, core.radius);
  hi += Vec2(core.radius, core.radius);
  const Vec2 h = (hi - lo) / kGrid;
  const Real cell = h.x() * h.y();
  Real area = 0, polar = 0;
  Vec2 first(0, 0);
  for (int i = 0; i < kGrid; ++i) {
    for (int j = 0; j < kGrid; ++j) {
      const Vec2 p = lo + Vec2((i + 0.5) * h.x(), (j + 0.5) * h.y());
      if (point_signed_distance(core, p) > 0) continue;
      area += cell;
      first += cell * p;
      polar += cell * p.squaredNorm();
    }
  }
  Integrated r;
  r.mass = density * area;
  r.center = first / area;
  r.inertia = density * (polar - area * r.center.squaredNorm());
  return r;
}

void expect_mass_matches(const ShapeGeometry& shape, Real density) {
  const mink::MassData exact = mink::compute_mass(shape, density);
  const Integrated numeric = integrate(shape, density);
  const WorldCore core = world_core(shape, Pose{});
  Real size = core.radius;
  for (const Vec2& p : core.points) size = std::max(size, (p - exact.center).norm() + core.radius);
  EXPECT_NEAR(exact.mass, numeric.mass, kTolerance * numeric.mass);
  EXPECT_NEAR((exact.center - numeric.center).norm(), 0, kTolerance * size);
  EXPECT_NEAR(exact.rotational_inertia, numeric.inertia, kTolerance * numeric.inertia);
}

TEST(ShapeMass, CircleMatchesIntegration) {
  std::mt19937_64 rng(1);
  for (int k = 0; k < 3; ++k) expect_mass_matches(random_shape(rng, ShapeKind::circle), 2.5);
  // And the closed form itself.
  const mink::MassData m = mink::compute_mass(mink::Circle{Vec2(1, 2), 0.5}, 4);
  EXPECT_NEAR(m.mass, 4 * std::numbers::pi * 0.25, 1e-12);
  EXPECT_NEAR(m.rotational_inertia, 0.5 * m.mass * 0.25, 1e-12);
}

TEST(ShapeMass, CapsuleMatchesIntegration) {
  std::mt19937_64 rng(2);
  for (int k = 0; k < 3; ++k) expect_mass_matches(random_shape(rng, ShapeKind::capsule), 1.5);
}

TEST(ShapeMass, PolygonMatchesIntegration) {
  std::mt19937_64 rng(3);
  for (int k = 0; k < 3; ++k) expect_mass_matches(mink::RoundedPolygon{random_hull(rng, 6), 0}, 3);
}

TEST(ShapeMass, RoundedPolygonMatchesIntegration) {
  std::mt19937_64 rng(4);
  for (Real radius : {0.05, 0.3, 1.0}) {
    expect_mass_matches(mink::RoundedPolygon{random_hull(rng, 5), radius}, 2);
  }
  // A rounded box is a box, four edge strips and one full disk.
  const Real r = 0.2;
  const mink::MassData m = mink::compute_mass(mink::RoundedPolygon{box(0.5, 0.25), r}, 1);
  EXPECT_NEAR(m.mass, 1 * 0.5 + 2 * (1 * r + 0.5 * r) + std::numbers::pi * r * r, 1e-12);
  EXPECT_NEAR(m.center.norm(), 0, 1e-12);
}

TEST(ShapeMass, SegmentsAndChainsHaveNoMass) {
  const mink::MassData s = mink::compute_mass(mink::Segment{Vec2(0, 0), Vec2(2, 0)}, 5);
  EXPECT_EQ(s.mass, 0);
  EXPECT_EQ(s.rotational_inertia, 0);
  EXPECT_EQ(s.center, Vec2(1, 0));
  const mink::MassData c = mink::compute_mass(
      mink::ChainSegment{Vec2(-1, 0), mink::Segment{Vec2(0, 0), Vec2(0, 2)}, Vec2(1, 0)}, 5);
  EXPECT_EQ(c.mass, 0);
}

TEST(ShapeMass, RejectsBadInput) {
  EXPECT_THROW(mink::compute_mass(mink::Circle{Vec2(0, 0), 0}, 1), mink::InvalidArgumentError);
  EXPECT_THROW(mink::compute_mass(mink::Circle{Vec2(0, 0), 1}, -1), mink::InvalidArgumentError);
  EXPECT_THROW(mink::compute_mass(mink::Capsule{Vec2(1, 1), Vec2(1, 1), 0.5}, 1),
               mink::InvalidArgumentError);
  EXPECT_THROW(mink::compute_mass(mink::Segment{Vec2(1, 1), Vec2(1, 1)}, 1),
               mink::InvalidArgumentError);
  EXPECT_THROW(mink::compute_mass(mink::RoundedPolygon{box(1, 1), -0.1}, 1),
               mink::InvalidArgumentError);
  try {
    mink::compute_mass(mink::Capsule{Vec2(0, 0), Vec2(1, 0), -2}, 1);
    FAIL();
  } catch (const mink::InvalidArgumentError& e) {
    EXPECT_NE(std::string(e.what()).find("capsule radius"), std::string::npos) << e.what();
  }
}

}  // namespace
