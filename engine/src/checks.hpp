#pragma once

#include <cmath>
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

}  // namespace mink::detail
