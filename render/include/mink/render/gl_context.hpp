#pragma once

#include <memory>

#include "mink/render/gl_backend.hpp"

namespace mink {

/// A current OpenGL 3.3 core context. The renderer draws through function pointers the
/// context resolves, so OSMesa, EGL and an SDL2 window can live in one program without their
/// GL libraries clashing.
class GlContext {
 public:
  virtual ~GlContext() = default;
  GlContext() = default;
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  /// @brief Makes this context current on the calling thread.
  virtual void make_current() = 0;
  /// @brief Address of a GL entry point, or null when the implementation lacks it.
  virtual void* proc_address(const char* name) const = 0;
  /// False for a window. The renderer always draws into its own framebuffer object of
  /// width() x height(); a window (offscreen() false) then gets each frame copied to its
  /// framebuffer 0 and present()ed.
  virtual bool offscreen() const = 0;
  /// @brief Shows the copied frame (swaps a window's buffers); nothing offscreen.
  virtual void present() {}
  /// @brief Drawable width in pixels, which for a window changes when it is resized.
  virtual int width() const = 0;
  /// @brief Drawable height in pixels, likewise.
  virtual int height() const = 0;
  /// @brief Short name of the backend for messages ("osmesa", "egl", "sdl2").
  virtual const char* name() const = 0;
};

/// @brief A headless GL 3.3 core context for frames of width x height pixels.
/// @throws InvalidArgumentError for a size outside 1..16384
/// @throws GlContextError, naming the backend and the step that failed, when the context
/// cannot be made
std::unique_ptr<GlContext> make_offscreen_context(GlBackend backend, int width, int height);

namespace detail {
/// @brief The size check every context applies.
/// @throws InvalidArgumentError for a size outside 1..16384.
void require_frame_size(int width, int height);
}  // namespace detail

}  // namespace mink
