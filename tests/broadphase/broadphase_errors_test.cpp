#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include "mink/broadphase/brute_force_broadphase.hpp"
#include "mink/broadphase/fixed_grid.hpp"
#include "mink/broadphase/sweep_and_prune.hpp"
#include "mink/error.hpp"

namespace {

using mink::Aabb;
using mink::Fattening;
using mink::ProxyKind;
using mink::Vec2;

template <typename T>
class BroadphaseErrors : public ::testing::Test {};
using Implementations = ::testing::Types<mink::SweepAndPrune, mink::BruteForceBroadphase>;
TYPED_TEST_SUITE(BroadphaseErrors, Implementations);

TYPED_TEST(BroadphaseErrors, RejectsBadBoxesIdsAndMargins) {
  TypeParam broadphase(0.1);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(broadphase.create_proxy({Vec2(0, nan), Vec2(1, 1)}, ProxyKind::moving, 0),
               mink::InvalidArgumentError);
  EXPECT_THROW(broadphase.create_proxy({Vec2(2, 0), Vec2(1, 1)}, ProxyKind::moving, 0),
               mink::InvalidArgumentError);
  const auto id = broadphase.create_proxy({Vec2(0, 0), Vec2(1, 1)}, ProxyKind::moving, 5);
  EXPECT_THROW(broadphase.move_proxy(id, {Vec2(0, 0), Vec2(INFINITY, 1)}),
               mink::InvalidArgumentError);
  EXPECT_THROW(broadphase.move_proxy(id + 1, {Vec2(0, 0), Vec2(1, 1)}), mink::InvalidArgumentError);
  EXPECT_THROW(broadphase.destroy_proxy(id + 7), mink::InvalidArgumentError);
  std::vector<mink::ProxyId> out;
  EXPECT_THROW(broadphase.query({Vec2(1, 0), Vec2(0, 1)}, out), mink::InvalidArgumentError);
  EXPECT_THROW(broadphase.query_point(Vec2(nan, 0), out), mink::InvalidArgumentError);
  broadphase.destroy_proxy(id);
  EXPECT_THROW(broadphase.destroy_proxy(id), mink::InvalidArgumentError);
  EXPECT_THROW(broadphase.fat_aabb(id), mink::InvalidArgumentError);
  EXPECT_THROW(broadphase.user_data(id), mink::InvalidArgumentError);
  EXPECT_THROW(TypeParam{-1.0}, mink::InvalidArgumentError);
  EXPECT_THROW(TypeParam{nan}, mink::InvalidArgumentError);
  EXPECT_THROW((TypeParam{Fattening{0.1, -1, 0}}), mink::InvalidArgumentError);
  EXPECT_THROW((TypeParam{Fattening{0.1, 0.125, nan}}), mink::InvalidArgumentError);
  try {
    broadphase.move_proxy(id, {Vec2(0, 0), Vec2(1, 1)});
    FAIL() << "no error";
  } catch (const mink::Error& error) {
    EXPECT_NE(std::string(error.what()).find("proxy " + std::to_string(id)), std::string::npos);
  }
}

TYPED_TEST(BroadphaseErrors, FatBoxFollowsTheMarginRule) {
  TypeParam broadphase(0.5);
  const auto id = broadphase.create_proxy({Vec2(0, 0), Vec2(1, 1)}, ProxyKind::moving, 9);
  EXPECT_EQ(broadphase.user_data(id), 9u);
  EXPECT_EQ(broadphase.fat_aabb(id).lower, Vec2(-0.5, -0.5));
  EXPECT_FALSE(broadphase.move_proxy(id, {Vec2(0.4, -0.5), Vec2(1.4, 0.5)}));
  EXPECT_EQ(broadphase.fat_aabb(id).upper, Vec2(1.5, 1.5));
  EXPECT_TRUE(broadphase.move_proxy(id, {Vec2(0.75, 0), Vec2(1.75, 1)}));
  EXPECT_EQ(broadphase.fat_aabb(id).lower, Vec2(0.25, -0.5));
  EXPECT_EQ(broadphase.proxy_count(), 1u);
}

TYPED_TEST(BroadphaseErrors, FatBoxReachesAheadAlongTheLastStep) {
  TypeParam broadphase(0.25);
  const auto id = broadphase.create_proxy({Vec2(0, 0), Vec2(1, 1)}, ProxyKind::moving, 0);
  // Steps of +0.125 in x, -0.0625 in y: the box leaves its fat box on the third step and
  // then reaches four steps ahead, on the side it moves to only.
  EXPECT_FALSE(broadphase.move_proxy(id, {Vec2(0.125, -0.0625), Vec2(1.125, 0.9375)}));
  EXPECT_FALSE(broadphase.move_proxy(id, {Vec2(0.25, -0.125), Vec2(1.25, 0.875)}));
  EXPECT_TRUE(broadphase.move_proxy(id, {Vec2(0.375, -0.1875), Vec2(1.375, 0.8125)}));
  EXPECT_EQ(broadphase.fat_aabb(id).lower, Vec2(0.125, -0.1875 - 0.25 - 4 * 0.0625));
  EXPECT_EQ(broadphase.fat_aabb(id).upper, Vec2(1.375 + 0.25 + 4 * 0.125, 0.8125 + 0.25));
  // A jump is no motion to predict: the reach is capped at four margins.
  EXPECT_TRUE(broadphase.move_proxy(id, {Vec2(100, 0), Vec2(101, 1)}));
  EXPECT_EQ(broadphase.fat_aabb(id).lower, Vec2(100 - 0.25, -0.25));
  EXPECT_EQ(broadphase.fat_aabb(id).upper, Vec2(101 + 0.25 + 4 * 0.25, 1 + 0.25 + 4 * 0.1875));
}

TYPED_TEST(BroadphaseErrors, SmallBoxesGetSmallMarginsAndNoReach) {
  TypeParam broadphase(Fattening{0.25, 0.125, 0});
  // Half-diagonal 2.5: an eighth of it is more than the margin, which then holds.
  const auto big = broadphase.create_proxy({Vec2(0, 0), Vec2(3, 4)}, ProxyKind::moving, 0);
  EXPECT_EQ(broadphase.fat_aabb(big).lower, Vec2(-0.25, -0.25));
  // Half-diagonal 0.25: the margin is an eighth of it.
  const auto small = broadphase.create_proxy({Vec2(0, 0), Vec2(0.3, 0.4)}, ProxyKind::moving, 1);
  EXPECT_EQ(broadphase.fat_aabb(small).upper, Vec2(0.3 + 0.03125, 0.4 + 0.03125));
  // Leaving its box, it is fattened around where it is, with no reach along the step.
  EXPECT_TRUE(broadphase.move_proxy(small, {Vec2(1, 0), Vec2(1.3, 0.4)}));
  EXPECT_EQ(broadphase.fat_aabb(small).lower, Vec2(1 - 0.03125, -0.03125));
  EXPECT_EQ(broadphase.fat_aabb(small).upper, Vec2(1.3 + 0.03125, 0.4 + 0.03125));
}

// A size given at creation sets the margin, whatever boxes the proxy is later given (a turning
// shape's box grows and shrinks; its size does not).
TYPED_TEST(BroadphaseErrors, AGivenSizeSetsTheMargin) {
  TypeParam broadphase(Fattening{0.25, 0.125, 0});
  const auto id = broadphase.create_proxy({Vec2(0, 0), Vec2(3, 4)}, ProxyKind::moving, 0, 0.5);
  EXPECT_EQ(broadphase.fat_aabb(id).lower, Vec2(-0.0625, -0.0625));
  EXPECT_TRUE(broadphase.move_proxy(id, {Vec2(10, 0), Vec2(11, 1)}));
  EXPECT_EQ(broadphase.fat_aabb(id).upper, Vec2(11.0625, 1.0625));
  // Large: the margin's cap holds.
  const auto big = broadphase.create_proxy({Vec2(0, 0), Vec2(1, 1)}, ProxyKind::moving, 1, 100);
  EXPECT_EQ(broadphase.fat_aabb(big).lower, Vec2(-0.25, -0.25));
  for (const mink::Real bad :
       {-0.5, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    EXPECT_THROW(broadphase.create_proxy({Vec2(0, 0), Vec2(1, 1)}, ProxyKind::moving, 2, bad),
                 mink::InvalidArgumentError)
        << bad;
  }
}

// Kinematic proxies pair as moving ones do, with static ones too; query_fixed finds them
// with the static ones and leaves the moving ones out.
TYPED_TEST(BroadphaseErrors, KinematicProxiesPairAsMovingAndAreFixedObstacles) {
  TypeParam broadphase(0);
  const auto ground = broadphase.create_proxy({Vec2(0, 0), Vec2(4, 1)}, ProxyKind::static_body, 0);
  const auto mover = broadphase.create_proxy({Vec2(1, 0.5), Vec2(2, 1.5)}, ProxyKind::kinematic, 1);
  const auto box = broadphase.create_proxy({Vec2(1.5, 1), Vec2(2.5, 2)}, ProxyKind::moving, 2);
  mink::PairEvents events;
  broadphase.update_pairs(events);
  EXPECT_EQ(broadphase.pairs().size(), 3u);  // ground-mover, ground-box, mover-box
  std::vector<mink::ProxyId> found;
  broadphase.query_fixed({Vec2(0, 0), Vec2(4, 4)}, found);
  std::sort(found.begin(), found.end());
  EXPECT_EQ(found, (std::vector<mink::ProxyId>{ground, mover}));
  found.clear();
  broadphase.query({Vec2(0, 0), Vec2(4, 4)}, found);
  EXPECT_EQ(found.size(), 3u);
  (void)box;
}

TYPED_TEST(BroadphaseErrors, StaticPairsAreNeverReported) {
  TypeParam broadphase(0);
  const auto a = broadphase.create_proxy({Vec2(0, 0), Vec2(1, 1)}, ProxyKind::static_body, 0);
  const auto b = broadphase.create_proxy({Vec2(1, 1), Vec2(2, 2)}, ProxyKind::static_body, 1);
  mink::PairEvents events;
  broadphase.update_pairs(events);
  EXPECT_TRUE(broadphase.pairs().empty());
  const auto c = broadphase.create_proxy({Vec2(0.5, 0.5), Vec2(1.5, 1.5)}, ProxyKind::moving, 2);
  broadphase.update_pairs(events);
  // Touching counts as overlapping.
  ASSERT_EQ(events.begun.size(), 2u);
  EXPECT_EQ(broadphase.pairs().size(), 2u);
  (void)a;
  (void)b;
  (void)c;
}

}  // namespace

// A snapshot's broadphase lays out its grid of fixed obstacles before the boxes are checked,
// so the grid takes any boxes: upside down, infinite, not a number, at the ends of the doubles
// (the snapshot-restore fuzzer's find: an upside-down box gave a negative count of cells).
// Among them, the well-formed boxes are still found as a scan finds them.
TEST(FixedGrid, LaysOutAnyBoxesItIsGiven) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  constexpr double big = std::numeric_limits<double>::max();
  const std::vector<std::vector<mink::FixedGrid::Box>> sets = {
      {{5, -1e42, 0, 1, 0}},
      {{0, 1, 0, 1, 0}, {3, 2, 7, -7, 1}, {-2, -1, 4, 5, 2}},
      {{nan, nan, nan, nan, 0}, {0, 1, 0, 1, 1}},
      {{-inf, inf, -inf, inf, 0}, {0, 1, 0, 1, 1}},
      {{-big, -big, 0, 0, 0}, {big, big, 1, 1, 1}, {0, 1, 0, 1, 2}},
      {{0, 0, 0, 0, 0}, {0, 0, 0, 0, 1}},
  };
  for (std::size_t k = 0; k < sets.size(); ++k) {
    mink::FixedGrid grid;
    grid.build(sets[k]);
    for (const mink::FixedGrid::Box& q :
         {mink::FixedGrid::Box{-3, 3, -3, 3, 0}, mink::FixedGrid::Box{0.5, 0.5, 0.5, 0.5, 0},
          mink::FixedGrid::Box{-big, big, -big, big, 0}}) {
      std::vector<mink::ProxyId> found, scanned;
      grid.query(q, [&](mink::ProxyId id) { found.push_back(id); });
      for (const mink::FixedGrid::Box& b : sets[k]) {
        const bool well_formed = b.lo0 <= b.hi0 && b.lo1 <= b.hi1 && std::isfinite(b.lo0) &&
                                 std::isfinite(b.hi0) && std::isfinite(b.lo1) &&
                                 std::isfinite(b.hi1);
        if (well_formed && b.lo0 <= q.hi0 && q.lo0 <= b.hi0 && b.lo1 <= q.hi1 && q.lo1 <= b.hi1) {
          scanned.push_back(b.id);
        }
      }
      std::sort(found.begin(), found.end());
      for (const mink::ProxyId id : scanned) {
        EXPECT_TRUE(std::binary_search(found.begin(), found.end(), id))
            << "set " << k << ", id " << id;
      }
    }
  }
}
