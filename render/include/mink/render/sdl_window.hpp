#pragma once

#include <string>

#include "mink/render/gl_context.hpp"
#include "mink/render/input_script.hpp"

struct SDL_Window;

namespace mink {

/// An SDL2 window with an OpenGL 3.3 core context: the interactive counterpart of the
/// offscreen contexts, drawn by the same Renderer (frames are copied to the window and swapped
/// on Renderer::end_frame). Needs a display; under Xvfb it runs headless too. Link
/// mink::render_window.
class SdlWindow final : public GlContext {
 public:
  /// @brief Opens a window of width x height pixels with a current GL 3.3 core context.
  /// @throws InvalidArgumentError for a size outside 1..16384
  /// @throws GlContextError (with SDL's message) when SDL, the window or the GL 3.3 core context
  /// cannot be made
  SdlWindow(const std::string& title, int width, int height, bool resizable = true);
  ~SdlWindow() override;

  /// @name GlContext
  /// @{
  void make_current() override;
  void* proc_address(const char* name) const override;
  bool offscreen() const override { return false; }
  /// @brief Swaps the window's buffers.
  void present() override;
  /// @brief Current drawable width in pixels (changes on resize).
  int width() const override;
  /// @brief Current drawable height in pixels.
  int height() const override;
  const char* name() const override { return "sdl2"; }
  /// @}

  /// @brief The SDL window, for event handling and titles.
  SDL_Window* handle() const { return window_; }
  /// Queues the SDL events a person's input would make (a key press and release, a mouse
  /// button or motion at a pixel of this window), so scripted runs go through the same event
  /// handling. Screenshot and quit events are the caller's to act on and push nothing. Throws
  /// InvalidArgumentError for a key name SDL does not know.
  void push(const ScriptEvent& event);

 private:
  SDL_Window* window_ = nullptr;
  void* context_ = nullptr;  // SDL_GLContext
};

}  // namespace mink
