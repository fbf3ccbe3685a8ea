#pragma once

#include <optional>
#include <string_view>

#include "mink/engine/scene.hpp"

namespace mink::detail {

/// Box2D v3's benchmark scene of that name (see benchmark_suite), or nothing for a name
/// outside the suite.
std::optional<SceneDef> benchmark_scene(std::string_view name);

}  // namespace mink::detail
