#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "mink/broadphase/proxy_store.hpp"
#include "mink/geometry/types.hpp"

namespace mink {

/// @brief The fixed obstacles (static and kinematic boxes) in a uniform grid, for the
/// queries continuous collision makes: one per fast body, at scattered places, mostly
/// finding nothing. A query looks at the one to four cells its box covers, where a scan of
/// boxes sorted along one axis would step over every obstacle in a slab across the world
/// (the far side of a ring, a row of floor segments) and over every large one (a drum's
/// walls). Rebuilt whole by build(); the brute-force broadphase is its test oracle.
class FixedGrid {
 public:
  /// A box on the two axes the caller chose, and whose it is.
  struct Box {
    Real lo0, hi0, lo1, hi1;
    ProxyId id;
  };

  /// Lays `boxes` out anew (they must be finite, lo <= hi); the order of their ids in a
  /// query's answer follows from theirs.
  void build(const std::vector<Box>& boxes);
  void clear();
  bool empty() const noexcept { return boxes_.empty(); }

  /// Calls found(id) once for every box overlapping `q` (touching counts), in an order fixed
  /// by the boxes given to build().
  template <typename Found>
  void query(const Box& q, Found&& found) const;
  /// Whether query(q) may find anything: false when none of q's columns (on axis 0) or none
  /// of its rows (on axis 1) holds a box, found at the cost of four reads.
  bool may_find(const Box& q) const {
    if (boxes_.empty()) return false;
    if (!spanning_.empty()) return true;
    // A box overlapping q has a column and a row among q's (cell_on keeps the order of
    // coordinates).
    const auto any_in = [&](const std::vector<std::uint32_t>& before, Real lo, Real hi, Real origin,
                            std::uint32_t cells) {
      return before[cell_on(hi, origin, cells) + 1] != before[cell_on(lo, origin, cells)];
    };
    return any_in(columns_before_, q.lo0, q.hi0, origin0_, cells0_) &&
           any_in(rows_before_, q.lo1, q.hi1, origin1_, cells1_);
  }

 private:
  struct Placed {
    Box box;
    std::uint32_t cell0, cell1;  ///< its first cell on each axis: where a query reports it
  };
  std::uint32_t cell_on(Real v, Real origin, std::uint32_t cells) const {
    const Real t = (v - origin) * inverse_cell_;
    if (!(t > 0)) return 0;
    if (t >= static_cast<Real>(cells - 1)) return cells - 1;
    return static_cast<std::uint32_t>(t);
  }
  static bool overlaps(const Box& x, const Box& q) {
    // Without branches: most boxes a query meets lie beside it, at no learnable pattern.
    return (static_cast<int>(x.lo0 <= q.hi0) & static_cast<int>(q.lo0 <= x.hi0) &
            static_cast<int>(x.lo1 <= q.hi1) & static_cast<int>(q.lo1 <= x.hi1)) != 0;
  }

  std::vector<Placed> boxes_;
  std::vector<std::uint32_t> cell_begin_;  ///< per cell (row-major on axis 1): into refs_, then n
  /// A bit per cell, set where the cell holds a box: most queries meet only empty cells, and
  /// these bits stay in the nearest cache where cell_begin_ does not.
  std::vector<std::uint64_t> occupied_;
  bool occupied(std::uint32_t cell) const { return (occupied_[cell >> 6] >> (cell & 63) & 1) != 0; }
  /// Per column on axis 0 and per row on axis 1: how many before it hold a box, then the count
  /// of all. A fast body's query mostly lies in rows or columns with none at all (a body
  /// falling between shelves, or beside a wall).
  std::vector<std::uint32_t> columns_before_, rows_before_;
  std::vector<std::uint32_t> refs_;      ///< indices into boxes_, by cell
  std::vector<std::uint32_t> spanning_;  ///< boxes over too many cells, looked at by every query
  Real origin0_ = 0, origin1_ = 0, inverse_cell_ = 0;
  std::uint32_t cells0_ = 0, cells1_ = 0;
};

template <typename Found>
void FixedGrid::query(const Box& q, Found&& found) const {
  if (!may_find(q)) return;
  const std::uint32_t first0 = cell_on(q.lo0, origin0_, cells0_);
  const std::uint32_t last0 = cell_on(q.hi0, origin0_, cells0_);
  const std::uint32_t first1 = cell_on(q.lo1, origin1_, cells1_);
  const std::uint32_t last1 = cell_on(q.hi1, origin1_, cells1_);
  if (std::uint64_t{last0 - first0 + 1} * (last1 - first1 + 1) > boxes_.size()) {
    // A box over more cells than there are obstacles (a bullet's sweep across the world):
    // every box once, in their order.
    for (const Placed& p : boxes_) {
      if (overlaps(p.box, q)) found(p.box.id);
    }
    return;
  }
  for (const std::uint32_t k : spanning_) {
    if (overlaps(boxes_[k].box, q)) found(boxes_[k].box.id);
  }
  for (std::uint32_t c1 = first1; c1 <= last1; ++c1) {
    for (std::uint32_t c0 = first0; c0 <= last0; ++c0) {
      const std::uint32_t cell = c1 * cells0_ + c0;
      if (!occupied(cell)) continue;
      for (std::uint32_t r = cell_begin_[cell]; r < cell_begin_[cell + 1]; ++r) {
        const Placed& p = boxes_[refs_[r]];
        // A box in several of the query's cells is reported from the first of them.
        const bool first_shared =
            std::max(p.cell0, first0) == c0 && std::max(p.cell1, first1) == c1;
        if (first_shared && overlaps(p.box, q)) found(p.box.id);
      }
    }
  }
}

}  // namespace mink
