// SweepAndPrune against BruteForceBroadphase: the same script of creations, motions,
// teleports and destructions drives both, and after every update the pair sets, the begun
// and ended events and the query answers must be identical.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "mink/broadphase/brute_force_broadphase.hpp"
#include "mink/broadphase/sweep_and_prune.hpp"

namespace {

using mink::Aabb;
using mink::Broadphase;
using mink::ProxyId;
using mink::ProxyKind;
using mink::ProxyPair;
using mink::Real;
using mink::Vec2;

#ifdef MINK_SANITIZED_BUILD
constexpr int kScale = 4;  // sanitized runs do a quarter of the work (pair counts shrink more)
#else
constexpr int kScale = 1;
#endif

using HandlePairs = std::vector<std::pair<std::uint64_t, std::uint64_t>>;

// Proxy id -> the test's handle for one implementation. Ended events may name proxies
// destroyed since the last update, whose user data is gone, so the test keeps its own map;
// it also lets the two implementations number their proxies differently.
class Handles {
 public:
  void set(ProxyId id, std::uint64_t handle) {
    if (id >= handles_.size()) handles_.resize(id + 1, ~std::uint64_t{0});
    handles_[id] = handle;
  }
  std::uint64_t operator()(ProxyId id) const {
    EXPECT_LT(id, handles_.size());
    return id < handles_.size() ? handles_[id] : ~std::uint64_t{0};
  }
  // Sorted; duplicates kept so they show up as differences.
  HandlePairs named(const std::vector<ProxyPair>& pairs) const {
    HandlePairs named;
    for (const ProxyPair& pair : pairs) {
      EXPECT_LT(pair.a, pair.b);
      const std::uint64_t a = (*this)(pair.a), b = (*this)(pair.b);
      named.emplace_back(std::min(a, b), std::max(a, b));
    }
    std::sort(named.begin(), named.end());
    return named;
  }
  std::vector<std::uint64_t> named(const std::vector<ProxyId>& ids) const {
    std::vector<std::uint64_t> named;
    for (ProxyId id : ids) named.push_back((*this)(id));
    std::sort(named.begin(), named.end());
    return named;
  }

 private:
  std::vector<std::uint64_t> handles_;
};

// How a scenario places and moves boxes.
struct Layout {
  std::string name;
  mink::Fattening fattening;  // a margin of 0.1 reaching four steps ahead, unless changed
  // A new tight box.
  std::function<Aabb(std::mt19937_64&)> spawn;
  // The tight box after one step of ordinary motion.
  std::function<Aabb(std::mt19937_64&, const Aabb&)> step;
  Real static_fraction = 0.1;
  int initial = 300;
  int steps = 150;
  Real teleport_rate = 0.01;
  Real create_rate = 0.02;
  Real destroy_rate = 0.02;
  Real move_fraction = 0.7;
};

Real uniform(std::mt19937_64& random, Real low, Real high) {
  return std::uniform_real_distribution<Real>(low, high)(random);
}

Aabb box_at(const Vec2& center, const Vec2& half) {
  return {center - half, center + half};
}

Aabb jitter(std::mt19937_64& random, const Aabb& box, Real amount) {
  const Vec2 shift(uniform(random, -amount, amount), uniform(random, -amount, amount));
  return {box.lower + shift, box.upper + shift};
}

class Twin {
 public:
  explicit Twin(const mink::Fattening& fattening) : fast_(fattening), slow_(fattening) {}

  void create(const Aabb& box, ProxyKind kind) {
    const std::uint64_t handle = next_handle_++;
    live_.push_back(
        {fast_.create_proxy(box, kind, handle), slow_.create_proxy(box, kind, handle), box, kind});
    fast_handles_.set(live_.back().fast, handle);
    slow_handles_.set(live_.back().slow, handle);
    EXPECT_EQ(fast_.user_data(live_.back().fast), handle);
  }
  void destroy(std::size_t index) {
    fast_.destroy_proxy(live_[index].fast);
    slow_.destroy_proxy(live_[index].slow);
    live_[index] = live_.back();
    live_.pop_back();
  }
  void move(std::size_t index, const Aabb& box) {
    Body& body = live_[index];
    body.box = box;
    const bool fast_changed = fast_.move_proxy(body.fast, box);
    const bool slow_changed = slow_.move_proxy(body.slow, box);
    ASSERT_EQ(fast_changed, slow_changed);
    ASSERT_EQ(fast_.fat_aabb(body.fast).lower, slow_.fat_aabb(body.slow).lower);
    ASSERT_EQ(fast_.fat_aabb(body.fast).upper, slow_.fat_aabb(body.slow).upper);
  }

  // Updates both and compares everything; returns the number of pairs.
  std::size_t update_and_compare(const std::string& where) {
    SCOPED_TRACE(where);
    fast_.update_pairs(fast_events_);
    slow_.update_pairs(slow_events_);
    EXPECT_EQ(fast_.proxy_count(), slow_.proxy_count());
    const HandlePairs slow_pairs = slow_handles_.named(slow_.pairs());
    EXPECT_EQ(fast_handles_.named(fast_.pairs()), slow_pairs);
    EXPECT_EQ(fast_handles_.named(fast_events_.begun), slow_handles_.named(slow_events_.begun));
    EXPECT_EQ(fast_handles_.named(fast_events_.ended), slow_handles_.named(slow_events_.ended));
    return slow_pairs.size();
  }

  void compare_query(const Aabb& box) {
    std::vector<ProxyId> fast_out, slow_out;
    fast_.query(box, fast_out);
    slow_.query(box, slow_out);
    EXPECT_EQ(fast_handles_.named(fast_out), slow_handles_.named(slow_out));
    fast_out.clear();
    slow_out.clear();
    fast_.query_fixed(box, fast_out);
    slow_.query_fixed(box, slow_out);
    EXPECT_EQ(fast_handles_.named(fast_out), slow_handles_.named(slow_out));
    // A "no" from the cheap test is the query's answer too.
    if (!fast_.may_meet_fixed(box)) {
      EXPECT_TRUE(slow_out.empty());
    }
  }
  void compare_point_query(const Vec2& point) {
    std::vector<ProxyId> fast_out, slow_out;
    fast_.query_point(point, fast_out);
    slow_.query_point(point, slow_out);
    EXPECT_EQ(fast_handles_.named(fast_out), slow_handles_.named(slow_out));
  }

  std::size_t size() const { return live_.size(); }
  const Aabb& box(std::size_t index) const { return live_[index].box; }
  bool is_static(std::size_t index) const { return live_[index].kind == ProxyKind::static_body; }
  const mink::SweepAndPrune& fast() const { return fast_; }

 private:
  struct Body {
    ProxyId fast;
    ProxyId slow;
    Aabb box;
    ProxyKind kind;
  };
  mink::SweepAndPrune fast_;
  mink::BruteForceBroadphase slow_;
  mink::PairEvents fast_events_, slow_events_;
  Handles fast_handles_, slow_handles_;
  std::vector<Body> live_;
  std::uint64_t next_handle_ = 0;
};

// Runs one scenario; returns the largest pair count seen, so tests can check they were not
// vacuous.
std::size_t run(const Layout& layout, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  Twin twin(layout.fattening);
  std::bernoulli_distribution coin(0.5);
  const auto kind = [&] {
    // A tenth of the moving proxies kinematic: they pair as moving ones do, and query_fixed
    // finds them with the static ones.
    if (uniform(random, 0, 1) < layout.static_fraction) return ProxyKind::static_body;
    return uniform(random, 0, 1) < 0.1 ? ProxyKind::kinematic : ProxyKind::moving;
  };
  for (int i = 0; i < layout.initial / kScale; ++i) twin.create(layout.spawn(random), kind());
  std::size_t most_pairs = twin.update_and_compare(layout.name + " initial");
  const int steps = layout.steps / kScale;
  for (int step = 0; step < steps; ++step) {
    for (std::size_t i = 0; i < twin.size(); ++i) {
      // Statics mostly stay put, but may be moved like any proxy.
      if (twin.is_static(i) && uniform(random, 0, 1) < 0.95) continue;
      if (uniform(random, 0, 1) > layout.move_fraction) continue;
      const Aabb box = uniform(random, 0, 1) < layout.teleport_rate
                           ? layout.spawn(random)
                           : layout.step(random, twin.box(i));
      twin.move(i, box);
      if (::testing::Test::HasFatalFailure()) return most_pairs;
    }
    const int creations =
        std::poisson_distribution<int>(layout.create_rate * layout.initial / kScale)(random);
    for (int c = 0; c < creations; ++c) twin.create(layout.spawn(random), kind());
    const int destructions =
        std::poisson_distribution<int>(layout.destroy_rate * layout.initial / kScale)(random);
    for (int d = 0; d < destructions && twin.size() > 0; ++d) {
      twin.destroy(std::uniform_int_distribution<std::size_t>(0, twin.size() - 1)(random));
    }
    // Now and then a burst: mass insertion or mass destruction.
    if (step % 37 == 36) {
      if (coin(random)) {
        for (int c = 0; c < layout.initial / kScale; ++c) twin.create(layout.spawn(random), kind());
      } else {
        while (twin.size() > static_cast<std::size_t>(layout.initial / kScale / 3)) {
          twin.destroy(std::uniform_int_distribution<std::size_t>(0, twin.size() - 1)(random));
        }
      }
    }
    if (step % 11 == 5) {
      // A proxy created and destroyed between two updates never pairs.
      twin.create(layout.spawn(random), kind());
      twin.destroy(twin.size() - 1);
    }
    most_pairs = std::max(most_pairs,
                          twin.update_and_compare(layout.name + " step " + std::to_string(step)));
    if (::testing::Test::HasFailure()) return most_pairs;
    for (int q = 0; q < 4; ++q) {
      const Aabb probe = layout.spawn(random);
      twin.compare_query(uniform(random, 0, 1) < 0.5 ? probe : probe.fattened(3));
      twin.compare_point_query(probe.lower);
      if (twin.size() > 0) twin.compare_point_query(twin.box(0).upper);
    }
    // Queries also answer between moves and the next update.
    if (twin.size() > 0) {
      twin.move(0, layout.spawn(random));
      twin.compare_query(twin.box(0).fattened(1));
    }
  }
  return most_pairs;
}

Layout uniform_layout() {
  Layout layout;
  layout.name = "uniform";
  layout.spawn = [](std::mt19937_64& r) {
    return box_at(Vec2(uniform(r, 0, 40), uniform(r, 0, 40)), Vec2(0.5, 0.5));
  };
  layout.step = [](std::mt19937_64& r, const Aabb& box) { return jitter(r, box, 0.15); };
  return layout;
}

// Runs the layout for seeds first ... last: each run's largest pair count must exceed `pairs`
// (scaled down in sanitized builds). Stops at the first failure.
void expect_pairs_over(const Layout& layout, std::uint64_t first, std::uint64_t last,
                       std::size_t pairs) {
  for (std::uint64_t seed = first; seed <= last; ++seed) {
    EXPECT_GT(run(layout, seed), pairs / (kScale * kScale));
    if (testing::Test::HasFailure()) return;
  }
}

TEST(SweepAndPruneOracle, UniformUnitBoxes) {
  expect_pairs_over(uniform_layout(), 1, 6, 50);
}

// The engine's fattening: margins by size, no reach ahead.
TEST(SweepAndPruneOracle, UniformUnitBoxesWithMarginsBySize) {
  Layout layout = uniform_layout();
  layout.fattening = {0.05, 0.125, 0};
  expect_pairs_over(layout, 1, 6, 30);
}

TEST(SweepAndPruneOracle, MixedSizesFromTinyToHuge) {
  Layout layout = uniform_layout();
  layout.name = "mixed sizes";
  layout.spawn = [](std::mt19937_64& r) {
    const Real roll = uniform(r, 0, 1);
    const Vec2 center(uniform(r, -30, 30), uniform(r, -30, 30));
    if (roll < 0.05) return box_at(center, Vec2(uniform(r, 5, 40), uniform(r, 5, 40)));
    if (roll < 0.3) return box_at(center, Vec2(1e-7, 1e-7));
    if (roll < 0.35) return box_at(center, Vec2(uniform(r, 10, 30), 0.1));  // long and thin
    return box_at(center, Vec2(uniform(r, 0.2, 1), uniform(r, 0.2, 1)));
  };
  layout.step = [](std::mt19937_64& r, const Aabb& box) { return jitter(r, box, 0.3); };
  expect_pairs_over(layout, 11, 14, 50);
}

TEST(SweepAndPruneOracle, AllBoxesOnOneVerticalLine) {
  Layout layout = uniform_layout();
  layout.name = "vertical line";
  layout.spawn = [](std::mt19937_64& r) {
    return box_at(Vec2(3, uniform(r, -100, 100)), Vec2(0.5, 0.5));
  };
  layout.step = [](std::mt19937_64& r, const Aabb& box) {
    const Real dy = uniform(r, -0.2, 0.2);
    return Aabb{box.lower + Vec2(0, dy), box.upper + Vec2(0, dy)};
  };
  expect_pairs_over(layout, 21, 24, 50);
}

TEST(SweepAndPruneOracle, IdenticalBoxes) {
  Layout layout = uniform_layout();
  layout.name = "identical";
  layout.initial = 120;
  layout.steps = 60;
  layout.spawn = [](std::mt19937_64&) { return box_at(Vec2(1, 2), Vec2(0.5, 0.5)); };
  // Sometimes a step, sometimes back: many boxes exactly equal at every update.
  layout.step = [](std::mt19937_64& r, const Aabb& box) {
    return uniform(r, 0, 1) < 0.5 ? box_at(Vec2(1, 2), Vec2(0.5, 0.5)) : jitter(r, box, 0.5);
  };
  expect_pairs_over(layout, 31, 33, 1000);
}

TEST(SweepAndPruneOracle, TouchingGridWithoutMargin) {
  // Integer boxes on a grid with no margin: pairs begin and end on exact contact.
  Layout layout;
  layout.name = "touching grid";
  layout.fattening.margin = 0;
  layout.spawn = [](std::mt19937_64& r) {
    const Vec2 corner(std::floor(uniform(r, 0, 20)), std::floor(uniform(r, 0, 20)));
    return Aabb{corner, corner + Vec2(1, 1)};
  };
  layout.step = [](std::mt19937_64& r, const Aabb& box) {
    const Vec2 shift(std::floor(uniform(r, -1, 2)), std::floor(uniform(r, -1, 2)));
    return Aabb{box.lower + shift, box.upper + shift};
  };
  expect_pairs_over(layout, 41, 44, 100);
}

TEST(SweepAndPruneOracle, MostlyStaticScene) {
  Layout layout = uniform_layout();
  layout.name = "mostly static";
  layout.static_fraction = 0.8;
  expect_pairs_over(layout, 51, 53, 20);
}

TEST(SweepAndPruneOracle, WallsOfSmallBoxes) {
  // Two walls and a floor of unit boxes (the compounds scene's container), most proxies of
  // them static: fixed queries near a wall meet a column of boxes on either axis.
  Layout layout = uniform_layout();
  layout.name = "walls";
  layout.static_fraction = 0.6;
  layout.spawn = [](std::mt19937_64& r) {
    const Real roll = uniform(r, 0, 1);
    const Real along = std::floor(uniform(r, 0, 40));
    if (roll < 0.3) return box_at(Vec2(0, along), Vec2(0.5, 0.55));
    if (roll < 0.6) return box_at(Vec2(along, 0), Vec2(0.55, 0.5));
    return box_at(Vec2(uniform(r, 0, 40), uniform(r, 0, 40)), Vec2(0.3, 0.3));
  };
  expect_pairs_over(layout, 81, 84, 50);
}

TEST(SweepAndPruneOracle, FewMoversAmongManyResting) {
  // Few touched proxies per update: their entries are found by slot rather than by a pass
  // over the array.
  Layout layout = uniform_layout();
  layout.name = "few movers";
  layout.initial = 1200;
  layout.steps = 60;
  layout.move_fraction = 0.03;
  layout.create_rate = 0.002;
  layout.destroy_rate = 0.002;
  expect_pairs_over(layout, 71, 72, 100);
}

TEST(SweepAndPruneOracle, ClustersThatDriftApart) {
  // Dense gaussian clusters whose boxes fly off far: the layout drifts outside the bands it
  // was built for, and teleports are frequent.
  Layout layout;
  layout.name = "clusters";
  layout.teleport_rate = 0.05;
  layout.spawn = [](std::mt19937_64& r) {
    const int cluster = std::uniform_int_distribution<int>(0, 3)(r);
    std::normal_distribution<Real> spread(0, 2);
    const Vec2 center(cluster * 25 + spread(r), (cluster % 2) * 10 + spread(r));
    return box_at(center, Vec2(uniform(r, 0.2, 0.8), uniform(r, 0.2, 0.8)));
  };
  layout.step = [](std::mt19937_64& r, const Aabb& box) {
    const Vec2 c = (box.lower + box.upper) / 2;
    const Vec2 shift = c.normalized() * uniform(r, 0, 1.5);
    return Aabb{box.lower + shift, box.upper + shift};
  };
  expect_pairs_over(layout, 61, 64, 50);
}

// query_fixed looks in a grid of the fixed entries: fixed sets of one entry, of equal lower
// bounds, of clustered ones with a far outlier, of a ring, of a drum of boxes too large for
// the bands, of one floor over many cells among small boxes, of three shelves far apart, and
// of points all at one place, queried below, above, between and across them, against the
// brute force. Where may_meet_fixed says a query finds nothing, the brute force finds nothing.
TEST(SweepAndPruneOracle, FixedQueriesOverEqualClusteredAndRingBounds) {
  std::mt19937_64 random(19);
  const std::vector<std::function<Aabb(int)>> layouts = {
      [](int) { return box_at(Vec2(3, 1), Vec2(0.5, 0.5)); },
      [](int i) { return box_at(Vec2(2, i * 0.7), Vec2(0.25, 0.25)); },
      [](int i) {
        return i == 0 ? box_at(Vec2(1e4, 0), Vec2(1, 1))
                      : box_at(Vec2(0.001 * i, 0.3 * i), Vec2(0.1, 0.1));
      },
      [](int i) {
        const double angle = i * 2 * 3.14159265358979 / 60;
        return box_at(Vec2(40 * std::cos(angle), 40 * std::sin(angle)), Vec2(1.2, 1.2));
      },
      [](int i) {
        const double angle = i * 2 * 3.14159265358979 / 60;
        return box_at(Vec2(12 * std::cos(angle), 12 * std::sin(angle)), Vec2(6, 6));
      },
      [](int i) {
        return i == 0 ? box_at(Vec2(0, -2), Vec2(50, 0.5))
                      : box_at(Vec2(i % 8 * 0.7, i / 8 * 0.6), Vec2(0.05, 0.05));
      },
      [](int i) { return box_at(Vec2(i % 20 * 1.0 - 10, i / 20 * 30.0 - 30), Vec2(0.5, 0.25)); },
      [](int) { return box_at(Vec2(-1, 2), Vec2(0, 0)); },
  };
  const std::size_t shelves = layouts.size() - 2;
  for (std::size_t l = 0; l < layouts.size(); ++l) {
    mink::SweepAndPrune fast(0.1);
    mink::BruteForceBroadphase slow(0.1);
    mink::PairEvents events;
    const int count = l == 0 ? 1 : 60;
    for (int i = 0; i < count; ++i) {
      const ProxyKind kind = i % 3 == 1 ? ProxyKind::kinematic : ProxyKind::static_body;
      fast.create_proxy(layouts[l](i), kind, static_cast<std::uint64_t>(i));
      slow.create_proxy(layouts[l](i), kind, static_cast<std::uint64_t>(i));
    }
    fast.create_proxy(box_at(Vec2(0, 0), Vec2(0.5, 0.5)), ProxyKind::moving, 1000);
    slow.create_proxy(box_at(Vec2(0, 0), Vec2(0.5, 0.5)), ProxyKind::moving, 1000);
    fast.update_pairs(events);
    slow.update_pairs(events);
    int said_none = 0;
    for (int q = 0; q < 2000; ++q) {
      const Vec2 center(uniform(random, -60, 60), uniform(random, -60, 60));
      const Vec2 half(uniform(random, 0, 3), uniform(random, 0, 3));
      const Aabb box = q % 100 == 0 ? box_at(Vec2(0, 0), Vec2(2e4, 2e4)) : box_at(center, half);
      std::vector<mink::ProxyId> fast_out, slow_out;
      fast.query_fixed(box, fast_out);
      slow.query_fixed(box, slow_out);
      std::vector<std::uint64_t> fast_named, slow_named;
      for (const auto id : fast_out) fast_named.push_back(fast.user_data(id));
      for (const auto id : slow_out) slow_named.push_back(slow.user_data(id));
      std::sort(fast_named.begin(), fast_named.end());
      std::sort(slow_named.begin(), slow_named.end());
      ASSERT_EQ(fast_named, slow_named) << "layout " << l << ", query " << q;
      if (!fast.may_meet_fixed(box)) {
        ++said_none;
        ASSERT_TRUE(slow_named.empty()) << "layout " << l << ", query " << q;
      }
    }
    // Between the shelves most queries lie in rows that hold nothing.
    if (l == shelves) {
      EXPECT_GT(said_none, 500);
    }
  }
}

TEST(SweepAndPruneOracle, RebuildsAndChoosesTheWideAxis) {
  mink::SweepAndPrune broadphase(0.1);
  mink::PairEvents events;
  for (int i = 0; i < 200; ++i) {
    broadphase.create_proxy(box_at(Vec2(0, i * 2.0), Vec2(0.5, 0.5)), ProxyKind::moving, i);
  }
  broadphase.update_pairs(events);
  EXPECT_EQ(broadphase.sweep_axis(), 1);  // spread along y
  EXPECT_GE(broadphase.rebuild_count(), 1u);
  EXPECT_TRUE(broadphase.pairs().empty());
}

}  // namespace
