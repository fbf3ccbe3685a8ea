#pragma once

#include <string>

#include "mink/engine/world.hpp"
#include "mink/render/camera.hpp"
#include "mink/render/renderer.hpp"

namespace mink::cli {

// The box a run's camera shows: every shape's box at the start, and for a spinning kinematic
// body the circle its shapes sweep, so a turning drum stays in frame.
void scene_bounds(const World& world, Vec2& lower, Vec2& upper);

// Kinetic energy of every body: translation of the centre of mass plus rotation about it.
Real kinetic_energy(const World& world);

// One frame: the world through World::draw, then `overlay` at the top-left corner.
void draw_world_frame(Renderer& renderer, const World& world, const std::string& overlay);

// "WxH" with both even (video needs even sizes) and in 64..8192; throws InvalidArgumentError.
void parse_frame_size(const std::string& text, int& width, int& height);

}  // namespace mink::cli
