#pragma once

#include <cstdint>
#include <vector>

#include "mink/broadphase/broadphase.hpp"

namespace mink {

// The persistent pair set: a dense vector (what pairs() hands out) indexed by an
// open-addressing hash table keyed by (a, b), so insert and erase cost O(1) and a step that
// changes few pairs touches little memory. Pairs are stored with a < b.
class PairSet {
 public:
  PairSet();

  // Returns false when the pair was already present / absent.
  bool insert(ProxyPair pair);
  bool erase(ProxyPair pair);
  bool contains(ProxyPair pair) const;

  const std::vector<ProxyPair>& pairs() const { return pairs_; }
  std::size_t size() const { return pairs_.size(); }

 private:
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};

  static std::uint64_t key_of(ProxyPair pair) {
    return (std::uint64_t{pair.a} << 32) | std::uint64_t{pair.b};
  }
  std::size_t home(std::uint64_t key) const {
    return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ULL) >> shift_);
  }
  // The slot holding `key`, or the empty slot where it would go.
  std::size_t find(std::uint64_t key) const;
  void grow();

  std::vector<std::uint64_t> keys_;
  std::vector<std::uint32_t> index_;  // position of the slot's pair in pairs_
  std::vector<ProxyPair> pairs_;
  std::size_t mask_ = 0;
  int shift_ = 0;
};

}  // namespace mink
