#include "mink/broadphase/sweep_and_prune.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

namespace mink {

namespace {

// Band height in typical (median) box extents on the band axis: a query then spans two or
// three bands and meets few boxes in each.
constexpr Real kBandHeightFactor = 2.0;
// Boxes this many typical extents long on either axis are kept out of the bands: one of them
// in the bands would widen every sweep.
constexpr Real kOversizeFactor = 4.0;
constexpr std::uint32_t kMaxBands = 1u << 20;
// The extents of the sorted boxes are rounded; reaching this much further keeps every sweep
// conservative.
constexpr Real kReachSlack = 1e-9;
constexpr std::size_t kSampleSize = 1025;

// Order-preserving 32-bit image of x, rounded down: the low half of a sort key. Rounding
// down keeps the sweep bounds conservative; the exact test on the doubles decides.
std::uint32_t sweep_key(Real x) {
  constexpr Real kFloatMax = std::numeric_limits<float>::max();
  const Real clamped = std::clamp(x, -kFloatMax, kFloatMax);
  const float f = static_cast<float>(clamped) + 0.0f;  // -0 and +0 must map to one key
  const auto bits = std::bit_cast<std::uint32_t>(f);
  const std::uint32_t key = (bits & 0x80000000u) != 0 ? ~bits : (bits | 0x80000000u);
  // Consecutive floats have consecutive keys, so one less is the float below. f is above
  // -FLT_MAX when it rounded up, so this cannot wrap.
  return static_cast<Real>(f) > clamped ? key - 1 : key;
}

std::uint64_t make_key(std::uint32_t band, std::uint32_t low) {
  return (std::uint64_t{band} << 32) | low;
}

ProxyPair ordered(ProxyId x, ProxyId y) {
  return x < y ? ProxyPair{x, y} : ProxyPair{y, x};
}

// std::nextafter(x, -infinity), without the library call (every query makes two): the double
// below a positive one has the bit pattern one less, below a negative one one more.
Real below(Real x) {
  if (std::isnan(x) || x == -std::numeric_limits<Real>::infinity()) return x;
  if (x == 0) return -std::numeric_limits<Real>::denorm_min();
  const auto bits = std::bit_cast<std::uint64_t>(x);
  return std::bit_cast<Real>(x > 0 ? bits - 1 : bits + 1);
}

// The order of the entry array, and the same test against a bare key for searching it.
// Lambdas rather than functions so that the algorithms inline them.
constexpr auto by_key = [](const auto& x, const auto& y) { return x.key < y.key; };
constexpr auto key_below = [](const auto& entry, std::uint64_t key) { return entry.key < key; };

}  // namespace

SweepAndPrune::SweepAndPrune(Real margin) : store_(Fattening{margin}) {}

SweepAndPrune::SweepAndPrune(const Fattening& fattening) : store_(fattening) {}

ProxyId SweepAndPrune::create_proxy(const Aabb& tight, ProxyKind kind, std::uint64_t user_data,
                                    Real size) {
  const ProxyId id = store_.create(tight, kind, user_data, size);
  if (id >= slot_.size()) {
    slot_.resize(id + 1, kNoSlot);
    committed_.resize(id + 1);
    touched_.resize(id + 1, 0);
  }
  slot_[id] = kNoSlot;
  touch(id, kCreated);
  return id;
}

void SweepAndPrune::destroy_proxy(ProxyId id) {
  store_.destroy(id);
  touch(id, kDestroyed);
}

bool SweepAndPrune::move_proxy(ProxyId id, const Aabb& tight) {
  if (!store_.move(id, tight)) return false;
  touch(id, kMoved);
  return true;
}

void SweepAndPrune::touch(ProxyId id, std::uint8_t what) {
  if (touched_[id] == 0) touched_ids_.push_back(id);
  touched_[id] |= what;
}

const Aabb& SweepAndPrune::fat_aabb(ProxyId id) const {
  store_.check_alive(id, "fat_aabb");
  return store_.fat(id);
}

std::uint64_t SweepAndPrune::user_data(ProxyId id) const {
  store_.check_alive(id, "user_data");
  return store_.user_data(id);
}

std::uint32_t SweepAndPrune::band_of(Real band_coordinate) const {
  const Real t = (band_coordinate - band_origin_) * band_scale_;
  if (!(t > 0)) return 0;
  if (t >= static_cast<Real>(band_count_ - 1)) return band_count_ - 1;
  return static_cast<std::uint32_t>(t);
}

SweepAndPrune::Entry SweepAndPrune::oriented(const Aabb& box) const {
  const int s = sweep_axis_;
  const int b = 1 - s;
  Entry entry{};
  entry.lo0 = box.lower[s];
  entry.hi0 = box.upper[s];
  entry.lo1 = box.lower[b];
  entry.hi1 = box.upper[b];
  return entry;
}

SweepAndPrune::Entry SweepAndPrune::make_entry(ProxyId id, const Aabb& box) const {
  Entry entry = oriented(box);
  entry.key = make_key(band_of(entry.lo1), sweep_key(entry.lo0));
  entry.id = id;
  entry.is_static = static_cast<std::uint16_t>(store_.is_static(id));
  entry.is_fixed = static_cast<std::uint16_t>(store_.is_fixed(id));
  return entry;
}

bool SweepAndPrune::is_oversized(const Entry& entry) const {
  return entry.hi0 - entry.lo0 > cap0_ || entry.hi1 - entry.lo1 > cap1_;
}

bool SweepAndPrune::overlap(const Entry& x, const Entry& y) {
  return x.lo0 <= y.hi0 && y.lo0 <= x.hi0 && x.lo1 <= y.hi1 && y.lo1 <= x.hi1;
}

template <typename Visit, typename StartInBand>
void SweepAndPrune::sweep_bands(const Entry& q, Visit&& visit, StartInBand&& start_in_band) const {
  if (!entries_.empty()) {
    // An entry overlapping q starts at most one largest extent before q on each axis.
    const Real reach0 = max_extent0_ * (1 + kReachSlack);
    const Real reach1 = max_extent1_ * (1 + kReachSlack);
    const std::uint32_t first_band = band_of(below(q.lo1 - reach1));
    const std::uint32_t last_band = band_of(q.hi1);
    const std::uint32_t low = sweep_key(below(q.lo0 - reach0));
    const std::uint32_t high = sweep_key(q.hi0);
    const Entry* const entries = entries_.data();
    for (std::uint32_t band = first_band; band <= last_band; ++band) {
      const Entry* const band_end = entries + band_begin_[band + 1];
      const Entry* it = start_in_band(band, band_end, make_key(band, low));
      const std::uint64_t stop = make_key(band, high);
      for (; it != band_end && it->key <= stop; ++it) {
        if (overlap(*it, q)) visit(*it);
      }
    }
  }
  for (const Entry& e : oversized_) {
    if (overlap(e, q)) visit(e);
  }
}

template <typename Visit>
void SweepAndPrune::sweep(const Entry& q, Visit&& visit) const {
  sweep_bands(q, visit, [&](std::uint32_t band, const Entry* band_end, std::uint64_t start) {
    return std::lower_bound(entries_.data() + band_begin_[band], band_end, start, key_below);
  });
}

// The first entry in [first, last) with a key not below `key`, when none before `first` is:
// a doubling search from `first`, cheap when the answer is near.
const SweepAndPrune::Entry* SweepAndPrune::gallop(const Entry* first, const Entry* last,
                                                  std::uint64_t key) {
  std::ptrdiff_t step = 1;
  while (first != last && first->key < key) {
    if (last - first <= step) return std::lower_bound(first + 1, last, key, key_below);
    const Entry* const probe = first + step;
    if (probe->key >= key) return std::lower_bound(first + 1, probe, key, key_below);
    first = probe + 1;
    step *= 2;
  }
  return first;
}

// sweep() for queries that come in array order: each band keeps, in `cursors`, where the
// previous query's search ended and searches onward from there. A query whose search bound lies
// below the kept one (rounding can reorder equal keys, and a worker's next block may lie
// before its last) starts afresh.
template <typename Visit>
void SweepAndPrune::resume_sweep(const Entry& q, std::vector<Cursor>& cursors,
                                 Visit&& visit) const {
  sweep_bands(q, visit, [&](std::uint32_t band, const Entry* band_end, std::uint64_t start) {
    const Entry* const entries = entries_.data();
    Cursor& cursor = cursors[band];
    if (cursor.stamp != cursor_stamp_ || start < cursor.key) {
      cursor = {cursor_stamp_, start, band_begin_[band]};
    }
    const Entry* const it = gallop(entries + cursor.index, band_end, start);
    cursor.key = start;
    cursor.index = static_cast<std::uint32_t>(it - entries);
    return it;
  });
}

void SweepAndPrune::find_band_starts() {
  band_starts(band_begin_);
}

void SweepAndPrune::band_starts(std::vector<std::uint32_t>& band_begin) const {
  band_begin.resize(std::size_t{band_count_} + 1);
  const std::size_t n = entries_.size();
  if (std::size_t{band_count_} * 16 > n) {
    // Many bands for few entries: one pass.
    std::size_t i = 0;
    for (std::uint32_t band = 0; band < band_count_; ++band) {
      while (i < n && (entries_[i].key >> 32) < band) ++i;
      band_begin[band] = static_cast<std::uint32_t>(i);
    }
  } else {
    for (std::uint32_t band = 0; band < band_count_; ++band) {
      band_begin[band] = static_cast<std::uint32_t>(
          std::lower_bound(entries_.begin(), entries_.end(), make_key(band, 0), key_below) -
          entries_.begin());
    }
  }
  band_begin[band_count_] = static_cast<std::uint32_t>(n);
}

void SweepAndPrune::update_pairs(PairEvents& events) {
  update_pairs(events, Ranges{});
}

void SweepAndPrune::update_pairs(PairEvents& events, const Ranges& ranges) {
  events.begun.clear();
  events.ended.clear();
  if (touched_ids_.empty()) return;
  find_ended(events);
  update_structure();
  find_begun(events, ranges);
  for (const ProxyId id : touched_ids_) {
    if ((touched_[id] & (kCreated | kDestroyed)) != 0 || store_.is_fixed(id)) fixed_stale_ = true;
    if ((touched_[id] & kDestroyed) == 0) committed_[id] = store_.fat(id);
    touched_[id] = 0;
  }
  touched_ids_.clear();
  store_.release_destroyed();
  if (fixed_stale_) refresh_fixed();
}

void SweepAndPrune::refresh_fixed() {
  fixed_boxes_.clear();
  const auto gather = [&](const std::vector<Entry>& entries) {
    for (const Entry& e : entries) {
      if (e.is_fixed != 0) fixed_boxes_.push_back(grid_box(e));
    }
  };
  gather(entries_);
  gather(oversized_);
  fixed_grid_.build(fixed_boxes_);
  fixed_stale_ = false;
}

// Pairs that no longer overlap. Only a pair with a touched member can end, and testing it on
// the current boxes is one lookup, so one pass over the pair list replaces a search with
// each touched proxy's previous box; the survivors are compacted in place.
void SweepAndPrune::find_ended(PairEvents& events) {
  std::size_t kept = 0;
  const std::uint8_t* const touched = touched_.data();
  for (const ProxyPair pair : pairs_) {
    const std::uint8_t touch = touched[pair.a] | touched[pair.b];
    // Tested whether touched or not: a branch on the touch would be mispredicted often.
    const bool apart = !store_.fat(pair.a).overlaps(store_.fat(pair.b));
    const bool ended = touch != 0 && ((touch & kDestroyed) != 0 || apart);
    pairs_[kept] = pair;
    kept += ended ? 0 : 1;
    if (ended) events.ended.push_back(pair);
  }
  pairs_.resize(kept);
}

// Pairs of the new boxes that did not overlap before (or involve a new proxy).
void SweepAndPrune::collect_touched_slots(std::size_t count,
                                          std::vector<std::uint32_t>& out) const {
  out.clear();
  // A pass over the array beats sorting the slots once a fair share of the entries is
  // touched.
  if (count * 8 > entries_.size()) {
    for (std::uint32_t i = 0; i < entries_.size(); ++i) {
      if (touched_[entries_[i].id] != 0) out.push_back(i);
    }
    return;
  }
  for (const ProxyId m : touched_ids_) {
    if ((touched_[m] & kDestroyed) == 0 && (slot_[m] & kOversizedBit) == 0) {
      out.push_back(slot_[m]);
    }
  }
  std::sort(out.begin(), out.end());
}

void SweepAndPrune::find_begun(PairEvents& events, const Ranges& ranges) {
  // The begun pairs collect in events.begun (empty until now) and join the pair list at the
  // end. Oversized entries sweep on their own.
  std::size_t banded = 0;
  for (const ProxyId m : touched_ids_) {
    if ((touched_[m] & kDestroyed) != 0) continue;
    const std::uint32_t slot = slot_[m];
    if ((slot & kOversizedBit) != 0) {
      report_begun(m, oversized_[slot & ~kOversizedBit], events.begun,
                   [&](const Entry& q, auto&& v) { sweep(q, v); });
    } else {
      ++banded;
    }
  }
  // Banded entries are searched in array order, so each band's search resumes where the
  // previous one stopped; in blocks, spread over the workers, each block's pairs kept apart
  // and taken in block order, so the pairs come in the same order on any number of workers.
  collect_touched_slots(banded, query_slots_);
  ++cursor_stamp_;
  constexpr std::uint32_t kBlock = 256;
  const auto count = static_cast<std::uint32_t>(query_slots_.size());
  const std::uint32_t blocks = (count + kBlock - 1) / kBlock;
  begun_blocks_.resize(blocks);
  const std::uint32_t workers = ranges.run ? std::max<std::uint32_t>(ranges.workers, 1) : 1;
  if (worker_cursors_.size() < workers) worker_cursors_.resize(workers);
  const auto search = [&](std::uint32_t first_block, std::uint32_t end_block,
                          std::uint32_t worker) {
    std::vector<Cursor>& cursors = worker_cursors_[worker];
    if (cursors.size() < band_count_) cursors.resize(band_count_);
    for (std::uint32_t block = first_block; block < end_block; ++block) {
      std::vector<ProxyPair>& found = begun_blocks_[block];
      found.clear();
      const std::uint32_t begin = block * kBlock;
      const std::uint32_t end = std::min(count, begin + kBlock);
      // The previous boxes are indexed by id, so in array order they are scattered: fetched a
      // few queries ahead.
      constexpr std::uint32_t kAhead = 4;
      for (std::uint32_t k = begin; k < end; ++k) {
        if (k + kAhead < end)
          __builtin_prefetch(&committed_[entries_[query_slots_[k + kAhead]].id]);
        const Entry& q = entries_[query_slots_[k]];
        report_begun(q.id, q, found,
                     [&](const Entry& query, auto&& v) { resume_sweep(query, cursors, v); });
      }
    }
  };
  if (workers > 1 && blocks > 1) {
    ranges.run(blocks, 1, search);
  } else {
    search(0, blocks, 0);
  }
  for (std::uint32_t block = 0; block < blocks; ++block) {
    events.begun.insert(events.begun.end(), begun_blocks_[block].begin(),
                        begun_blocks_[block].end());
  }
  pairs_.insert(pairs_.end(), events.begun.begin(), events.begun.end());
}

template <typename Sweep>
void SweepAndPrune::report_begun(ProxyId m, const Entry& q, std::vector<ProxyPair>& found,
                                 Sweep&& sweep) const {
  const bool m_new = (touched_[m] & kCreated) != 0;
  const Entry before = m_new ? q : oriented(committed_[m]);
  sweep(q, [&](const Entry& e) {
    const ProxyId o = e.id;
    if (o == m || (q.is_static != 0 && e.is_static != 0)) return;
    const std::uint8_t touch_o = touched_[o];
    if (touch_o != 0 && o < m) return;
    // An untouched partner's box in the array is also its previous box.
    const bool existed =
        !m_new && (touch_o != 0 ? (touch_o & kCreated) == 0 && committed_[m].overlaps(committed_[o])
                                : overlap(before, e));
    if (!existed) found.push_back(ordered(m, o));
  });
}

void SweepAndPrune::remove_entry(ProxyId id) {
  const std::uint32_t slot = slot_[id];
  if ((slot & kOversizedBit) != 0) {
    const std::uint32_t index = slot & ~kOversizedBit;
    oversized_[index] = oversized_.back();
    slot_[oversized_[index].id] = index | kOversizedBit;
    oversized_.pop_back();
  } else {
    // Compacted away in sort_changed().
    entries_[slot].id = null_proxy;
    ++dead_count_;
  }
  slot_[id] = kNoSlot;
}

// Puts an entry that is not in the array yet where it belongs: the oversized list, or the
// appended batch merged in by sort_changed().
void SweepAndPrune::place_entry(const Entry& entry) {
  if (is_oversized(entry)) {
    slot_[entry.id] = static_cast<std::uint32_t>(oversized_.size()) | kOversizedBit;
    oversized_.push_back(entry);
  } else {
    appended_.push_back(entry);
  }
}

void SweepAndPrune::update_structure() {
  std::size_t created = 0;
  for (const ProxyId id : touched_ids_) created += (touched_[id] & kCreated) != 0 ? 1 : 0;
  // Mass insertion, or boxes drifted far outside the bands: sort from scratch.
  if (!built_ || created * 4 > entries_.size() || clamped_count_ * 4 > entries_.size() + 256) {
    rebuild();
    return;
  }
  changed_slots_.clear();
  appended_.clear();
  dead_count_ = 0;
  for (const ProxyId id : touched_ids_) {
    const std::uint8_t touch = touched_[id];
    if ((touch & kCreated) != 0 && (touch & kDestroyed) != 0) continue;
    if ((touch & kDestroyed) != 0) {
      remove_entry(id);
      continue;
    }
    const Entry entry = make_entry(id, store_.fat(id));
    if ((touch & kCreated) != 0) {
      place_entry(entry);
      continue;
    }
    const std::uint32_t slot = slot_[id];
    const bool oversized = is_oversized(entry);
    if ((slot & kOversizedBit) != 0 && oversized) {
      oversized_[slot & ~kOversizedBit] = entry;
    } else if ((slot & kOversizedBit) == 0 && !oversized) {
      entries_[slot] = entry;
      changed_slots_.push_back(slot);
    } else {
      remove_entry(id);
      place_entry(entry);
    }
  }
  for (const std::uint32_t slot : changed_slots_) note_placed(entries_[slot]);
  for (const Entry& entry : appended_) note_placed(entry);
  sort_changed();
}

void SweepAndPrune::note_placed(const Entry& entry) {
  max_extent0_ = std::max(max_extent0_, entry.hi0 - entry.lo0);
  max_extent1_ = std::max(max_extent1_, entry.hi1 - entry.lo1);
  const Real t = (entry.lo1 - band_origin_) * band_scale_;
  if (t < 0 || t >= static_cast<Real>(band_count_) ||
      (band_scale_ == 0 && entry.lo1 != band_origin_)) {
    ++clamped_count_;
  }
}

bool SweepAndPrune::sink(std::size_t i, std::size_t& shifts) {
  const Entry entry = entries_[i];
  std::size_t j = i;
  while (j > 0 && entries_[j - 1].key > entry.key) {
    entries_[j] = entries_[j - 1];
    slot_[entries_[j].id] = static_cast<std::uint32_t>(j);
    --j;
  }
  if (j == i) return false;
  entries_[j] = entry;
  slot_[entry.id] = static_cast<std::uint32_t>(j);
  shifts += i - j;
  return true;
}

void SweepAndPrune::sort_changed() {
  const std::size_t n = entries_.size();
  // Insertion sort pays while the boxes moved little; beyond this many shifts a full sort is
  // cheaper.
  const std::size_t budget = 8 * n + 1024;
  std::size_t shifts = 0;
  if (dead_count_ == 0 && appended_.empty()) {
    // Only the changed entries and their right neighbours can be out of order, and a shift
    // at position i can only disorder position i + 1.
    collect_touched_slots(changed_slots_.size(), changed_slots_);
    constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
    std::size_t listed = 0;
    std::size_t follow = kNone;
    for (;;) {
      const std::size_t next_listed =
          listed < changed_slots_.size() ? changed_slots_[listed] : kNone;
      const std::size_t i = std::min(next_listed, follow);
      if (i >= n) break;
      const bool was_listed = i == next_listed;
      if (was_listed) ++listed;
      const bool shifted = i > 0 && sink(i, shifts);
      follow = was_listed || shifted ? i + 1 : kNone;
      if (shifts > budget) break;
    }
    if (shifts <= budget) {
      find_band_starts();
      return;
    }
  } else {
    std::size_t kept = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (entries_[i].id != null_proxy) entries_[kept++] = entries_[i];
    }
    entries_.resize(kept);
    for (std::size_t i = 1; i < kept && shifts <= budget; ++i) sink(i, shifts);
    if (shifts <= budget && !appended_.empty()) {
      std::sort(appended_.begin(), appended_.end(), by_key);
      entries_.insert(entries_.end(), appended_.begin(), appended_.end());
      std::inplace_merge(entries_.begin(), entries_.begin() + static_cast<std::ptrdiff_t>(kept),
                         entries_.end(), by_key);
    } else if (!appended_.empty()) {
      entries_.insert(entries_.end(), appended_.begin(), appended_.end());
    }
    appended_.clear();
    dead_count_ = 0;
    if (shifts <= budget) {
      recompute_slots();
      return;
    }
  }
  std::sort(entries_.begin(), entries_.end(), by_key);
  recompute_slots();
}

void SweepAndPrune::recompute_slots() {
  find_band_starts();
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    slot_[entries_[i].id] = static_cast<std::uint32_t>(i);
  }
}

void SweepAndPrune::rebuild() {
  ++rebuild_count_;
  fixed_stale_ = true;
  built_ = true;
  entries_.clear();
  oversized_.clear();
  appended_.clear();
  dead_count_ = 0;
  clamped_count_ = 0;
  // Every slot is set again below; those of proxies destroyed since the last update would
  // otherwise keep pointing into the old arrays (and a snapshot of them would not load).
  std::fill(slot_.begin(), slot_.end(), kNoSlot);

  std::vector<ProxyId> ids;
  ids.reserve(store_.count());
  Vec2 low = Vec2::Constant(std::numeric_limits<Real>::infinity());
  Vec2 high = -low;
  for (ProxyId id = 0; id < store_.id_bound(); ++id) {
    if (!store_.alive(id)) continue;
    ids.push_back(id);
    low = low.cwiseMin(store_.fat(id).lower);
    high = high.cwiseMax(store_.fat(id).lower);
  }
  const std::size_t n = ids.size();
  if (n == 0) {
    find_band_starts();  // every band empty
    return;
  }

  // Sweep along the axis of larger spread; cut the other one into bands.
  const Vec2 spread = high - low;
  sweep_axis_ = spread.x() >= spread.y() ? 0 : 1;
  const int s = sweep_axis_;
  const int b = 1 - s;

  // Typical extents from an even sample.
  std::vector<Real> extents0, extents1;
  const std::size_t step = std::max<std::size_t>(1, n / kSampleSize);
  for (std::size_t i = 0; i < n; i += step) {
    const Aabb& box = store_.fat(ids[i]);
    extents0.push_back(box.upper[s] - box.lower[s]);
    extents1.push_back(box.upper[b] - box.lower[b]);
  }
  const auto median = [](std::vector<Real>& values) {
    auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
  };
  const Real median0 = median(extents0);
  const Real median1 = median(extents1);
  constexpr Real kInfinity = std::numeric_limits<Real>::infinity();
  cap0_ = median0 > 0 ? kOversizeFactor * median0 : kInfinity;
  cap1_ = median1 > 0 ? kOversizeFactor * median1 : kInfinity;

  const Real range = spread[b];
  band_origin_ = low[b];
  band_count_ = 1;
  band_scale_ = 0;
  if (range > 0) {
    Real height = kBandHeightFactor * median1;
    if (!(height > 0)) height = range / std::sqrt(static_cast<Real>(n));
    const Real wanted = std::floor(range / height) + 1;
    const Real most =
        static_cast<Real>(std::min<std::size_t>(kMaxBands, std::max<std::size_t>(1, n / 2)));
    band_count_ = static_cast<std::uint32_t>(std::min(wanted, most));
    band_scale_ = 1 / std::max(height, range / band_count_);
  }

  max_extent0_ = 0;
  max_extent1_ = 0;
  clamped_count_ = 0;
  entries_.reserve(n);
  for (const ProxyId id : ids) {
    const Entry entry = make_entry(id, store_.fat(id));
    if (is_oversized(entry)) {
      slot_[id] = static_cast<std::uint32_t>(oversized_.size()) | kOversizedBit;
      oversized_.push_back(entry);
    } else {
      note_placed(entry);
      entries_.push_back(entry);
    }
  }
  std::sort(entries_.begin(), entries_.end(), by_key);
  recompute_slots();
}

void SweepAndPrune::query(const Aabb& box, std::vector<ProxyId>& out) const {
  ProxyStore::check_box(box, "query");
  // The array holds the boxes of the last update; touched proxies are tested on their
  // current boxes instead.
  sweep(oriented(box), [&](const Entry& e) {
    if (touched_[e.id] == 0) out.push_back(e.id);
  });
  for (const ProxyId id : touched_ids_) {
    if ((touched_[id] & kDestroyed) == 0 && store_.fat(id).overlaps(box)) out.push_back(id);
  }
}

void SweepAndPrune::query_fixed(const Aabb& box, std::vector<ProxyId>& out) const {
  ProxyStore::check_box(box, "query_fixed");
  for_each_fixed(box, [&](ProxyId id, std::uint64_t) { out.push_back(id); });
}

void SweepAndPrune::sweep_fixed(const Entry& q, std::vector<ProxyId>& out) const {
  sweep(q, [&](const Entry& e) {
    if (e.is_fixed != 0 && touched_[e.id] == 0) out.push_back(e.id);
  });
}

void SweepAndPrune::query_point(const Vec2& point, std::vector<ProxyId>& out) const {
  ProxyStore::check_point(point, "query_point");
  query(Aabb{point, point}, out);
}

}  // namespace mink

namespace mink {

template <typename Archive>
void SweepAndPrune::fields(Archive& archive) {
  const auto entries = [&](std::vector<Entry>& list) {
    if constexpr (Archive::loading) {
      list.resize(archive.count(sizeof(Entry) / 2));
    } else {
      archive.count(list.size());
    }
    for (Entry& e : list) {
      archive(e.key);
      archive(e.lo0);
      archive(e.hi0);
      archive(e.lo1);
      archive(e.hi1);
      archive(e.id);
      archive(e.is_static);
      archive(e.is_fixed);
    }
  };
  if constexpr (Archive::loading) {
    store_.load(archive);
    pairs_.resize(archive.count(2 * sizeof(ProxyId)));
  } else {
    store_.save(archive);
    archive.count(pairs_.size());
  }
  for (ProxyPair& pair : pairs_) {
    archive(pair.a);
    archive(pair.b);
  }
  entries(entries_);
  archive(band_begin_);
  entries(oversized_);
  archive(slot_);
  archive(committed_);
  archive(touched_);
  archive(touched_ids_);
  // The search cursors say nothing past the update that set them (each update stamps its
  // own): written as none; a snapshot's own are read, checked and left.
  std::vector<Cursor> cursors;
  if constexpr (Archive::loading) {
    cursors.resize(archive.count(sizeof(Cursor) / 2));
  } else {
    archive.count(cursors.size());
  }
  for (Cursor& cursor : cursors) {
    archive(cursor.stamp);
    archive(cursor.key);
    archive(cursor.index);
  }
  archive(cursor_stamp_);
  if constexpr (Archive::loading) {
    for (const Cursor& cursor : cursors) {
      if (cursor.stamp > cursor_stamp_) {
        archive.in.fail("a broadphase cursor stamped ahead of its sweeps");
      }
    }
  }
  std::uint64_t dead = dead_count_, clamped = clamped_count_, rebuilds = rebuild_count_;
  archive(dead);
  archive(built_);
  archive(sweep_axis_);
  archive(band_origin_);
  archive(band_scale_);
  archive(band_count_);
  archive(cap0_);
  archive(cap1_);
  archive(max_extent0_);
  archive(max_extent1_);
  archive(clamped);
  archive(rebuilds);
  dead_count_ = static_cast<std::size_t>(dead);
  clamped_count_ = static_cast<std::size_t>(clamped);
  rebuild_count_ = static_cast<std::size_t>(rebuilds);
  if constexpr (Archive::loading) {
    // What the queries index with must stay in range; the checksum guards the rest.
    const std::size_t ids = store_.id_bound();
    if (slot_.size() > ids || committed_.size() > ids || touched_.size() > ids) {
      archive.in.fail("broadphase per-proxy arrays longer than the proxies");
    }
    for (const ProxyPair& pair : pairs_) {
      if (pair.a >= ids || pair.b >= ids) archive.in.fail("a broadphase pair of unknown proxies");
    }
    for (const std::vector<Entry>* list : {&entries_, &oversized_}) {
      for (const Entry& e : *list) {
        if (e.id >= ids) archive.in.fail("a broadphase entry of an unknown proxy");
      }
    }
    for (std::size_t id = 0; id < slot_.size(); ++id) {
      const std::uint32_t s = slot_[id];
      const std::size_t bound = (s & kOversizedBit) != 0 ? oversized_.size() : entries_.size();
      if (s != kNoSlot && (s & ~kOversizedBit) >= bound) {
        archive.in.fail("a broadphase slot beyond its array: proxy " + std::to_string(id) + " at " +
                        std::to_string(s & ~kOversizedBit) + " of " + std::to_string(bound) +
                        ((s & kOversizedBit) != 0 ? " oversized entries" : " entries"));
      }
    }
    for (const std::uint32_t b : band_begin_) {
      if (b > entries_.size()) archive.in.fail("a broadphase band beyond the entries");
    }
    // The bands as a rebuild leaves them: the next one sizes its tables by band_count_ (a
    // count of 10^9 asked for gigabytes).
    if (band_count_ < 1 || band_count_ > kMaxBands || (sweep_axis_ != 0 && sweep_axis_ != 1) ||
        (!band_begin_.empty() && band_begin_.size() != std::size_t{band_count_} + 1) ||
        !std::isfinite(band_origin_) || !std::isfinite(band_scale_) || band_scale_ < 0 ||
        !(cap0_ >= 0) || !(cap1_ >= 0) || !std::isfinite(max_extent0_) ||
        !std::isfinite(max_extent1_)) {
      archive.in.fail("broadphase bands out of range: " + std::to_string(band_count_) + " bands, " +
                      std::to_string(band_begin_.size()) + " band starts, axis " +
                      std::to_string(sweep_axis_) + ", scale " + std::to_string(band_scale_) +
                      ", caps " + std::to_string(cap0_) + " and " + std::to_string(cap1_));
    }
    for (const ProxyId id : touched_ids_) {
      if (id >= ids) archive.in.fail("a touched proxy that does not exist");
    }
    check_loaded_state(archive.in);
  }
}

// What the updates and sweeps take on trust, checked for a loaded state: each proxy's slot
// names the entry that holds it, the touched list holds each touched proxy once, a proxy has an
// entry exactly when the next update expects one (one created since has none yet; one
// destroyed since still has its own), the band starts are the entries' own, and no search
// cursor carries a stamp the next sweep could take for its own.
void SweepAndPrune::check_loaded_state(ByteReader& in) const {
  const std::size_t ids = store_.id_bound();
  if (slot_.size() != ids || committed_.size() != ids || touched_.size() != ids) {
    in.fail("broadphase per-proxy arrays not one entry per proxy");
  }
  const auto check_list = [&](const std::vector<Entry>& list, std::uint32_t bit) {
    for (std::size_t i = 0; i < list.size(); ++i) {
      const ProxyId id = list[i].id;
      if (id == null_proxy) continue;
      if (slot_[id] != (static_cast<std::uint32_t>(i) | bit)) {
        in.fail("a broadphase entry its proxy's slot does not name: proxy " + std::to_string(id));
      }
    }
  };
  check_list(entries_, 0);
  check_list(oversized_, kOversizedBit);
  if (!std::is_sorted(entries_.begin(), entries_.end(), by_key)) {
    in.fail("broadphase entries out of order");
  }
  constexpr std::uint8_t kAnyTouch = kMoved | kCreated | kDestroyed;
  std::size_t touched_count = 0;
  for (std::size_t id = 0; id < ids; ++id) {
    const std::uint32_t s = slot_[id];
    const std::vector<Entry>& list = (s & kOversizedBit) != 0 ? oversized_ : entries_;
    if (s != kNoSlot && list[s & ~kOversizedBit].id != id) {
      in.fail("a broadphase slot naming another proxy's entry: proxy " + std::to_string(id));
    }
    const std::uint8_t touch = touched_[id];
    if ((touch & ~kAnyTouch) != 0) in.fail("a broadphase proxy touched in an unknown way");
    touched_count += touch != 0 ? 1 : 0;
    const bool alive = store_.alive(static_cast<ProxyId>(id));
    const bool created = (touch & kCreated) != 0, destroyed = (touch & kDestroyed) != 0;
    if (alive ? destroyed : (touch != 0 && !destroyed)) {
      in.fail("a broadphase proxy touched unlike its life: proxy " + std::to_string(id));
    }
    if (!built_) continue;
    const bool listed = alive ? !created : destroyed && !created;
    if ((s != kNoSlot) != listed) {
      in.fail("a broadphase proxy " + std::string(listed ? "missing from" : "left in") +
              " the sorted boxes: proxy " + std::to_string(id));
    }
  }
  std::vector<std::uint8_t> seen(ids, 0);
  for (const ProxyId id : touched_ids_) {
    if (touched_[id] == 0 || seen[id]++ != 0) in.fail("a broadphase touched list unlike its flags");
  }
  if (touched_ids_.size() != touched_count) in.fail("a broadphase touched list unlike its flags");

  // (A broadphase never built has neither.)
  if (!entries_.empty() || !band_begin_.empty()) {
    std::vector<std::uint32_t> own;
    band_starts(own);
    if (band_begin_ != own) in.fail("broadphase band starts that are not the entries' own");
  }
  if (cursor_stamp_ == std::numeric_limits<std::uint64_t>::max()) {
    in.fail("a broadphase cursor stamp at its largest value");
  }
}

void SweepAndPrune::save(SaveArchive& archive) const {
  const_cast<SweepAndPrune*>(this)->fields(archive);
}
void SweepAndPrune::load(LoadArchive& archive) {
  fields(archive);
  refresh_fixed();
  // Stamps of the state before may come again.
  worker_cursors_.clear();
}

}  // namespace mink
