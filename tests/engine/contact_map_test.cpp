// The contact map (engine/src/contact_map.hpp) against std::unordered_map as its oracle.
#include "contact_map.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <unordered_map>

namespace {

using mink::detail::ContactMap;

std::uint64_t pair_key(std::uint32_t a, std::uint32_t b) {
  return (static_cast<std::uint64_t>(a) << 32) | b;
}

// Seeded runs of sets, overwrites and erases over few proxies (long probe runs, erases from
// their middles, the table growing through them), every key looked up after each call.
TEST(ContactMap, AgreesWithAnUnorderedMapOverRandomSetsAndErases) {
  for (std::uint32_t seed = 1; seed <= 20; ++seed) {
    std::mt19937 random(seed);
    const std::uint32_t proxies = 8 + seed * 4;
    std::uniform_int_distribution<std::uint32_t> proxy(0, proxies - 1);
    ContactMap map;
    std::unordered_map<std::uint64_t, std::uint32_t> oracle;
    for (int call = 0; call < 3000; ++call) {
      const std::uint64_t key = pair_key(proxy(random), proxy(random));
      if (random() % 3 == 0) {
        map.erase(key);
        oracle.erase(key);
      } else {
        const auto value = static_cast<std::uint32_t>(random() % 100000);
        map.set(key, value);
        oracle[key] = value;
      }
      ASSERT_EQ(map.size(), oracle.size()) << "seed " << seed << ", call " << call;
      for (std::uint32_t a = 0; a < proxies; a += 3) {
        for (std::uint32_t b = 0; b < proxies; ++b) {
          const auto found = oracle.find(pair_key(a, b));
          ASSERT_EQ(map.find(pair_key(a, b)),
                    found == oracle.end() ? ContactMap::kNone : found->second)
              << "seed " << seed << ", call " << call << ", pair " << a << ", " << b;
        }
      }
    }
    map.clear();
    EXPECT_EQ(map.size(), 0u);
    EXPECT_FALSE(map.contains(pair_key(0, 1)));
  }
}

TEST(ContactMap, AnEmptyMapFindsNothingAndErasesNothing) {
  ContactMap map;
  EXPECT_EQ(map.find(pair_key(3, 4)), ContactMap::kNone);
  map.erase(pair_key(3, 4));
  map.reserve(1000);
  EXPECT_EQ(map.size(), 0u);
  map.set(pair_key(3, 4), 7);
  EXPECT_EQ(map.find(pair_key(3, 4)), 7u);
  EXPECT_EQ(map.find(pair_key(4, 3)), ContactMap::kNone);
}

}  // namespace
