#include "mink/render/sdl_window.hpp"

#include <SDL.h>

#include <string>

#include "mink/error.hpp"
#include "mink/render/render_error.hpp"

namespace mink {

namespace {

[[noreturn]] void fail(const std::string& step) {
  throw GlContextError("sdl2 window: " + step + ": " + SDL_GetError());
}

}  // namespace

SdlWindow::SdlWindow(const std::string& title, int width, int height, bool resizable) {
  detail::require_frame_size(width, height);
  // SDL counts its initialisations, so every window may ask and release its own.
  if (SDL_InitSubSystem(SDL_INIT_VIDEO) != 0) fail("no video (is there a display?)");
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 3);
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 3);
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, SDL_GL_CONTEXT_PROFILE_CORE);
  SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
  SDL_GL_SetAttribute(SDL_GL_DEPTH_SIZE, 0);
  Uint32 flags = SDL_WINDOW_OPENGL | SDL_WINDOW_ALLOW_HIGHDPI;
  if (resizable) flags |= SDL_WINDOW_RESIZABLE;
  window_ = SDL_CreateWindow(title.c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, width,
                             height, flags);
  if (window_ == nullptr) {
    const std::string error = SDL_GetError();
    SDL_QuitSubSystem(SDL_INIT_VIDEO);
    throw GlContextError("sdl2 window: cannot create the window: " + error);
  }
  context_ = SDL_GL_CreateContext(window_);
  if (context_ == nullptr) {
    const std::string error = SDL_GetError();
    SDL_DestroyWindow(window_);
    SDL_QuitSubSystem(SDL_INIT_VIDEO);
    throw GlContextError("sdl2 window: no OpenGL 3.3 core context: " + error);
  }
  // Swap on the display's refresh when it allows, else as fast as frames come.
  if (SDL_GL_SetSwapInterval(1) != 0) SDL_GL_SetSwapInterval(0);
}

SdlWindow::~SdlWindow() {
  SDL_GL_DeleteContext(static_cast<SDL_GLContext>(context_));
  SDL_DestroyWindow(window_);
  SDL_QuitSubSystem(SDL_INIT_VIDEO);
}

void SdlWindow::make_current() {
  if (SDL_GL_MakeCurrent(window_, static_cast<SDL_GLContext>(context_)) != 0) {
    fail("cannot make the context current");
  }
}

void* SdlWindow::proc_address(const char* name) const {
  return SDL_GL_GetProcAddress(name);
}

void SdlWindow::present() {
  SDL_GL_SwapWindow(window_);
}

void SdlWindow::push(const ScriptEvent& event) {
  SDL_Event sdl{};
  const Uint32 window_id = SDL_GetWindowID(window_);
  switch (event.kind) {
    case ScriptEvent::Kind::key: {
      const SDL_Keycode key = SDL_GetKeyFromName(event.key.c_str());
      if (key == SDLK_UNKNOWN) {
        throw InvalidArgumentError("line " + std::to_string(event.line) + ": SDL knows no key '" +
                                   event.key + "'");
      }
      for (const Uint32 type : {SDL_KEYDOWN, SDL_KEYUP}) {
        sdl = SDL_Event{};
        sdl.key.type = type;
        sdl.key.windowID = window_id;
        sdl.key.state = type == SDL_KEYDOWN ? SDL_PRESSED : SDL_RELEASED;
        sdl.key.keysym.sym = key;
        sdl.key.keysym.scancode = SDL_GetScancodeFromKey(key);
        SDL_PushEvent(&sdl);
      }
      return;
    }
    case ScriptEvent::Kind::mouse_down:
    case ScriptEvent::Kind::mouse_up: {
      const bool down = event.kind == ScriptEvent::Kind::mouse_down;
      sdl.button.type = down ? SDL_MOUSEBUTTONDOWN : SDL_MOUSEBUTTONUP;
      sdl.button.windowID = window_id;
      sdl.button.button = static_cast<Uint8>(event.button);
      sdl.button.state = down ? SDL_PRESSED : SDL_RELEASED;
      sdl.button.clicks = 1;
      sdl.button.x = event.x;
      sdl.button.y = event.y;
      SDL_PushEvent(&sdl);
      return;
    }
    case ScriptEvent::Kind::mouse_move:
      sdl.motion.type = SDL_MOUSEMOTION;
      sdl.motion.windowID = window_id;
      sdl.motion.x = event.x;
      sdl.motion.y = event.y;
      SDL_PushEvent(&sdl);
      return;
    case ScriptEvent::Kind::screenshot:
    case ScriptEvent::Kind::quit:
      return;
  }
}

int SdlWindow::width() const {
  int w = 0;
  int h = 0;
  SDL_GL_GetDrawableSize(window_, &w, &h);
  return w;
}

int SdlWindow::height() const {
  int w = 0;
  int h = 0;
  SDL_GL_GetDrawableSize(window_, &w, &h);
  return h;
}

}  // namespace mink
