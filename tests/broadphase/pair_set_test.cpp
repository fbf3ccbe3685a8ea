#include "mink/broadphase/pair_set.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <utility>

namespace {

using mink::PairSet;
using mink::ProxyPair;

TEST(PairSet, InsertEraseContainsAgreeWithStdSet) {
  PairSet set;
  std::set<std::pair<std::uint32_t, std::uint32_t>> reference;
  std::mt19937_64 random(7);
  std::uniform_int_distribution<std::uint32_t> id(0, 300);
  for (int round = 0; round < 200000; ++round) {
    std::uint32_t a = id(random), b = id(random);
    if (a == b) continue;
    if (a > b) std::swap(a, b);
    const ProxyPair pair{a, b};
    if (random() % 3 == 0) {
      EXPECT_EQ(set.erase(pair), reference.erase({a, b}) == 1);
    } else {
      EXPECT_EQ(set.insert(pair), reference.insert({a, b}).second);
    }
    if (round % 1000 == 0) {
      ASSERT_EQ(set.size(), reference.size());
      std::vector<std::pair<std::uint32_t, std::uint32_t>> listed;
      for (const ProxyPair& p : set.pairs()) {
        EXPECT_TRUE(set.contains(p));
        listed.emplace_back(p.a, p.b);
      }
      std::sort(listed.begin(), listed.end());
      EXPECT_TRUE(std::equal(listed.begin(), listed.end(), reference.begin(), reference.end()));
    }
  }
  for (const auto& [a, b] : reference) EXPECT_TRUE(set.contains({a, b}));
  EXPECT_FALSE(set.contains({1000, 1001}));
}

TEST(PairSet, ErasingEverythingLeavesItEmpty) {
  PairSet set;
  for (std::uint32_t i = 0; i < 5000; ++i) EXPECT_TRUE(set.insert({i, i + 1}));
  for (std::uint32_t i = 0; i < 5000; ++i) EXPECT_TRUE(set.erase({i, i + 1}));
  EXPECT_EQ(set.size(), 0u);
  EXPECT_FALSE(set.erase({0, 1}));
  EXPECT_TRUE(set.insert({0, 1}));
}

}  // namespace
