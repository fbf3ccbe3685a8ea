#include "egl_context.hpp"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <string>

#include "dynamic_library.hpp"
#include "mink/render/render_error.hpp"

namespace mink::detail {

namespace {

constexpr const char* kStep = "egl backend: ";

struct EglApi {
  DynamicLibrary library{{"libEGL.so.1", "libEGL.so"}, "egl backend"};
  decltype(&eglGetProcAddress) proc_address =
      library.function<decltype(&eglGetProcAddress)>("eglGetProcAddress");
  decltype(&eglQueryString) query_string =
      library.function<decltype(&eglQueryString)>("eglQueryString");
  decltype(&eglInitialize) initialize = library.function<decltype(&eglInitialize)>("eglInitialize");
  decltype(&eglBindAPI) bind_api = library.function<decltype(&eglBindAPI)>("eglBindAPI");
  decltype(&eglChooseConfig) choose_config =
      library.function<decltype(&eglChooseConfig)>("eglChooseConfig");
  decltype(&eglCreateContext) create_context =
      library.function<decltype(&eglCreateContext)>("eglCreateContext");
  decltype(&eglMakeCurrent) make_current =
      library.function<decltype(&eglMakeCurrent)>("eglMakeCurrent");
  decltype(&eglDestroyContext) destroy_context =
      library.function<decltype(&eglDestroyContext)>("eglDestroyContext");
  decltype(&eglGetError) get_error = library.function<decltype(&eglGetError)>("eglGetError");
};

const EglApi& egl_api() {
  static const EglApi api;
  return api;
}

std::string egl_error(const EglApi& api) {
  char code[16];
  std::snprintf(code, sizeof code, "0x%04X", static_cast<unsigned>(api.get_error()));
  return std::string(" (EGL error ") + code + ")";
}

class EglContext final : public GlContext {
 public:
  EglContext(int width, int height) : api_(egl_api()), width_(width), height_(height) {
    const char* client_extensions = api_.query_string(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!has_extension(client_extensions, "EGL_MESA_platform_surfaceless")) {
      throw GlContextError(std::string(kStep) + "EGL_MESA_platform_surfaceless is not offered");
    }
    const auto get_platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        api_.proc_address("eglGetPlatformDisplayEXT"));
    if (get_platform_display == nullptr) {
      throw GlContextError(std::string(kStep) + "eglGetPlatformDisplayEXT is missing");
    }
    display_ = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display_ == EGL_NO_DISPLAY) {
      throw GlContextError(std::string(kStep) + "no surfaceless display" + egl_error(api_));
    }
    // Initialising an initialised display is a no-op, so contexts can share the display.
    EGLint major = 0;
    EGLint minor = 0;
    if (!api_.initialize(display_, &major, &minor)) {
      throw GlContextError(std::string(kStep) + "eglInitialize failed" + egl_error(api_));
    }
    const char* display_extensions = api_.query_string(display_, EGL_EXTENSIONS);
    if (!has_extension(display_extensions, "EGL_KHR_surfaceless_context")) {
      throw GlContextError(std::string(kStep) + "EGL_KHR_surfaceless_context is not offered");
    }
    if (!api_.bind_api(EGL_OPENGL_API)) {
      throw GlContextError(std::string(kStep) + "desktop OpenGL is not offered" + egl_error(api_));
    }
    EGLConfig config = EGL_NO_CONFIG_KHR;
    if (!has_extension(display_extensions, "EGL_KHR_no_config_context")) {
      const EGLint config_attributes[] = {EGL_SURFACE_TYPE, 0, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                                          EGL_NONE};
      EGLint found = 0;
      if (!api_.choose_config(display_, config_attributes, &config, 1, &found) || found < 1) {
        throw GlContextError(std::string(kStep) + "no OpenGL config" + egl_error(api_));
      }
    }
    const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                         3,
                                         EGL_CONTEXT_MINOR_VERSION,
                                         3,
                                         EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                         EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                         EGL_NONE};
    context_ = api_.create_context(display_, config, EGL_NO_CONTEXT, context_attributes);
    if (context_ == EGL_NO_CONTEXT) {
      throw GlContextError(std::string(kStep) + "no OpenGL 3.3 core context" + egl_error(api_));
    }
    try {
      make_current();
    } catch (...) {
      api_.destroy_context(display_, context_);
      throw;
    }
  }
  ~EglContext() override {
    api_.make_current(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    api_.destroy_context(display_, context_);
  }

  void make_current() override {
    if (!api_.make_current(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
      throw GlContextError(std::string(kStep) + "eglMakeCurrent failed" + egl_error(api_));
    }
  }
  void* proc_address(const char* name) const override {
    return reinterpret_cast<void*>(api_.proc_address(name));
  }
  bool offscreen() const override { return true; }
  int width() const override { return width_; }
  int height() const override { return height_; }
  const char* name() const override { return "egl"; }

 private:
  const EglApi& api_;
  int width_;
  int height_;
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<GlContext> make_egl_context(int width, int height) {
  return std::make_unique<EglContext>(width, height);
}

}  // namespace mink::detail
