#pragma once

#include <string_view>

#include "mink/engine/body_def.hpp"
#include "mink/engine/shape_def.hpp"

namespace mink::python {

/// @brief "static", "kinematic" or "dynamic", as to_string(BodyType) and scene files spell them.
/// @throws InvalidArgumentError naming anything else.
BodyType parse_body_type(std::string_view name);
/// @brief "polygon", "circle", "capsule", "segment" or "chain".
/// @throws InvalidArgumentError naming anything else.
ShapeType parse_shape_type(std::string_view name);

}  // namespace mink::python
