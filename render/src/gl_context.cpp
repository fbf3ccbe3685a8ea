#include "mink/render/gl_context.hpp"

#include <string>

#include "egl_context.hpp"
#include "mink/error.hpp"
#include "osmesa_context.hpp"

namespace mink {

namespace detail {

void require_frame_size(int width, int height) {
  constexpr int kLargest = 16384;
  if (width < 1 || height < 1 || width > kLargest || height > kLargest) {
    throw InvalidArgumentError("frame size " + std::to_string(width) + " x " +
                               std::to_string(height) + " is outside 1..16384");
  }
}

}  // namespace detail

std::unique_ptr<GlContext> make_offscreen_context(GlBackend backend, int width, int height) {
  detail::require_frame_size(width, height);
  switch (backend) {
    case GlBackend::osmesa:
      return detail::make_osmesa_context(width, height);
    case GlBackend::egl:
      return detail::make_egl_context(width, height);
  }
  throw InvalidArgumentError("unknown GL backend");
}

}  // namespace mink
