#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "mink/engine/stale_id_error.hpp"
#include "mink/geometry/large_page_allocator.hpp"

namespace mink::detail {

// Slots with generations and a free list, shared by bodies and shapes. A slot type has
// `alive` and `generation`; an id type has `index`, `generation` and `world`. Destroying bumps
// the generation so kept ids go stale; ids name their world so one from another World is
// refused instead of reaching a slot that happens to exist here too.
// "KindId{index I, generation G, world W}": how error messages name an id.
template <typename Id>
std::string id_string(const char* kind, const Id& id) {
  return std::string(kind) + "{index " + std::to_string(id.index) + ", generation " +
         std::to_string(id.generation) + ", world " + std::to_string(id.world) + "}";
}

template <typename Slot>
class IdPool {
 public:
  std::uint32_t allocate() {
    std::uint32_t index;
    if (!free_.empty()) {
      index = free_.back();
      free_.pop_back();
    } else {
      index = static_cast<std::uint32_t>(slots_.size());
      slots_.emplace_back();
    }
    Slot& slot = slots_[index];
    const std::uint32_t generation = slot.generation;
    slot = Slot{};
    slot.generation = generation;
    slot.alive = true;
    ++live_;
    return index;
  }

  void release(std::uint32_t index) {
    Slot& slot = slots_[index];
    slot.alive = false;
    ++slot.generation;
    free_.push_back(index);
    --live_;
  }

  template <typename Id>
  bool valid(const Id& id, std::uint32_t world) const noexcept {
    return id.world == world && id.index < slots_.size() && slots_[id.index].alive &&
           slots_[id.index].generation == id.generation;
  }

  template <typename Id>
  Slot& get(const Id& id, std::uint32_t world, const char* what) {
    if (!valid(id, world)) {
      throw StaleIdError(to_string(id) + " does not name a live " + what + " of this world");
    }
    return slots_[id.index];
  }

  using Slots = LargeVector<Slot>;
  Slots& slots() noexcept { return slots_; }
  const Slots& slots() const noexcept { return slots_; }
  Slot& operator[](std::uint32_t index) { return slots_[index]; }
  const Slot& operator[](std::uint32_t index) const { return slots_[index]; }
  std::size_t size() const noexcept { return slots_.size(); }
  auto begin() noexcept { return slots_.begin(); }
  auto end() noexcept { return slots_.end(); }
  auto begin() const noexcept { return slots_.begin(); }
  auto end() const noexcept { return slots_.end(); }
  std::size_t live() const noexcept { return live_; }
  // The slots, free list (its order decides the next slot handed out) and live count, for
  // snapshots; loading checks that they agree.
  template <typename Archive>
  void fields(Archive& archive) {
    archive(slots_);
    archive(free_);
    std::uint64_t live = live_;
    archive(live);
    live_ = static_cast<std::size_t>(live);
    if constexpr (Archive::loading) {
      std::size_t alive = 0;
      for (const Slot& slot : slots_) alive += slot.alive ? 1 : 0;
      if (alive != live_) archive.in.fail("a live count that does not match the slots");
      for (const std::uint32_t index : free_) {
        if (index >= slots_.size() || slots_[index].alive) {
          archive.in.fail("a free slot that is beyond the slots or alive");
        }
      }
    }
  }
  // Ids of the live slots, in slot order.
  template <typename Id>
  std::vector<Id> live_ids(std::uint32_t world) const {
    std::vector<Id> ids;
    ids.reserve(live_);
    for (std::uint32_t i = 0; i < slots_.size(); ++i) {
      if (slots_[i].alive) ids.push_back({i, slots_[i].generation, world});
    }
    return ids;
  }

 private:
  Slots slots_;
  std::vector<std::uint32_t> free_;
  std::size_t live_ = 0;
};

}  // namespace mink::detail
