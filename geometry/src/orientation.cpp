#include "mink/geometry/orientation.hpp"

#include <algorithm>
#include <array>
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

}  // namespace

int orient2d_exact(const Vec2& a, const Vec2& b, const Vec2& c) noexcept {
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
