#pragma once

#include <cstdint>
#include <string_view>

#include "mink/engine/world.hpp"
#include "mink/render/renderer.hpp"

namespace mink {

/// @brief The box a camera shows a world in: every shape's box, and for a spinning kinematic
/// body the circle its shapes sweep, so a turning drum stays in frame. An empty world gives
/// [-10, 10] x [-10, 10].
void world_bounds(const World& world, Vec2& lower, Vec2& upper);

/// @brief What a headless run's frames show: shapes, contact points, sleep state.
inline constexpr std::uint32_t kRunFrameLayers =
    draw_shapes | draw_contact_points | draw_sleep_state;

/// @brief One frame of a headless run: the world through World::draw (the DrawLayer flags
/// `layers`) on a dark background, then `overlay` at the top-left corner (none when empty).
void draw_world_frame(Renderer& renderer, const World& world, std::string_view overlay,
                      std::uint32_t layers = kRunFrameLayers);

}  // namespace mink
