#pragma once

#include <string>

#include "mink/error.hpp"

namespace mink {

/// A BodyId or ShapeId used after its object was destroyed (or never issued by this world).
/// The message names the id.
class StaleIdError : public Error {
 public:
  using Error::Error;
};

}  // namespace mink
