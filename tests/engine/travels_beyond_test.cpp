// moved_fast's test of how far a body went (engine/src/continuous.hpp) against the square root
// it stands for: the bounds it tries first must never change the answer.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "continuous.hpp"

namespace {

using mink::Real;
using mink::detail::travels_beyond;

bool by_the_square_root(Real x, Real y, Real reach, Real scale, Real limit) {
  return scale * (std::sqrt(x * x + y * y) + reach) > limit;
}

// Seeded cases over twenty orders of magnitude, with the limit drawn at random and also put
// exactly on the computed value and one step of rounding either side of it, where the bounds
// come nearest to a wrong answer.
TEST(TravelsBeyond, AgreesWithTheSquareRootAtAndAroundTheLimit) {
  std::mt19937_64 random(16);
  std::uniform_real_distribution<Real> exponent(-12, 8), unit(0, 1);
  const auto magnitude = [&] { return std::pow(Real{10}, exponent(random)); };
  const auto signed_magnitude = [&] { return (unit(random) < 0.5 ? -1 : 1) * magnitude(); };
  int cases = 0, beyond = 0;
  for (int k = 0; k < 200000; ++k) {
    const Real x = k % 7 == 0 ? 0 : signed_magnitude();
    const Real y = k % 5 == 0 ? 0 : signed_magnitude();
    const Real reach = k % 3 == 0 ? 0 : magnitude();
    const Real scale = k % 2 == 0 ? 1 : Real{1} / 60;
    const Real value = scale * (std::sqrt(x * x + y * y) + reach);
    const Real inf = std::numeric_limits<Real>::infinity();
    for (const Real limit : {magnitude(), value, std::nextafter(value, inf),
                             std::nextafter(value, -inf), value * (1 + 1e-9), value * (1 - 1e-9)}) {
      const bool expected = by_the_square_root(x, y, reach, scale, limit);
      ASSERT_EQ(travels_beyond(x, y, reach, scale, limit), expected)
          << "x " << x << ", y " << y << ", reach " << reach << ", scale " << scale << ", limit "
          << limit;
      ++cases;
      beyond += expected ? 1 : 0;
    }
  }
  // Both answers are well represented.
  EXPECT_GT(beyond, cases / 5);
  EXPECT_LT(beyond, cases * 4 / 5);
}

// Where the bounds are not used or could fail: no limit, limits too small for the squares,
// lengths whose squares underflow or overflow, and no motion at all.
TEST(TravelsBeyond, AgreesWithTheSquareRootAtTheEdges) {
  const Real tiny = std::numeric_limits<Real>::denorm_min();
  const Real huge = std::numeric_limits<Real>::max();
  const std::vector<Real> values = {0,     tiny, 1e-200, 1e-160, 1e-100, 1e-81,
                                    1e-79, 1e-3, 1,      1e150,  1e160,  huge};
  for (const Real x : values) {
    for (const Real y : values) {
      for (const Real reach : {Real{0}, Real{1e-200}, Real{0.01}}) {
        for (const Real limit : values) {
          ASSERT_EQ(travels_beyond(x, -y, reach, 1, limit),
                    by_the_square_root(x, -y, reach, 1, limit))
              << "x " << x << ", y " << -y << ", reach " << reach << ", limit " << limit;
        }
      }
    }
  }
}

}  // namespace
