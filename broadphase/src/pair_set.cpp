#include "mink/broadphase/pair_set.hpp"

namespace mink {

namespace {
constexpr int kInitialBits = 6;
}

PairSet::PairSet()
    : keys_(std::size_t{1} << kInitialBits, kEmpty),
      index_(std::size_t{1} << kInitialBits, 0),
      mask_((std::size_t{1} << kInitialBits) - 1),
      shift_(64 - kInitialBits) {}

std::size_t PairSet::find(std::uint64_t key) const {
  std::size_t slot = home(key);
  while (keys_[slot] != kEmpty && keys_[slot] != key) slot = (slot + 1) & mask_;
  return slot;
}

bool PairSet::contains(ProxyPair pair) const {
  return keys_[find(key_of(pair))] != kEmpty;
}

bool PairSet::insert(ProxyPair pair) {
  const std::uint64_t key = key_of(pair);
  std::size_t slot = find(key);
  if (keys_[slot] == key) return false;
  // Kept at most half full so probe runs stay short.
  if (2 * (pairs_.size() + 1) > keys_.size()) {
    grow();
    slot = find(key);
  }
  keys_[slot] = key;
  index_[slot] = static_cast<std::uint32_t>(pairs_.size());
  pairs_.push_back(pair);
  return true;
}

bool PairSet::erase(ProxyPair pair) {
  std::size_t slot = find(key_of(pair));
  if (keys_[slot] == kEmpty) return false;
  // The last pair fills the hole in the dense vector.
  const std::uint32_t position = index_[slot];
  const ProxyPair last = pairs_.back();
  pairs_[position] = last;
  pairs_.pop_back();
  if (position < pairs_.size()) index_[find(key_of(last))] = position;
  // Backward-shift deletion: later members of the probe run move up so lookups never need
  // tombstones.
  std::size_t hole = slot;
  std::size_t next = (hole + 1) & mask_;
  while (keys_[next] != kEmpty) {
    const std::size_t wanted = home(keys_[next]);
    // Moves into the hole only if its home is not strictly between the hole and its slot.
    if (((next - wanted) & mask_) >= ((next - hole) & mask_)) {
      keys_[hole] = keys_[next];
      index_[hole] = index_[next];
      hole = next;
    }
    next = (next + 1) & mask_;
  }
  keys_[hole] = kEmpty;
  return true;
}

void PairSet::grow() {
  std::vector<std::uint64_t> old_keys = std::move(keys_);
  std::vector<std::uint32_t> old_index = std::move(index_);
  const std::size_t capacity = old_keys.size() * 2;
  keys_.assign(capacity, kEmpty);
  index_.assign(capacity, 0);
  mask_ = capacity - 1;
  --shift_;
  for (std::size_t i = 0; i < old_keys.size(); ++i) {
    if (old_keys[i] == kEmpty) continue;
    const std::size_t slot = find(old_keys[i]);
    keys_[slot] = old_keys[i];
    index_[slot] = old_index[i];
  }
}

}  // namespace mink
