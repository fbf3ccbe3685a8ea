#pragma once

#include <memory>

#include "mink/render/gl_context.hpp"

namespace mink::detail {

// OpenGL 3.3 core through EGL on Mesa's surfaceless platform (EGL_MESA_platform_surfaceless),
// with no surface at all: the renderer draws into its own framebuffer object.
std::unique_ptr<GlContext> make_egl_context(int width, int height);

}  // namespace mink::detail
