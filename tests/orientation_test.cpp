#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "mink/geometry/orientation.hpp"
#include "test_support.hpp"

namespace {

using mink::Vec2;
using mink_test::cgal_orientation;
using mink_test::format_point;
using mink_test::unit_double;

struct Triple {
  Vec2 a;
  Vec2 b;
  Vec2 c;
};

std::string describe(const Triple& t) {
  return format_point(t.a) + ", " + format_point(t.b) + ", " + format_point(t.c);
}

int sign_of(double value) {
  return (value > 0) - (value < 0);
}

// Compares a sign function with CGAL on every triple; reports the count and the first few
// disagreements instead of one failure per triple.
template <typename Orientation>
::testing::AssertionResult agrees_with_cgal(const std::vector<Triple>& triples,
                                            Orientation orientation) {
  std::size_t disagreements = 0;
  std::string examples;
  for (const Triple& t : triples) {
    const int expected = cgal_orientation(t.a, t.b, t.c);
    const int got = orientation(t.a, t.b, t.c);
    if (got == expected) continue;
    if (++disagreements <= 3) {
      examples += "\n  " + describe(t) + ": CGAL " + std::to_string(expected) + ", got " +
                  std::to_string(got);
    }
  }
  if (disagreements == 0) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << disagreements << " of " << triples.size() << " triples disagree with CGAL:" << examples;
}

::testing::AssertionResult orient2d_agrees_with_cgal(const std::vector<Triple>& triples) {
  return agrees_with_cgal(
      triples, [](const Vec2& a, const Vec2& b, const Vec2& c) { return mink::orient2d(a, b, c); });
}

// The exact fallback on its own: the filter in orient2d answers most ordinary triples before
// the fallback runs, which would hide a fallback bug there.
::testing::AssertionResult exact_path_agrees_with_cgal(const std::vector<Triple>& triples) {
  return agrees_with_cgal(triples, [](const Vec2& a, const Vec2& b, const Vec2& c) {
    return mink::detail::orient2d_exact(a, b, c);
  });
}

// The big-integer path alone: the slow twin that orient2d_exact falls back to when a product
// would underflow or overflow its floating-point expansions.
::testing::AssertionResult big_integer_path_agrees_with_cgal(const std::vector<Triple>& triples) {
  return agrees_with_cgal(triples, [](const Vec2& a, const Vec2& b, const Vec2& c) {
    return mink::detail::orient2d_big_integer(a, b, c);
  });
}

std::size_t naive_sign_disagreements(const std::vector<Triple>& triples) {
  std::size_t count = 0;
  for (const Triple& t : triples) {
    if (sign_of(mink::orient2d_naive(t.a, t.b, t.c)) != cgal_orientation(t.a, t.b, t.c)) {
      ++count;
    }
  }
  return count;
}

std::vector<Triple> random_triples(std::size_t count, double scale, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  const auto coordinate = [&] { return scale * (2 * unit_double(random()) - 1); };
  std::vector<Triple> triples;
  for (std::size_t i = 0; i < count; ++i) {
    triples.push_back({Vec2(coordinate(), coordinate()), Vec2(coordinate(), coordinate()),
                       Vec2(coordinate(), coordinate())});
  }
  return triples;
}

// Random triples on a small integer grid: many are exactly collinear or repeat a point.
std::vector<Triple> small_grid_triples(std::size_t count, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  const auto coordinate = [&] { return static_cast<double>(random() % 5) - 2; };
  std::vector<Triple> triples;
  for (std::size_t i = 0; i < count; ++i) {
    triples.push_back({Vec2(coordinate(), coordinate()), Vec2(coordinate(), coordinate()),
                       Vec2(coordinate(), coordinate())});
  }
  return triples;
}

// The classic failure of the naive determinant: a 256 x 256 grid of points one ulp apart
// near (0.5, 0.5), each against the line through (12, 12) and (24, 24).
std::vector<Triple> ulp_grid_triples() {
  std::vector<Triple> triples;
  for (int i = 0; i < 256; ++i) {
    for (int j = 0; j < 256; ++j) {
      triples.push_back({Vec2(0.5 + i * 0x1p-53, 0.5 + j * 0x1p-53), Vec2(12, 12), Vec2(24, 24)});
    }
  }
  return triples;
}

// Points on y = 0.3 x + 0.1 rounded to doubles, then nudged by -3..3 ulps in y; triples of
// them are within a few ulps of collinear.
std::vector<Triple> near_line_triples(std::size_t count, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  const auto point = [&] {
    const double x = 4 * unit_double(random()) - 2;
    double y = 0.3 * x + 0.1;
    const int nudges = static_cast<int>(random() % 7) - 3;
    for (int k = 0; k < std::abs(nudges); ++k) {
      y = std::nextafter(y, nudges > 0 ? INFINITY : -INFINITY);
    }
    return Vec2(x, y);
  };
  std::vector<Triple> triples;
  for (std::size_t i = 0; i < count; ++i) triples.push_back({point(), point(), point()});
  return triples;
}

// Any finite double, every exponent equally likely: exercises overflow and underflow.
std::vector<Triple> random_bit_pattern_triples(std::size_t count, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  const auto coordinate = [&] {
    for (;;) {
      const double value = std::bit_cast<double>(random());
      if (std::isfinite(value)) return value;
    }
  };
  std::vector<Triple> triples;
  for (std::size_t i = 0; i < count; ++i) {
    triples.push_back({Vec2(coordinate(), coordinate()), Vec2(coordinate(), coordinate()),
                       Vec2(coordinate(), coordinate())});
  }
  return triples;
}

// Every coordinate drawn from a handful of magnitudes from subnormal to near the largest
// double, so one triple mixes huge and tiny values and many triples are degenerate.
std::vector<Triple> mixed_magnitude_triples(std::size_t count, std::uint64_t seed) {
  constexpr double kMax = std::numeric_limits<double>::max();
  constexpr double kSubnormal = std::numeric_limits<double>::denorm_min();
  const std::array<double, 17> values = {
      0,   kSubnormal, -kSubnormal, 3 * kSubnormal, 1e-300, -1e-300, 2.5e-308, 1,     -1,
      0.1, 1e300,      -1e300,      3e299,          kMax,   -kMax,   1e154,    -1e154};
  std::mt19937_64 random(seed);
  const auto coordinate = [&] { return values[random() % values.size()]; };
  std::vector<Triple> triples;
  for (std::size_t i = 0; i < count; ++i) {
    triples.push_back({Vec2(coordinate(), coordinate()), Vec2(coordinate(), coordinate()),
                       Vec2(coordinate(), coordinate())});
  }
  return triples;
}

Vec2 scaled(const Vec2& p, int power_of_two) {
  return Vec2(std::ldexp(p.x(), power_of_two), std::ldexp(p.y(), power_of_two));
}

std::vector<Triple> scaled(const std::vector<Triple>& triples, int power_of_two) {
  std::vector<Triple> result;
  for (const Triple& t : triples) {
    result.push_back(
        {scaled(t.a, power_of_two), scaled(t.b, power_of_two), scaled(t.c, power_of_two)});
  }
  return result;
}

TEST(Orientation, BasicTurns) {
  EXPECT_EQ(mink::orient2d({0, 0}, {1, 0}, {0, 1}), 1);
  EXPECT_EQ(mink::orient2d({0, 0}, {0, 1}, {1, 0}), -1);
  EXPECT_EQ(mink::orient2d({0, 0}, {1, 1}, {2, 2}), 0);
  EXPECT_EQ(mink::orient2d({0, 0}, {1, 1}, {-3, -3}), 0);
}

TEST(Orientation, RandomTriplesAgreeWithCgal) {
  const auto triples = random_triples(100'000, 1.0, 1);
  EXPECT_TRUE(orient2d_agrees_with_cgal(triples));
  EXPECT_TRUE(exact_path_agrees_with_cgal(triples));
  EXPECT_TRUE(big_integer_path_agrees_with_cgal(triples));
}

TEST(Orientation, SmallIntegerGridAgreesWithCgalIncludingCollinear) {
  const auto triples = small_grid_triples(50'000, 2);
  std::size_t collinear = 0;
  for (const Triple& t : triples) collinear += cgal_orientation(t.a, t.b, t.c) == 0;
  ASSERT_GT(collinear, 1000u) << "the grid should produce many collinear triples";
  EXPECT_TRUE(orient2d_agrees_with_cgal(triples));
  EXPECT_TRUE(exact_path_agrees_with_cgal(triples));
}

TEST(Orientation, UlpGridNearDiagonalIsExactWhereNaiveFails) {
  const auto triples = ulp_grid_triples();
  EXPECT_GT(naive_sign_disagreements(triples), 0u)
      << "the grid no longer defeats the naive determinant, so it shows nothing";
  EXPECT_TRUE(orient2d_agrees_with_cgal(triples));
  EXPECT_TRUE(exact_path_agrees_with_cgal(triples));
}

TEST(Orientation, NudgedPointsOnALineAreExactWhereNaiveFails) {
  const auto triples = near_line_triples(100'000, 3);
  EXPECT_GT(naive_sign_disagreements(triples), 0u);
  EXPECT_TRUE(orient2d_agrees_with_cgal(triples));
  EXPECT_TRUE(exact_path_agrees_with_cgal(triples));
  EXPECT_TRUE(big_integer_path_agrees_with_cgal(triples));
}

TEST(Orientation, HugeCoordinatesAgreeWithCgal) {
  // Products of ~1e300 overflow, so only the exact path can answer.
  EXPECT_TRUE(orient2d_agrees_with_cgal(random_triples(20'000, 1e300, 4)));
  EXPECT_TRUE(orient2d_agrees_with_cgal(random_triples(20'000, 1.7e308, 5)));
  EXPECT_TRUE(orient2d_agrees_with_cgal(scaled(ulp_grid_triples(), 960)));
  // Just inside and just outside the range where the expansions are exact.
  for (int power : {440, 500, 520}) {
    EXPECT_TRUE(exact_path_agrees_with_cgal(scaled(ulp_grid_triples(), power))) << power;
    EXPECT_TRUE(big_integer_path_agrees_with_cgal(scaled(ulp_grid_triples(), power))) << power;
  }
}

TEST(Orientation, TinyAndSubnormalCoordinatesAgreeWithCgal) {
  // Products of ~1e-300 underflow to zero or subnormals.
  EXPECT_TRUE(orient2d_agrees_with_cgal(random_triples(20'000, 1e-300, 6)));
  EXPECT_TRUE(orient2d_agrees_with_cgal(random_triples(20'000, 1e-320, 7)));
  EXPECT_TRUE(orient2d_agrees_with_cgal(scaled(small_grid_triples(20'000, 8), -1074)));
  EXPECT_TRUE(orient2d_agrees_with_cgal(scaled(ulp_grid_triples(), -1000)));
  EXPECT_TRUE(orient2d_agrees_with_cgal(scaled(ulp_grid_triples(), -1060)));
  for (int power : {-430, -450, -470, -540}) {
    EXPECT_TRUE(exact_path_agrees_with_cgal(scaled(ulp_grid_triples(), power))) << power;
    EXPECT_TRUE(big_integer_path_agrees_with_cgal(scaled(ulp_grid_triples(), power))) << power;
  }
}

TEST(Orientation, MixedMagnitudesInOneTripleAgreeWithCgal) {
  const auto triples = mixed_magnitude_triples(30'000, 9);
  EXPECT_TRUE(orient2d_agrees_with_cgal(triples));
  EXPECT_TRUE(exact_path_agrees_with_cgal(triples));
}

TEST(Orientation, RandomBitPatternsAgreeWithCgal) {
  const auto triples = random_bit_pattern_triples(30'000, 10);
  EXPECT_TRUE(orient2d_agrees_with_cgal(triples));
  EXPECT_TRUE(exact_path_agrees_with_cgal(triples));
}

TEST(Orientation, ScalingByPowersOfTwoKeepsTheSign) {
  // Exact scaling (no overflow or underflow) cannot change the sign of the determinant.
  const auto base = ulp_grid_triples();
  for (int power : {-900, -300, 300, 900}) {
    const auto triples = scaled(base, power);
    for (std::size_t i = 0; i < base.size(); ++i) {
      const Triple& t = triples[i];
      ASSERT_EQ(mink::orient2d(t.a, t.b, t.c), mink::orient2d(base[i].a, base[i].b, base[i].c))
          << "scaled by 2^" << power << ": " << describe(base[i]);
    }
  }
}

TEST(Orientation, ExactlyCollinearLargeIntegersAreCollinear) {
  // All coordinates are integers below 2^53, so they and the points between are exact, but
  // the naive products (~2^104) are rounded.
  const Vec2 start(0x1p51 + 1, 0x1p50 + 7);
  const Vec2 step(0x1p50 + 3, 0x1p49 + 5);
  const Vec2 middle = start + step;
  const Vec2 end = start + 2 * step;
  const Vec2 beyond = start - step;
  for (const Triple& t : {Triple{start, middle, end}, Triple{end, start, middle},
                          Triple{middle, end, beyond}, Triple{beyond, start, end}}) {
    EXPECT_EQ(mink::orient2d(t.a, t.b, t.c), 0) << describe(t);
    EXPECT_EQ(cgal_orientation(t.a, t.b, t.c), 0) << describe(t);
  }
  // One unit off the line, the turn is visible to the exact predicate.
  EXPECT_EQ(mink::orient2d(start, end, middle + Vec2(0, 1)), 1);
  EXPECT_EQ(mink::orient2d(start, end, middle - Vec2(0, 1)), -1);
}

TEST(Orientation, CollinearPointsWhoseDifferencesOverflow) {
  constexpr double kBig = 1.5e308;  // kBig - (-kBig) overflows
  constexpr double kSubnormal = std::numeric_limits<double>::denorm_min();
  const Vec2 low(-kBig, -kBig);
  const Vec2 high(kBig, kBig);
  EXPECT_EQ(mink::orient2d(low, Vec2(0, 0), high), 0);
  EXPECT_EQ(mink::orient2d(Vec2(-kBig, kBig), Vec2(0, 0), Vec2(kBig, -kBig)), 0);
  // A subnormal step off the diagonal y = x is still a turn: left of low -> high.
  EXPECT_EQ(mink::orient2d(low, high, Vec2(0, kSubnormal)), 1);
  EXPECT_EQ(mink::orient2d(low, high, Vec2(kSubnormal, 0)), -1);
  EXPECT_EQ(cgal_orientation(low, high, Vec2(0, kSubnormal)), 1);
  // Collinear at 2^900 scale, where the products overflow.
  const Vec2 unit(std::ldexp(3.0, 900), std::ldexp(5.0, 900));
  EXPECT_EQ(mink::orient2d(unit, 2 * unit, -4 * unit), 0);
  EXPECT_EQ(mink::orient2d(Vec2(0, 0), unit, 2 * unit + Vec2(0, std::ldexp(1.0, 870))), 1);
}

TEST(Orientation, SubnormalTriangle) {
  constexpr double kSubnormal = std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(mink::orient2d({0, 0}, {kSubnormal, 0}, {0, kSubnormal}), 1);
  EXPECT_EQ(mink::orient2d({0, 0}, {0, kSubnormal}, {kSubnormal, 0}), -1);
  EXPECT_EQ(mink::orient2d({kSubnormal, kSubnormal}, {2 * kSubnormal, 2 * kSubnormal},
                           {3 * kSubnormal, 3 * kSubnormal}),
            0);
  // Mixed: a subnormal height over a huge base.
  EXPECT_EQ(mink::orient2d({-1e300, 0}, {1e300, 0}, {0, kSubnormal}), 1);
  EXPECT_EQ(mink::orient2d({-1e300, 0}, {1e300, 0}, {0, -kSubnormal}), -1);
}

TEST(Orientation, CyclicSymmetryAndAntisymmetry) {
  std::vector<Triple> triples = random_triples(5'000, 1.0, 11);
  for (const auto& more :
       {ulp_grid_triples(), near_line_triples(5'000, 12), small_grid_triples(5'000, 13),
        mixed_magnitude_triples(5'000, 14), random_bit_pattern_triples(5'000, 15)}) {
    triples.insert(triples.end(), more.begin(), more.end());
  }
  for (const Triple& t : triples) {
    const int turn = mink::orient2d(t.a, t.b, t.c);
    ASSERT_EQ(mink::orient2d(t.b, t.c, t.a), turn) << describe(t);
    ASSERT_EQ(mink::orient2d(t.c, t.a, t.b), turn) << describe(t);
    ASSERT_EQ(mink::orient2d(t.b, t.a, t.c), -turn) << describe(t);
    ASSERT_EQ(mink::orient2d(t.a, t.c, t.b), -turn) << describe(t);
    ASSERT_EQ(mink::orient2d(t.c, t.b, t.a), -turn) << describe(t);
  }
}

TEST(Orientation, RepeatedPointIsCollinear) {
  for (const Triple& t : mixed_magnitude_triples(5'000, 16)) {
    ASSERT_EQ(mink::orient2d(t.a, t.a, t.b), 0) << describe(t);
    ASSERT_EQ(mink::orient2d(t.a, t.b, t.a), 0) << describe(t);
    ASSERT_EQ(mink::orient2d(t.b, t.a, t.a), 0) << describe(t);
  }
}

TEST(Orientation, LexicographicOrder) {
  EXPECT_TRUE(mink::lex_less({0, 5}, {1, -5}));
  EXPECT_TRUE(mink::lex_less({1, -5}, {1, 5}));
  EXPECT_FALSE(mink::lex_less({1, 5}, {1, 5}));
  EXPECT_FALSE(mink::lex_less({2, 0}, {1, 9}));
}

}  // namespace
