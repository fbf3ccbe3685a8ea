#pragma once

// Shared by the render tests: a headless frame on either backend, pixel helpers and scratch
// file paths.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "mink/render/gl_context.hpp"
#include "mink/render/image.hpp"
#include "mink/render/renderer.hpp"

namespace mink_test {

struct Headless {
  std::unique_ptr<mink::GlContext> context;
  std::unique_ptr<mink::Renderer> renderer;

  Headless(mink::GlBackend backend, int width, int height, mink::RendererOptions options = {})
      : context(mink::make_offscreen_context(backend, width, height)),
        renderer(std::make_unique<mink::Renderer>(*context, options)) {}
  ~Headless() { renderer.reset(); }  // GL objects go before their context
};

using Rgba = std::array<std::uint8_t, 4>;
using Rgb = std::array<std::uint8_t, 3>;

inline Rgba to_rgba(mink::Color c) {
  const auto channel = [](float v) { return static_cast<std::uint8_t>(v * 255.0f + 0.5f); };
  return {channel(c.r), channel(c.g), channel(c.b), channel(c.a)};
}

inline std::string describe(const Rgba& p) {
  return "(" + std::to_string(p[0]) + ", " + std::to_string(p[1]) + ", " + std::to_string(p[2]) +
         ", " + std::to_string(p[3]) + ")";
}

// Columns [x0, x1) of rows [y0, y1).
struct PixelRect {
  int x0;
  int y0;
  int x1;
  int y1;
};

// Pixels in `rect` of exactly `colour`: all four channels for an Rgba, the colour channels
// alone (any alpha) for an Rgb.
template <std::size_t Channels>
int count_pixels(const mink::Image& image, const std::array<std::uint8_t, Channels>& colour,
                 PixelRect rect) {
  int found = 0;
  for (int y = rect.y0; y < rect.y1; ++y) {
    for (int x = rect.x0; x < rect.x1; ++x) {
      const Rgba p = image.at(x, y);
      found += std::equal(colour.begin(), colour.end(), p.begin());
    }
  }
  return found;
}

// The same over the whole image.
template <std::size_t Channels>
int count_pixels(const mink::Image& image, const std::array<std::uint8_t, Channels>& colour) {
  return count_pixels(image, colour, {0, 0, image.width, image.height});
}

// `name` in GoogleTest's temporary directory.
inline std::filesystem::path temp_path(const std::string& name) {
  return std::filesystem::path(testing::TempDir()) / name;
}

inline std::string backend_name(const testing::TestParamInfo<mink::GlBackend>& info) {
  return std::string(mink::to_string(info.param));
}

}  // namespace mink_test
