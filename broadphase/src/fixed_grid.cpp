#include "mink/broadphase/fixed_grid.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace mink {

namespace {

// Cells on a side of the typical (median) obstacle's larger extent: it then covers one to
// four cells, and a query of a fast body's size about as many.
constexpr Real kCellFactor = 1.0;
// At most this many cells per obstacle in all: a world of a few tiny obstacles far apart
// gets larger cells rather than a grid mostly empty.
constexpr std::uint64_t kCellsPerBox = 4;
// An obstacle over more cells than this is looked at by every query instead (one huge floor
// among many small boxes would otherwise fill the grid).
constexpr std::uint64_t kMaxCellsOfABox = 16;

}  // namespace

void FixedGrid::clear() {
  boxes_.clear();
  cell_begin_.clear();
  occupied_.clear();
  columns_before_.clear();
  rows_before_.clear();
  refs_.clear();
  spanning_.clear();
  cells0_ = cells1_ = 0;
}

void FixedGrid::build(const std::vector<Box>& boxes) {
  clear();
  if (boxes.empty()) return;
  Real lo0 = boxes.front().lo0, hi0 = boxes.front().hi0;
  Real lo1 = boxes.front().lo1, hi1 = boxes.front().hi1;
  std::vector<Real> extents;
  extents.reserve(boxes.size());
  for (const Box& b : boxes) {
    lo0 = std::min(lo0, b.lo0);
    hi0 = std::max(hi0, b.hi0);
    lo1 = std::min(lo1, b.lo1);
    hi1 = std::max(hi1, b.hi1);
    extents.push_back(std::max(b.hi0 - b.lo0, b.hi1 - b.lo1));
  }
  const auto middle = extents.begin() + static_cast<std::ptrdiff_t>(extents.size() / 2);
  std::nth_element(extents.begin(), middle, extents.end());
  const Real span0 = hi0 - lo0, span1 = hi1 - lo1;
  // The typical extent, but no finer than a grid of kCellsPerBox cells per obstacle needs.
  const std::uint64_t most_cells = kCellsPerBox * boxes.size() + 4;
  Real cell = kCellFactor * *middle;
  const Real coarsest = std::sqrt(span0 * span1 / static_cast<Real>(most_cells));
  cell = std::max({cell, coarsest, std::max(span0, span1) / static_cast<Real>(most_cells)});
  if (!(cell > 0)) {
    // Every obstacle a point, all at one place: one cell.
    origin0_ = lo0;
    origin1_ = lo1;
    inverse_cell_ = 0;
    cells0_ = cells1_ = 1;
  } else {
    origin0_ = lo0;
    origin1_ = lo1;
    inverse_cell_ = 1 / cell;
    // One cell at least, whatever the boxes: a snapshot's broadphase is laid out before its
    // boxes are checked (and refused when upside down or not finite).
    const auto cells_over = [&](Real span) {
      const Real n = std::floor(span * inverse_cell_) + 1;
      if (!(n >= 1)) return std::uint32_t{1};
      return static_cast<std::uint32_t>(std::min<Real>(n, static_cast<Real>(most_cells)));
    };
    cells0_ = cells_over(span0);
    cells1_ = cells_over(span1);
    // Rounding may leave a few more than most_cells: fewer rows then.
    while (std::uint64_t{cells0_} * cells1_ > 2 * most_cells && cells1_ > 1) --cells1_;
  }

  boxes_.reserve(boxes.size());
  const std::size_t cell_count = std::size_t{cells0_} * cells1_;
  cell_begin_.assign(cell_count + 1, 0);
  for (const Box& b : boxes) {
    Placed p{b, cell_on(b.lo0, origin0_, cells0_), cell_on(b.lo1, origin1_, cells1_)};
    boxes_.push_back(p);
  }
  // Counting sort of the boxes' references by cell, each cell's in the boxes' order.
  const auto for_each_cell = [&](const Placed& p, auto&& visit) {
    const std::uint32_t last0 = cell_on(p.box.hi0, origin0_, cells0_);
    const std::uint32_t last1 = cell_on(p.box.hi1, origin1_, cells1_);
    for (std::uint32_t c1 = p.cell1; c1 <= last1; ++c1) {
      for (std::uint32_t c0 = p.cell0; c0 <= last0; ++c0) visit(c1 * cells0_ + c0);
    }
  };
  const auto spans_too_many = [&](const Placed& p) {
    const std::uint64_t along0 = cell_on(p.box.hi0, origin0_, cells0_) - p.cell0 + 1;
    const std::uint64_t along1 = cell_on(p.box.hi1, origin1_, cells1_) - p.cell1 + 1;
    return along0 * along1 > kMaxCellsOfABox;
  };
  for (std::uint32_t k = 0; k < boxes_.size(); ++k) {
    if (spans_too_many(boxes_[k])) {
      spanning_.push_back(k);
      continue;
    }
    for_each_cell(boxes_[k], [&](std::size_t cell) { ++cell_begin_[cell + 1]; });
  }
  occupied_.assign((cell_count + 63) / 64, 0);
  columns_before_.assign(std::size_t{cells0_} + 1, 0);
  rows_before_.assign(std::size_t{cells1_} + 1, 0);
  for (std::size_t c = 0; c < cell_count; ++c) {
    if (cell_begin_[c + 1] != 0) {
      occupied_[c >> 6] |= std::uint64_t{1} << (c & 63);
      columns_before_[c % cells0_ + 1] = 1;
      rows_before_[c / cells0_ + 1] = 1;
    }
    cell_begin_[c + 1] += cell_begin_[c];
  }
  std::partial_sum(columns_before_.begin(), columns_before_.end(), columns_before_.begin());
  std::partial_sum(rows_before_.begin(), rows_before_.end(), rows_before_.begin());
  refs_.resize(cell_begin_[cell_count]);
  std::vector<std::uint32_t> next(cell_begin_.begin(), cell_begin_.end() - 1);
  for (std::uint32_t k = 0; k < boxes_.size(); ++k) {
    if (spans_too_many(boxes_[k])) continue;
    for_each_cell(boxes_[k], [&](std::size_t cell) { refs_[next[cell]++] = k; });
  }
}

}  // namespace mink
