#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "mink/broadphase/broadphase.hpp"
#include "mink/broadphase/fixed_grid.hpp"
#include "mink/broadphase/proxy_store.hpp"
#include "mink/byte_stream.hpp"

namespace mink {

/// Sweep and prune over fat boxes. The boxes live in one persistent array sorted by
/// (band, lower bound on the sweep axis): the sweep axis is the axis of larger spread, and the
/// other axis is cut into bands a few boxes high so that a sweep only meets boxes near in both
/// axes (a single sweep over a 2D world meets O(sqrt n) boxes per query). Each box sits in
/// the band of its lower bound, so it is stored once. Boxes far larger than the typical one
/// are kept apart in a short list every query tests.
///
/// Only proxies whose fat box changed (or that were created or destroyed) can begin or end
/// pairs, so update_pairs searches only for those: one pass over the pair list ends the pairs
/// with a touched member whose current boxes no longer overlap (O(pairs), which the engine
/// pays anyway to visit its contacts, and no index to keep), an insertion sort started at the
/// changed entries updates the array (frame coherence keeps it short), then sweeping the new boxes
/// finds the begun pairs, in array order so that each band's search resumes where the previous one
/// stopped. A pair is new exactly when the previous boxes did not overlap, so the pair list needs
/// no hash set.
class SweepAndPrune final : public Broadphase {
 public:
  explicit SweepAndPrune(Real margin = 0.1);
  explicit SweepAndPrune(const Fattening& fattening);

  ProxyId create_proxy(const Aabb& tight, ProxyKind kind, std::uint64_t user_data,
                       Real size = kSizeOfBox) override;
  void destroy_proxy(ProxyId id) override;
  bool move_proxy(ProxyId id, const Aabb& tight) override;
  void update_pairs(PairEvents& events) override;

  /// Runs body(begin, end, worker) over ranges covering [0, count), each of at least
  /// min_range items, with worker below `workers` (no two ranges running at once share one),
  /// and returns when all have run.
  using RangeBody = std::function<void(std::uint32_t, std::uint32_t, std::uint32_t)>;
  struct Ranges {
    std::uint32_t workers = 1;
    std::function<void(std::uint32_t count, std::uint32_t min_range, const RangeBody& body)> run;
  };
  /// update_pairs() with its searches for new pairs spread over `ranges`' workers; the pairs
  /// and events are the same, in the same order, on any number of them.
  void update_pairs(PairEvents& events, const Ranges& ranges);

  const std::vector<ProxyPair>& pairs() const override { return pairs_; }
  const Aabb& fat_aabb(ProxyId id) const override;
  std::uint64_t user_data(ProxyId id) const override;
  std::size_t proxy_count() const override { return store_.count(); }
  /// Whether `id` names a live proxy (a loaded snapshot's shapes are checked against it).
  bool is_proxy(ProxyId id) const { return store_.alive(id); }

  void query(const Aabb& box, std::vector<ProxyId>& out) const override;
  void query_point(const Vec2& point, std::vector<ProxyId>& out) const override;
  void query_fixed(const Aabb& box, std::vector<ProxyId>& out) const override;
  /// query_fixed() for a caller whose box is known to be well formed (finite, lower <= upper;
  /// not checked): found(id, user_data) for each proxy it would report, in the same order,
  /// without a list in between. Continuous collision makes one such query per fast body.
  template <typename Found>
  void for_each_fixed(const Aabb& box, Found&& found) const;
  /// Whether for_each_fixed(box) may find anything (`box` well formed, as there): false,
  /// cheaply, when no fixed box lies in the grid's rows or columns that `box` spans (most fast
  /// bodies are far from every obstacle).
  bool may_meet_fixed(const Aabb& box) const {
    if (fixed_stale_ || !touched_ids_.empty()) return true;
    return fixed_grid_.may_find(grid_box(oriented(box)));
  }

  // Statistics, for tests and tuning.
  int sweep_axis() const { return sweep_axis_; }
  std::size_t band_count() const { return band_count_; }
  std::size_t oversized_count() const { return oversized_.size(); }
  std::size_t rebuild_count() const { return rebuild_count_; }

  /// The whole state as snapshot bytes and back, the array order, the layout and the touched
  /// proxies included: a loaded broadphase reports the same pairs in the same order as the
  /// saved one would have.
  void save(SaveArchive& archive) const;
  void load(LoadArchive& archive);

 private:
  template <typename Archive>
  void fields(Archive& archive);
  /// Refuses, through `in`, a loaded state whose slots, entries, touched proxies, band starts
  /// or search cursors disagree.
  void check_loaded_state(ByteReader& in) const;
  /// A box in (sweep axis, band axis) coordinates, with its sort key.
  struct Entry {
    std::uint64_t key;
    Real lo0, hi0, lo1, hi1;
    ProxyId id;
    std::uint16_t is_static;  ///< static: never pairs with another static entry
    std::uint16_t is_fixed;   ///< static or kinematic: query_fixed() finds it
  };
  /// Per band: where a search ended (valid while stamp is the update's cursor_stamp_).
  struct Cursor {
    std::uint64_t stamp = 0;
    std::uint64_t key = 0;
    std::uint32_t index = 0;
  };
  /// What happened to a proxy since the last update_pairs.
  enum Touch : std::uint8_t { kMoved = 1, kCreated = 2, kDestroyed = 4 };
  static constexpr std::uint32_t kNoSlot = ~std::uint32_t{0};
  static constexpr std::uint32_t kOversizedBit = std::uint32_t{1} << 31;

  void touch(ProxyId id, std::uint8_t what);
  Entry make_entry(ProxyId id, const Aabb& box) const;
  /// Only the box of an entry: enough for overlap().
  Entry oriented(const Aabb& box) const;
  /// An entry as the fixed grid takes it.
  static FixedGrid::Box grid_box(const Entry& e) { return {e.lo0, e.hi0, e.lo1, e.hi1, e.id}; }
  bool is_oversized(const Entry& entry) const;
  std::uint32_t band_of(Real band_coordinate) const;

  static bool overlap(const Entry& x, const Entry& y);
  /// Calls visit(entry) for every stored entry overlapping q's box. start_in_band(band,
  /// band_end, key) finds the band's first entry with a key not below `key`.
  template <typename Visit, typename StartInBand>
  void sweep_bands(const Entry& q, Visit&& visit, StartInBand&& start_in_band) const;
  /// Calls visit(entry) for every stored entry overlapping `entry`'s box.
  template <typename Visit>
  void sweep(const Entry& entry, Visit&& visit) const;
  /// The fixed entries overlapping `q` in the sorted array, for queries while the grid is stale.
  void sweep_fixed(const Entry& q, std::vector<ProxyId>& out) const;

  static const Entry* gallop(const Entry* first, const Entry* last, std::uint64_t key);
  template <typename Visit>
  void resume_sweep(const Entry& entry, std::vector<Cursor>& cursors, Visit&& visit) const;
  /// Appends to `found` the pairs of m (whose entry is q) that sweep(q, visit) finds and that
  /// did not exist before.
  template <typename Sweep>
  void report_begun(ProxyId m, const Entry& q, std::vector<ProxyPair>& found, Sweep&& sweep) const;

  /// The slots of the touched proxies in entries_, ascending; `count` of them are expected.
  void collect_touched_slots(std::size_t count, std::vector<std::uint32_t>& out) const;
  void find_ended(PairEvents& events);
  void update_structure();
  void find_begun(PairEvents& events, const Ranges& ranges);
  void remove_entry(ProxyId id);
  void place_entry(const Entry& entry);
  /// Widens the sweep reach for a new entry and counts it if it falls outside the bands.
  void note_placed(const Entry& entry);
  /// Moves entries_[i] left to its place; true when it moved.
  bool sink(std::size_t i, std::size_t& shifts);
  void sort_changed();
  void rebuild();
  /// Lays fixed_grid_ out from the fixed entries of entries_ and oversized_.
  void refresh_fixed();
  /// Also refreshes band_begin_, which every change of entries_ invalidates.
  void recompute_slots();
  void find_band_starts();
  /// The first index in entries_ of each band, then n: what band_begin_ holds.
  void band_starts(std::vector<std::uint32_t>& band_begin) const;

  ProxyStore store_;
  std::vector<ProxyPair> pairs_;  ///< the pair set; begun pairs appended, ended ones compacted away

  std::vector<Entry> entries_;             ///< sorted by key; boxes as of the last update
  std::vector<std::uint32_t> band_begin_;  ///< per band: its first index in entries_, then n
  std::vector<Entry> oversized_;           ///< unsorted; boxes as of the last update
  std::vector<std::uint32_t> slot_;    ///< per id: index in entries_, or in oversized_ with the bit
  std::vector<Aabb> committed_;        ///< per id: fat box as of the last update
  std::vector<std::uint8_t> touched_;  ///< per id: Touch bits
  std::vector<ProxyId> touched_ids_;
  /// The fixed entries, for query_fixed(): fixed obstacles are few among many moving boxes,
  /// which a sweep of the bands would step over one by one. Stale (and not used) until the
  /// first update after a fixed proxy changed or the array was laid out anew.
  FixedGrid fixed_grid_;
  std::vector<FixedGrid::Box> fixed_boxes_;  ///< scratch for laying it out
  bool fixed_stale_ = true;

  // Scratch, kept to avoid allocating every step.
  std::vector<std::uint32_t> changed_slots_;
  std::vector<Entry> appended_;
  std::vector<std::uint32_t> query_slots_;
  /// Per worker and band: where resume_sweep's last search there ended.
  std::vector<std::vector<Cursor>> worker_cursors_;
  /// Per block of find_begun's searches: the pairs it found.
  std::vector<std::vector<ProxyPair>> begun_blocks_;
  std::uint64_t cursor_stamp_ = 0;  ///< this update's: a cursor of another is stale
  std::size_t dead_count_ = 0;

  // Layout, chosen at each rebuild.
  bool built_ = false;
  int sweep_axis_ = 0;
  Real band_origin_ = 0;
  Real band_scale_ = 1;  ///< bands per unit length
  std::uint32_t band_count_ = 1;
  Real cap0_ = 0, cap1_ = 0;                ///< extents beyond which a box is oversized
  Real max_extent0_ = 0, max_extent1_ = 0;  ///< largest extents among entries_
  std::size_t clamped_count_ = 0;           ///< entries placed outside the band range
  std::size_t rebuild_count_ = 0;
};

template <typename Found>
void SweepAndPrune::for_each_fixed(const Aabb& box, Found&& found) const {
  const Entry q = oriented(box);
  const auto report = [&](ProxyId id) { found(id, store_.user_data(id)); };
  if (fixed_stale_) {
    std::vector<ProxyId> ids;
    sweep_fixed(q, ids);
    for (const ProxyId id : ids) report(id);
  } else {
    fixed_grid_.query(grid_box(q), [&](ProxyId id) {
      if (touched_[id] == 0) report(id);
    });
  }
  // Fixed proxies changed since the last update, at their boxes now.
  for (const ProxyId id : touched_ids_) {
    if ((touched_[id] & kDestroyed) == 0 && store_.is_fixed(id) && store_.fat(id).overlaps(box)) {
      report(id);
    }
  }
}

}  // namespace mink
