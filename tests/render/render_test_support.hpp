#pragma once

// Shared by the render tests: a headless frame on either backend and pixel helpers.

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <memory>
#include <string>

#include "mink/render/gl_context.hpp"
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

inline Rgba to_rgba(mink::Color c) {
  const auto channel = [](float v) { return static_cast<std::uint8_t>(v * 255.0f + 0.5f); };
  return {channel(c.r), channel(c.g), channel(c.b), channel(c.a)};
}

inline std::string describe(const Rgba& p) {
  return "(" + std::to_string(p[0]) + ", " + std::to_string(p[1]) + ", " + std::to_string(p[2]) +
         ", " + std::to_string(p[3]) + ")";
}

inline std::string backend_name(const testing::TestParamInfo<mink::GlBackend>& info) {
  return std::string(mink::to_string(info.param));
}

}  // namespace mink_test
