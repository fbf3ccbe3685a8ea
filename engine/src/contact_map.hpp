#pragma once

#include <bit>
#include <cstdint>
#include <vector>

namespace mink::detail {

// The contact of each proxy pair (pair_key in contact.hpp to its index in WorldState::contacts).
// Busy scenes make and destroy thousands of contacts a step: a node-based map allocated and
// freed one node for each and missed the cache on every look-up. This one keeps keys and values
// in two flat arrays, open addressing with linear probing, at most half full; an erased key's
// run is shifted back over it, so there are no tombstones and a look-up stops at the first
// empty slot. Only looked up, never walked, so its layout decides nothing about a step.
class ContactMap {
 public:
  static constexpr std::uint32_t kNone = ~std::uint32_t{0};

  // The value under `key`, or kNone.
  std::uint32_t find(std::uint64_t key) const {
    if (keys_.empty()) return kNone;
    for (std::size_t i = home(key);; i = (i + 1) & mask_) {
      if (keys_[i] == key) return values_[i];
      if (keys_[i] == kEmpty) return kNone;
    }
  }
  bool contains(std::uint64_t key) const { return find(key) != kNone; }

  // Sets the value under `key`, adding the key if it is not there.
  void set(std::uint64_t key, std::uint32_t value) {
    if (2 * (size_ + 1) > keys_.size()) grow();
    std::size_t i = home(key);
    while (keys_[i] != kEmpty && keys_[i] != key) i = (i + 1) & mask_;
    if (keys_[i] == kEmpty) ++size_;
    keys_[i] = key;
    values_[i] = value;
  }

  // Removes `key` if it is there.
  void erase(std::uint64_t key) {
    if (keys_.empty()) return;
    std::size_t hole = home(key);
    while (keys_[hole] != key) {
      if (keys_[hole] == kEmpty) return;
      hole = (hole + 1) & mask_;
    }
    // Each later key of the run whose home is not between the hole and itself moves into the
    // hole, which moves to where it was.
    for (std::size_t i = (hole + 1) & mask_; keys_[i] != kEmpty; i = (i + 1) & mask_) {
      const std::size_t from_home = (i - home(keys_[i])) & mask_;
      if (from_home >= ((i - hole) & mask_)) {
        keys_[hole] = keys_[i];
        values_[hole] = values_[i];
        hole = i;
      }
    }
    keys_[hole] = kEmpty;
    --size_;
  }

  void clear() {
    keys_.assign(keys_.size(), kEmpty);
    size_ = 0;
  }
  // Room for `count` keys without growing.
  void reserve(std::size_t count) {
    while (2 * count > keys_.size()) grow();
  }
  std::size_t size() const { return size_; }

 private:
  // Proxy ids never reach 2^32 - 1, so no pair of them has this key.
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};

  std::size_t home(std::uint64_t key) const {
    return static_cast<std::size_t>((key * 0x9e3779b97f4a7c15ull) >> shift_);
  }

  void grow() {
    const std::size_t capacity = keys_.empty() ? 64 : 2 * keys_.size();
    std::vector<std::uint64_t> keys(capacity, kEmpty);
    std::vector<std::uint32_t> values(capacity);
    keys.swap(keys_);
    values.swap(values_);
    mask_ = capacity - 1;
    shift_ = 64 - std::countr_zero(capacity);
    size_ = 0;
    for (std::size_t i = 0; i < keys.size(); ++i) {
      if (keys[i] != kEmpty) set(keys[i], values[i]);
    }
  }

  std::vector<std::uint64_t> keys_;
  std::vector<std::uint32_t> values_;
  std::size_t mask_ = 0;
  int shift_ = 64;
  std::size_t size_ = 0;
};

}  // namespace mink::detail
