#pragma once

#include <string>

#include "mink/error.hpp"

namespace mink {

/// A GL context could not be made or a GL call failed (library missing, no such platform,
/// version too old, shader or framebuffer incomplete). The message names the backend and step.
class GlContextError : public Error {
 public:
  using Error::Error;
};

}  // namespace mink
