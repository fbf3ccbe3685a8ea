#pragma once

#include <cstdint>

#include "mink/engine/scene.hpp"

namespace mink::detail {

/// Appends Box2D v3's human (its shared/human.c at scale 1) standing with its feet at `feet`:
/// eleven capsule bodies (the lower legs with a rounded foot polygon each), each pinned to its
/// parent by a limited revolute joint with a 5 Hz spring towards standing and a weak motor at
/// speed 0 for joint friction. Its shapes are category 2 and collide with categories 1 and 2,
/// the feet with category 1 only; the negative `group` keeps its own parts apart.
void add_human(SceneDef& scene, const Vec2& feet, std::int32_t group);

}  // namespace mink::detail
