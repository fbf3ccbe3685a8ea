#include "mink/broadphase/pair_set.hpp"

namespace mink {

namespace {
constexpr int kInitialBits = 6;
}

PairSet::PairSet()
    : slots_(std::size_t{1} << kInitialBits, Slot{kEmpty, 0}),
      mask_((std::size_t{1} << kInitialBits) - 1),
      shift_(64 - kInitialBits) {}

std::size_t PairSet::find(std::uint64_t key) const {
  std::size_t slot = home(key);
  while (slots_[slot].key != kEmpty && slots_[slot].key != key) slot = (slot + 1) & mask_;
  return slot;
}

bool PairSet::contains(ProxyPair pair) const {
  return slots_[find(key_of(pair))].key != kEmpty;
}

bool PairSet::insert(ProxyPair pair) {
  const std::uint64_t key = key_of(pair);
  std::size_t slot = find(key);
  if (slots_[slot].key == key) return false;
  // Kept at most half full so probe runs stay short.
  if (2 * (pairs_.size() + 1) > slots_.size()) {
    grow();
    slot = find(key);
  }
  slots_[slot] = {key, static_cast<std::uint32_t>(pairs_.size())};
  pairs_.push_back(pair);
  return true;
}

bool PairSet::erase(ProxyPair pair) {
  const std::size_t slot = find(key_of(pair));
  if (slots_[slot].key == kEmpty) return false;
  // The last pair fills the hole in the dense vector.
  const std::uint32_t position = slots_[slot].index;
  const ProxyPair last = pairs_.back();
  pairs_[position] = last;
  pairs_.pop_back();
  if (position < pairs_.size()) slots_[find(key_of(last))].index = position;
  // Backward-shift deletion: later members of the probe run move up so lookups never need
  // tombstones.
  std::size_t hole = slot;
  std::size_t next = (hole + 1) & mask_;
  while (slots_[next].key != kEmpty) {
    const std::size_t wanted = home(slots_[next].key);
    // Moves into the hole only if its home is not strictly between the hole and its slot.
    if (((next - wanted) & mask_) >= ((next - hole) & mask_)) {
      slots_[hole] = slots_[next];
      hole = next;
    }
    next = (next + 1) & mask_;
  }
  slots_[hole].key = kEmpty;
  return true;
}

void PairSet::grow() {
  std::vector<Slot> old = std::move(slots_);
  slots_.assign(old.size() * 2, Slot{kEmpty, 0});
  mask_ = slots_.size() - 1;
  --shift_;
  for (const Slot& entry : old) {
    if (entry.key != kEmpty) slots_[find(entry.key)] = entry;
  }
}

}  // namespace mink
