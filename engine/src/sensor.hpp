#pragma once

#include <cstdint>
#include <vector>

#include "mink/engine/ids.hpp"

namespace mink::detail {

// A sensor's visitors as of the last step, sorted by slot, so the next step's set can be
// compared in one merge and events come out in a fixed order.
struct SensorState {
  std::uint32_t shape = 0;
  std::vector<ShapeId> visitors;
};

}  // namespace mink::detail
