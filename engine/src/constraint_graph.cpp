// The constraint graph's colours: one bit per body and colour.

#include "constraint_graph.hpp"

#include <algorithm>
#include <cassert>
#include <cstddef>

namespace mink::detail {

namespace {

bool taken(const std::vector<std::uint64_t>& bits, std::uint32_t body) {
  const std::size_t word = body >> 6;
  return word < bits.size() && (bits[word] >> (body & 63) & 1) != 0;
}

void set(std::vector<std::uint64_t>& bits, std::uint32_t body, bool on) {
  const std::size_t word = body >> 6;
  if (word >= bits.size()) bits.resize(word + 1, 0);
  const std::uint64_t bit = std::uint64_t{1} << (body & 63);
  bits[word] = on ? bits[word] | bit : bits[word] & ~bit;
}

}  // namespace

bool ConstraintGraph::place(std::uint8_t color, std::uint32_t body_a, bool a_fixed,
                            std::uint32_t body_b, bool b_fixed) {
  std::vector<std::uint64_t>& bits = bits_[color];
  if ((!a_fixed && taken(bits, body_a)) || (!b_fixed && taken(bits, body_b))) return false;
  if (!a_fixed) set(bits, body_a, true);
  if (!b_fixed) set(bits, body_b, true);
  return true;
}

std::uint8_t ConstraintGraph::add(std::uint32_t body_a, bool a_fixed, std::uint32_t body_b,
                                  bool b_fixed) {
  for (std::uint8_t color = 0; color < kGraphColors; ++color) {
    if (place(color, body_a, a_fixed, body_b, b_fixed)) return color;
  }
  return kOverflowColor;
}

void ConstraintGraph::remove(std::uint8_t color, std::uint32_t body_a, bool a_fixed,
                             std::uint32_t body_b, bool b_fixed) {
  if (color >= kGraphColors) return;  // the overflow holds no bits
  std::vector<std::uint64_t>& bits = bits_[color];
  assert((a_fixed || taken(bits, body_a)) && (b_fixed || taken(bits, body_b)));
  if (!a_fixed) set(bits, body_a, false);
  if (!b_fixed) set(bits, body_b, false);
}

bool ConstraintGraph::same_colours(const ConstraintGraph& other) const {
  const auto used = [](const std::vector<std::uint64_t>& bits) {
    std::size_t n = bits.size();
    while (n > 0 && bits[n - 1] == 0) --n;
    return n;
  };
  for (std::size_t color = 0; color < kGraphColors; ++color) {
    const std::vector<std::uint64_t>& a = bits_[color];
    const std::vector<std::uint64_t>& b = other.bits_[color];
    const std::size_t n = used(a);
    if (n != used(b) ||
        !std::equal(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(n), b.begin())) {
      return false;
    }
  }
  return true;
}

}  // namespace mink::detail
