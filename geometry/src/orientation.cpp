#include "mink/geometry/orientation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace mink::detail {
namespace {

// A finite double is m * 2^e with |m| < 2^53; relative to the smallest exponent among the six
// inputs every coordinate is an integer of at most 53 + 2098 bits, so differences fit in 2152
// bits and products in 4304: 135 limbs of 32 bits (32-bit limbs keep carries in uint64_t).
constexpr int kMaxLimbs = 140;
constexpr int kLimbBits = 32;

struct BigInt {
  std::array<std::uint32_t, kMaxLimbs> limb{};
  int size = 0;  // limbs in use; zero has size 0
  bool negative = false;
};

struct ScaledDouble {
  std::int64_t mantissa = 0;  // signed, |mantissa| < 2^53
  int exponent = 0;
};

ScaledDouble decompose(Real value) {
  if (value == 0) return {};
  int exponent = 0;
  const Real fraction = std::frexp(value, &exponent);  // value = fraction * 2^exponent
  return {static_cast<std::int64_t>(std::ldexp(fraction, 53)), exponent - 53};
}

void trim(BigInt& x) {
  while (x.size > 0 && x.limb[x.size - 1] == 0) --x.size;
  if (x.size == 0) x.negative = false;
}

BigInt shifted(const ScaledDouble& value, int shift) {
  BigInt result;
  if (value.mantissa == 0) return result;
  const std::uint64_t magnitude = value.mantissa < 0 ? static_cast<std::uint64_t>(-value.mantissa)
                                                     : static_cast<std::uint64_t>(value.mantissa);
  const int word = shift / kLimbBits;
  const int bit = shift % kLimbBits;
  // The 53-bit magnitude shifted by up to 31 bits spans at most three limbs.
  const std::uint64_t low = magnitude << bit;
  const std::uint64_t high = bit == 0 ? 0 : magnitude >> (64 - bit);
  result.limb[word] = static_cast<std::uint32_t>(low);
  result.limb[word + 1] = static_cast<std::uint32_t>(low >> 32);
  result.limb[word + 2] = static_cast<std::uint32_t>(high);
  result.size = word + 3;
  result.negative = value.mantissa < 0;
  trim(result);
  return result;
}

int compare_magnitude(const BigInt& x, const BigInt& y) {
  if (x.size != y.size) return x.size < y.size ? -1 : 1;
  for (int i = x.size - 1; i >= 0; --i) {
    if (x.limb[i] != y.limb[i]) return x.limb[i] < y.limb[i] ? -1 : 1;
  }
  return 0;
}

// |x| + |y|
BigInt add_magnitude(const BigInt& x, const BigInt& y) {
  BigInt result;
  const int n = std::max(x.size, y.size);
  std::uint64_t carry = 0;
  for (int i = 0; i < n; ++i) {
    carry += static_cast<std::uint64_t>(x.limb[i]) + y.limb[i];
    result.limb[i] = static_cast<std::uint32_t>(carry);
    carry >>= kLimbBits;
  }
  result.limb[n] = static_cast<std::uint32_t>(carry);
  result.size = n + 1;
  trim(result);
  return result;
}

// |x| - |y|, requires |x| >= |y|
BigInt subtract_magnitude(const BigInt& x, const BigInt& y) {
  BigInt result;
  std::int64_t borrow = 0;
  for (int i = 0; i < x.size; ++i) {
    std::int64_t difference = static_cast<std::int64_t>(x.limb[i]) - y.limb[i] - borrow;
    borrow = difference < 0 ? 1 : 0;
    if (difference < 0) difference += std::int64_t{1} << kLimbBits;
    result.limb[i] = static_cast<std::uint32_t>(difference);
  }
  result.size = x.size;
  trim(result);
  return result;
}

BigInt subtract(const BigInt& x, const BigInt& y) {
  if (x.negative != y.negative) {  // x - y = x + (-y), same signs after negation
    BigInt result = add_magnitude(x, y);
    result.negative = x.negative && result.size > 0;
    return result;
  }
  const int order = compare_magnitude(x, y);
  if (order == 0) return {};
  BigInt result = order > 0 ? subtract_magnitude(x, y) : subtract_magnitude(y, x);
  result.negative = (order > 0) ? x.negative : !x.negative;
  trim(result);
  return result;
}

BigInt multiply(const BigInt& x, const BigInt& y) {
  BigInt result;
  if (x.size == 0 || y.size == 0) return result;
  for (int i = 0; i < x.size; ++i) {
    std::uint64_t carry = 0;
    for (int j = 0; j < y.size; ++j) {
      // (2^32 - 1)^2 + 2 (2^32 - 1) < 2^64: no overflow.
      carry += static_cast<std::uint64_t>(x.limb[i]) * y.limb[j] + result.limb[i + j];
      result.limb[i + j] = static_cast<std::uint32_t>(carry);
      carry >>= kLimbBits;
    }
    result.limb[i + y.size] = static_cast<std::uint32_t>(carry);
  }
  result.size = x.size + y.size;
  result.negative = x.negative != y.negative;
  trim(result);
  return result;
}

int compare(const BigInt& x, const BigInt& y) {
  if (x.negative != y.negative) {
    if (x.size == 0 && y.size == 0) return 0;
    return x.negative ? -1 : 1;
  }
  const int order = compare_magnitude(x, y);
  return x.negative ? -order : order;
}

// Exact floating-point expansions (Shewchuk): a value held as a sum of doubles whose
// magnitudes do not overlap. Two-sum and two-product (through fma) make every step exact as long
// as no product underflows or overflows, which expansion_sign's range check ensures.
struct TwoTerm {
  Real high;
  Real low;  // exact error: high + low is the exact result
};

TwoTerm two_sum(Real x, Real y) {
  const Real sum = x + y;
  const Real y_part = sum - x;
  return {sum, (x - (sum - y_part)) + (y - y_part)};
}

TwoTerm two_product(Real x, Real y) {
  const Real product = x * y;
  return {product, std::fma(x, y, -product)};
}

// Up to 16 components: each of the two products of two-term differences has 8 terms.
struct Expansion {
  std::array<Real, 16> terms{};
  int size = 0;

  // Adds `value` exactly, keeping the components non-overlapping in increasing magnitude.
  void add(Real value) {
    int kept = 0;
    for (int i = 0; i < size; ++i) {
      const TwoTerm step = two_sum(value, terms[i]);
      value = step.high;
      if (step.low != 0) terms[kept++] = step.low;
    }
    terms[kept++] = value;
    size = kept;
  }
  // The largest component decides the sign of a non-overlapping expansion.
  int sign() const {
    for (int i = size - 1; i >= 0; --i) {
      if (terms[i] != 0) return terms[i] > 0 ? 1 : -1;
    }
    return 0;
  }
};

// A product of non-zero factors must stay where fma's error term is exact (no underflow) and
// nothing overflows.
bool in_expansion_range(Real product) {
  constexpr Real kSmallest = 0x1p-900;
  constexpr Real kLargest = 0x1p+1000;
  const Real magnitude = std::abs(product);
  return magnitude >= kSmallest && magnitude <= kLargest;
}

// det = (ax - cx)(by - cy) - (ay - cy)(bx - cx) with each difference split exactly into two
// terms and each product of two-term factors expanded into four exact two-products.
// Returns false when a magnitude leaves the range where that is exact.
bool orient2d_expansion(const Vec2& a, const Vec2& b, const Vec2& c, int& sign) {
  const TwoTerm acx = two_sum(a.x(), -c.x());
  const TwoTerm bcy = two_sum(b.y(), -c.y());
  const TwoTerm acy = two_sum(a.y(), -c.y());
  const TwoTerm bcx = two_sum(b.x(), -c.x());
  Expansion det;
  bool in_range = true;
  const auto add_product = [&](Real x, Real y, Real sign_of_term) {
    if (x == 0 || y == 0) return;  // most differences are exact: their low terms are zero
    const TwoTerm product = two_product(x, y);
    in_range &= in_expansion_range(product.high);
    det.add(sign_of_term * product.low);
    det.add(sign_of_term * product.high);
  };
  for (Real x : {acx.low, acx.high}) {
    for (Real y : {bcy.low, bcy.high}) add_product(x, y, 1);
  }
  for (Real x : {acy.low, acy.high}) {
    for (Real y : {bcx.low, bcx.high}) add_product(x, y, -1);
  }
  if (!in_range || !std::isfinite(acx.high) || !std::isfinite(bcy.high) ||
      !std::isfinite(acy.high) || !std::isfinite(bcx.high)) {
    return false;
  }
  sign = det.sign();
  return true;
}

}  // namespace

int orient2d_exact(const Vec2& a, const Vec2& b, const Vec2& c) noexcept {
  int sign = 0;
  if (orient2d_expansion(a, b, c, sign)) return sign;
  return orient2d_big_integer(a, b, c);
}

int orient2d_big_integer(const Vec2& a, const Vec2& b, const Vec2& c) noexcept {
  const std::array<ScaledDouble, 6> parts = {decompose(a.x()), decompose(a.y()), decompose(b.x()),
                                             decompose(b.y()), decompose(c.x()), decompose(c.y())};
  int lowest_exponent = 0;
  bool any_nonzero = false;
  for (const ScaledDouble& part : parts) {
    if (part.mantissa == 0) continue;
    lowest_exponent = any_nonzero ? std::min(lowest_exponent, part.exponent) : part.exponent;
    any_nonzero = true;
  }
  if (!any_nonzero) return 0;
  std::array<BigInt, 6> v;
  for (int i = 0; i < 6; ++i) v[i] = shifted(parts[i], parts[i].exponent - lowest_exponent);
  const BigInt& ax = v[0];
  const BigInt& ay = v[1];
  const BigInt& bx = v[2];
  const BigInt& by = v[3];
  const BigInt& cx = v[4];
  const BigInt& cy = v[5];
  // det = (ax - cx)(by - cy) - (ay - cy)(bx - cx), the same expansion the filter rounds.
  const BigInt left = multiply(subtract(ax, cx), subtract(by, cy));
  const BigInt right = multiply(subtract(ay, cy), subtract(bx, cx));
  return compare(left, right);
}

}  // namespace mink::detail

namespace mink {

bool all_on_one_line(std::span<const Vec2> points) noexcept {
  if (points.empty()) return true;
  std::size_t second = 1;
  while (second < points.size() && points[second] == points[0]) ++second;
  for (std::size_t i = second + 1; i < points.size(); ++i) {
    if (orient2d(points[0], points[second], points[i]) != 0) return false;
  }
  return true;
}

}  // namespace mink
