#pragma once

#include <span>
#include <string>
#include <string_view>

#include "mink/geometry/types.hpp"

namespace mink::cli {

// The answer `mink overlap` prints for one pair of point sets (world coordinates).
struct OverlapAnswer {
  bool overlap = false;
  Real distance = 0;   // >= 0, 0 when overlapping
  Real depth = 0;      // >= 0, 0 when apart
  Vec2 normal{0, 0};   // unit, from a towards b
  int iterations = 0;  // GJK iterations plus EPA expansions
};

// Hulls both point sets, then GJK distance and, when they overlap, EPA. Near touching (within
// 1e-9 of the coordinates' magnitude) the verdict is settled by the exact edge test, so it is
// right for every input, not just the comfortably apart or overlapping ones. Throws
// mink::Error subclasses for degenerate or non-finite point sets.
OverlapAnswer answer_overlap(std::span<const Vec2> a, std::span<const Vec2> b);

// One input line `{"a": [[x, y], ...], "b": [[x, y], ...]}` to its output line (no newline):
// the answer, or {"error": "line N: ..."} when the line is malformed or a point set is
// degenerate. Sets `ok` to false for an error line.
std::string overlap_line(std::string_view line, std::size_t line_number, bool& ok);

}  // namespace mink::cli
