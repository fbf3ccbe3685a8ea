#pragma once

#include <memory>

#include "mink/render/gl_context.hpp"

namespace mink::detail {

// OpenGL 3.3 core through Mesa's OSMesa (libOSMesa.so.8, opened at run time).
std::unique_ptr<GlContext> make_osmesa_context(int width, int height);

}  // namespace mink::detail
