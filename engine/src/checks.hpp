#pragma once

#include <cmath>
#include <cstdio>
#include <string>

#include "mink/error.hpp"
#include "mink/geometry/types.hpp"

namespace mink::detail {

// The argument checks of the World API: a failed one throws InvalidArgumentError with `what`.
inline void require(bool ok, const std::string& what) {
  if (!ok) throw InvalidArgumentError(what);
}

inline bool finite(const Vec2& v) {
  return std::isfinite(v.x()) && std::isfinite(v.y());
}

// `value` to all 17 significant digits: for messages about values too close to a limit to
// show in fewer.
inline std::string exact_number(Real value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

}  // namespace mink::detail
