#pragma once

#include <string>
#include <string_view>

#include "mink/engine/world.hpp"
#include "mink/render/camera.hpp"
#include "mink/render/renderer.hpp"

namespace mink::cli {

// Kinetic energy of every body: translation of the centre of mass plus rotation about it.
Real kinetic_energy(const World& world);

struct FrameSizeRules {
  bool require_even = true;               // video needs even sizes; PNG figures do not
  std::string_view example = "1280x720";  // shown when the text is not WIDTHxHEIGHT at all
};

// "WxH" with both in 64..8192 (and even, unless `rules` says otherwise); throws
// InvalidArgumentError.
void parse_frame_size(const std::string& text, int& width, int& height,
                      const FrameSizeRules& rules = {});

}  // namespace mink::cli
