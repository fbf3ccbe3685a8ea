// The direct solve of contact stacks: its complementarity solver against trying every set of
// pushing rows, and stacks of very different masses in a world against closed-form rest.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include "contact_stack_solver.hpp"
#include "test_worlds.hpp"

namespace {

using namespace mink;

// The slow twin: every set of pushing rows in turn, solved by Gaussian elimination; the one
// whose pushes are all non-negative and whose other rows do not approach. For a positive
// definite K exactly one set qualifies (up to rows at exactly zero).
std::vector<double> complementarity_by_every_set(const std::vector<double>& k,
                                                 const std::vector<double>& q, int n) {
  for (std::uint32_t set = 0; set < (1u << n); ++set) {
    std::vector<int> rows;
    for (int i = 0; i < n; ++i) {
      if (set >> i & 1) rows.push_back(i);
    }
    const auto m = static_cast<int>(rows.size());
    std::vector<double> a(static_cast<std::size_t>(m * (m + 1)));
    for (int i = 0; i < m; ++i) {
      for (int j = 0; j < m; ++j) a[i * (m + 1) + j] = k[rows[i] * n + rows[j]];
      a[i * (m + 1) + m] = -q[rows[i]];
    }
    for (int c = 0; c < m; ++c) {
      int best = c;
      for (int r = c + 1; r < m; ++r) {
        if (std::abs(a[r * (m + 1) + c]) > std::abs(a[best * (m + 1) + c])) best = r;
      }
      for (int j = 0; j <= m; ++j) std::swap(a[c * (m + 1) + j], a[best * (m + 1) + j]);
      for (int r = 0; r < m; ++r) {
        if (r == c) continue;
        const double f = a[r * (m + 1) + c] / a[c * (m + 1) + c];
        for (int j = 0; j <= m; ++j) a[r * (m + 1) + j] -= f * a[c * (m + 1) + j];
      }
    }
    std::vector<double> x(static_cast<std::size_t>(n), 0.0);
    double size = 0;
    for (int i = 0; i < n; ++i) size = std::max(size, std::abs(q[i]));
    bool ok = true;
    for (int i = 0; i < m; ++i) {
      x[rows[i]] = a[i * (m + 1) + m] / a[i * (m + 1) + i];
      ok = ok && x[rows[i]] >= 0;
    }
    for (int i = 0; i < n && ok; ++i) {
      if (set >> i & 1) continue;
      double w = q[i];
      for (int j = 0; j < n; ++j) w += k[i * n + j] * x[j];
      ok = w >= -1e-9 * size;
    }
    if (ok) return x;
  }
  return {};
}

// Random positive definite matrices: B B^T with a millionth more on the diagonal (as the
// stacks have), some nearly singular (B with fewer columns than rows, as rows outnumbering
// their bodies' degrees of freedom), rows scaled over three orders of magnitude (mass ratios
// of 1000), from any starting guess. The answers agree in what the pushes do (K x + q, which a
// nearly singular K fixes where it leaves the pushes themselves loose), and each answer is
// complementary: no pull, no approach, no push where the bodies part.
TEST(ContactStack, ComplementarityAgreesWithTryingEverySetOfRows) {
  std::mt19937_64 random(20261207);
  std::uniform_real_distribution<double> unit(-1, 1);
  int solved = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const int n = 1 + trial % 10;
    const int columns = trial % 3 == 0 ? std::max(1, n - 2) : n + 2;
    std::vector<double> b(static_cast<std::size_t>(n * columns));
    for (int i = 0; i < n; ++i) {
      const double scale = std::pow(10.0, 1.5 * unit(random));
      for (int j = 0; j < columns; ++j) b[i * columns + j] = scale * unit(random);
    }
    std::vector<double> k(static_cast<std::size_t>(n * n)), q(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        double sum = 0;
        for (int t = 0; t < columns; ++t) sum += b[i * columns + t] * b[j * columns + t];
        k[i * n + j] = sum;
      }
    }
    for (int i = 0; i < n; ++i) {
      k[i * n + i] *= 1 + 1e-6;
      q[i] = std::sqrt(k[i * n + i]) * unit(random);
    }
    std::vector<double> x(static_cast<std::size_t>(n));
    auto active = static_cast<std::uint32_t>(random()) & ((1u << n) - 1);
    ASSERT_TRUE(detail::solve_complementarity(k, q, n, x, active)) << "trial " << trial;
    const std::vector<double> expected = complementarity_by_every_set(k, q, n);
    ASSERT_EQ(expected.size(), static_cast<std::size_t>(n)) << "trial " << trial;
    for (int i = 0; i < n; ++i) {
      double w = q[i], w_expected = q[i], size = std::abs(q[i]);
      for (int j = 0; j < n; ++j) {
        w += k[i * n + j] * x[j];
        w_expected += k[i * n + j] * expected[j];
        size += std::abs(k[i * n + j] * expected[j]);
      }
      EXPECT_NEAR(w, w_expected, 1e-6 * size) << "trial " << trial << ", row " << i;
      EXPECT_GE(x[i], 0) << "trial " << trial << ", row " << i;
      EXPECT_GE(w, -1e-6 * size) << "trial " << trial << ", row " << i;
      EXPECT_LE(std::abs(w) * x[i], 1e-6 * size * std::abs(x[i]) + 1e-300)
          << "trial " << trial << ", row " << i;
      EXPECT_TRUE((active >> i & 1) != 0 ? std::abs(w) <= 1e-6 * size : x[i] == 0)
          << "trial " << trial << ", row " << i;
    }
    ++solved;
  }
  EXPECT_EQ(solved, 4000);
}

BodyId add_box(World& world, const Vec2& position, Real half, Real density) {
  ShapeDef shape = ShapeDef::box(half, half);
  shape.density = density;
  return test::add_body(world, position, shape);
}

// A column of 1 m boxes on the ground, densities from the bottom up, awake throughout (a
// sleeping stack would hide a slow sag).
WorldDef awake_world() {
  WorldDef def;
  def.enable_sleep = false;
  return def;
}

struct Column {
  World world;
  std::vector<BodyId> boxes;
  explicit Column(const std::vector<Real>& densities, const WorldDef& def = awake_world())
      : world(def) {
    test::add_ground(world);
    for (std::size_t level = 0; level < densities.size(); ++level) {
      boxes.push_back(
          add_box(world, Vec2(0, 0.5 + static_cast<Real>(level)), 0.5, densities[level]));
    }
  }
};

// At the default settings (60 Hz contacts, 5 substeps), a 1 kg box under two 1000 kg ones,
// two 1 kg boxes under a 1000 kg one, alternating 1 and 1000 kg boxes, and a 1000 kg box on a
// column of fifteen 1 kg ones (the most a stack's 32 points hold). Solved together,
// a soft contact sags by the acceleration its pushes give its two bodies apart, over omega^2.
// Every box is held still, so a contact between two boxes pushes them apart not at all, and
// the ground's contact (twice the stiffness, 120 Hz) by the bottom box's g: it sinks by
// g / (2 pi 120)^2 = 17.6 um, and every box above rides on it, each contact adding under a
// micrometre. One contact at a time, the bottom contact sags by all the weight it carries
// over the light box's mass (2001 g / (1 kg (2 pi 120)^2) = 3.5 cm) and the stack falls.
TEST(ContactStack, LightBoxesUnderHeavyOnesRestAsTheSoftStepGivesAtTheDefaultSettings) {
  const WorldDef def = awake_world();
  const Real omega = 2 * std::numbers::pi * 2 * def.contact_hertz;
  const Real sag = -def.gravity.y() / (omega * omega);
  for (const std::vector<Real>& densities :
       {std::vector<Real>{1, 1000, 1000}, std::vector<Real>{1, 1, 1000},
        std::vector<Real>{1, 1000, 1, 1000}, std::vector<Real>{1, 100, 10000},
        std::vector<Real>{1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1000}}) {
    Column column(densities, def);
    std::size_t stacked = 0;
    for (int i = 0; i < 600; ++i) {
      column.world.step();
      ASSERT_TRUE(test::all_finite(column.world)) << "step " << i;
      stacked = std::max(stacked, column.world.counters().stacked_constraints);
    }
    EXPECT_EQ(stacked, densities.size());  // every contact of the column, the ground's too
    for (std::size_t level = 0; level < densities.size(); ++level) {
      const Vec2 p = column.world.position(column.boxes[level]);
      const Real ideal = 0.5 + static_cast<Real>(level) - sag;
      EXPECT_NEAR(p.y(), ideal, 0.05 * sag + 1e-6 * static_cast<Real>(level))
          << "density " << densities[level] << ", level " << level;
      EXPECT_NEAR(p.x(), 0, 1e-6) << "level " << level;
      EXPECT_NEAR(column.world.angle(column.boxes[level]), 0, 1e-6) << "level " << level;
      EXPECT_LT(column.world.linear_velocity(column.boxes[level]).norm(), 1e-4);
    }
  }
}

// Bodies of like masses make no stack: their contacts stay in the SIMD colours.
TEST(ContactStack, LikeMassesMakeNoStack) {
  Column column({1, 5, 1, 9});
  for (int i = 0; i < 120; ++i) {
    column.world.step();
    ASSERT_EQ(column.world.counters().stacked_constraints, 0u) << "step " << i;
  }
}

// A 1000 kg box dropped from 0.3 m onto a 1 kg box on the ground comes to rest on it, the
// light box not crushed: both end at their heights less the ground contact's sag, at rest.
TEST(ContactStack, HeavyBoxDroppedOnALightOneComesToRestOnIt) {
  World world(awake_world());
  test::add_ground(world);
  const BodyId light = add_box(world, Vec2(0, 0.5), 0.5, 1);
  const BodyId heavy = add_box(world, Vec2(0, 1.8), 0.5, 1000);
  for (int i = 0; i < 600; ++i) {
    world.step();
    ASSERT_TRUE(test::all_finite(world)) << "step " << i;
  }
  EXPECT_NEAR(world.position(light).y(), 0.5, 1e-4);
  EXPECT_NEAR(world.position(heavy).y(), 1.5, 1e-4);
  EXPECT_NEAR(world.angle(light), 0, 1e-4);
  EXPECT_LT(world.linear_velocity(heavy).norm(), 1e-4);
}

// Only paths are stacks (each moving body in at most two of its contacts): a light plank on
// two supports under a heavy box is in three, and stays one contact at a time.
TEST(ContactStack, ALightBodyInThreeContactsIsInNoStack) {
  World world(awake_world());
  test::add_ground(world);
  for (const Real x : {-2.0, 2.0}) {
    BodyDef def;
    def.position = Vec2(x, 0.5);
    world.create_shape(world.create_body(def), ShapeDef::box(0.25, 0.5));
  }
  ShapeDef plank = ShapeDef::box(2.5, 0.05);
  test::add_body(world, Vec2(0, 1.05), plank);
  add_box(world, Vec2(0, 1.6), 0.5, 1000);
  for (int i = 0; i < 60; ++i) {
    world.step();
    ASSERT_EQ(world.counters().stacked_constraints, 0u) << "step " << i;
  }
}

// With stacks, the SIMD solver and its one-at-a-time twin, and any worker count, give the same
// bits: the stacks are solved in the overflow, one worker, in constraint order.
TEST(ContactStack, StacksKeepTheSolverTwinsAndWorkerCountsBitwiseEqual) {
  const auto run = [](bool simd, int workers) {
    WorldDef def;
    def.simd_solver = simd;
    def.worker_count = workers;
    World world(def);
    test::add_ground(world, 40);
    for (int column = 0; column < 12; ++column) {
      for (int level = 0; level < 4; ++level) {
        const Real density = (level + column) % 3 == 0 ? 1 : 500;
        add_box(world, Vec2(-22 + 4 * column, 0.5 + level), 0.5, density);
      }
    }
    std::size_t stacked = 0;
    for (int i = 0; i < 120; ++i) {
      world.step();
      stacked = std::max(stacked, world.counters().stacked_constraints);
    }
    EXPECT_GT(stacked, 0u);
    return test::state_hash(world);
  };
  const auto reference = run(true, 1);
  EXPECT_EQ(run(false, 1), reference);
  EXPECT_EQ(run(true, 2), reference);
  EXPECT_EQ(run(false, 3), reference);
}

// A snapshot taken while a stack is solved resumes it exactly, at another worker count too:
// stacks are found afresh each step from the state (the warm-start impulses among it).
TEST(ContactStack, ASnapshotResumesAStackExactly) {
  Column column({1, 1000, 1, 1000});
  for (int i = 0; i < 45; ++i) column.world.step();
  ASSERT_GT(column.world.counters().stacked_constraints, 0u);
  World resumed = World::from_snapshot(column.world.snapshot(), 2);
  for (int i = 0; i < 120; ++i) {
    column.world.step();
    resumed.step();
  }
  EXPECT_EQ(test::state_hash(resumed), test::state_hash(column.world));
}

}  // namespace
