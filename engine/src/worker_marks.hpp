#pragma once

// One bit per item (a contact, a joint), marked from several workers at once: each worker marks
// words of its own, and a word read is the union of the workers'. Workers marking one shared set
// of words with atomic ORs made its cache lines go back and forth between them (neighbouring
// bodies share contacts and joints), so the marking took as long on two workers as on one.

#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace mink::detail {

class WorkerMarks {
 public:
  // Nothing marked, for items [0, items) and workers [0, workers).
  void reset(std::size_t items, std::uint32_t workers) {
    words_ = (items + 63) / 64;
    workers_ = workers;
    bits_.assign(words_ * workers, 0);
  }
  void mark(std::uint32_t index, std::uint32_t worker) {
    bits_[worker * words_ + (index >> 6)] |= std::uint64_t{1} << (index & 63);
  }
  std::size_t words() const noexcept { return words_; }
  // Items [64 word, 64 word + 64) as any worker marked them.
  std::uint64_t word(std::size_t word) const {
    std::uint64_t marked = 0;
    for (std::uint32_t worker = 0; worker < workers_; ++worker) {
      marked |= bits_[worker * words_ + word];
    }
    return marked;
  }
  // visit(index) for each item any worker marked, in index order.
  template <typename Visit>
  void for_each_marked(Visit&& visit) const {
    for (std::size_t w = 0; w < words_; ++w) {
      for (std::uint64_t bits = word(w); bits != 0; bits &= bits - 1) {
        visit(
            static_cast<std::uint32_t>(w * 64 + static_cast<std::size_t>(std::countr_zero(bits))));
      }
    }
  }
  // Replaces those items' marks by `marked` (a pass that drops some of them, word by word).
  void set_word(std::size_t word, std::uint64_t marked) {
    bits_[word] = marked;
    for (std::uint32_t worker = 1; worker < workers_; ++worker) bits_[worker * words_ + word] = 0;
  }

 private:
  std::vector<std::uint64_t> bits_;  // worker by worker, words_ words each
  std::size_t words_ = 0;
  std::uint32_t workers_ = 0;
};

}  // namespace mink::detail
