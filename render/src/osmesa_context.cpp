#include "osmesa_context.hpp"

#include <GL/osmesa.h>

#include <string>
#include <vector>

#include "dynamic_library.hpp"
#include "mink/render/render_error.hpp"

namespace mink::detail {

namespace {

struct OsMesaApi {
  DynamicLibrary library{{"libOSMesa.so.8", "libOSMesa.so.6", "libOSMesa.so"},
                         "osmesa backend (OSMesa is gone from Mesa 25.1 on; try --gl egl)"};
  decltype(&OSMesaCreateContextAttribs) create =
      library.function<decltype(&OSMesaCreateContextAttribs)>("OSMesaCreateContextAttribs");
  decltype(&OSMesaMakeCurrent) make_current =
      library.function<decltype(&OSMesaMakeCurrent)>("OSMesaMakeCurrent");
  decltype(&OSMesaDestroyContext) destroy =
      library.function<decltype(&OSMesaDestroyContext)>("OSMesaDestroyContext");
  decltype(&OSMesaGetProcAddress) proc_address =
      library.function<decltype(&OSMesaGetProcAddress)>("OSMesaGetProcAddress");
};

const OsMesaApi& osmesa_api() {
  static const OsMesaApi api;
  return api;
}

class OsMesaContext final : public GlContext {
 public:
  OsMesaContext(int width, int height)
      : api_(osmesa_api()),
        width_(width),
        height_(height),
        buffer_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4) {
    // No depth, stencil or accumulation buffer: the renderer paints in call order.
    const int attributes[] = {OSMESA_FORMAT,
                              OSMESA_RGBA,
                              OSMESA_DEPTH_BITS,
                              0,
                              OSMESA_STENCIL_BITS,
                              0,
                              OSMESA_ACCUM_BITS,
                              0,
                              OSMESA_PROFILE,
                              OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION,
                              3,
                              OSMESA_CONTEXT_MINOR_VERSION,
                              3,
                              0};
    context_ = api_.create(attributes, nullptr);
    if (context_ == nullptr) {
      throw GlContextError("osmesa backend: OSMesaCreateContextAttribs found no OpenGL 3.3 core");
    }
    try {
      make_current();
    } catch (...) {
      api_.destroy(context_);
      throw;
    }
  }
  ~OsMesaContext() override { api_.destroy(context_); }

  void make_current() override {
    if (!api_.make_current(context_, buffer_.data(), GL_UNSIGNED_BYTE, width_, height_)) {
      throw GlContextError("osmesa backend: OSMesaMakeCurrent failed for " +
                           std::to_string(width_) + " x " + std::to_string(height_));
    }
  }
  void* proc_address(const char* name) const override {
    return reinterpret_cast<void*>(api_.proc_address(name));
  }
  bool offscreen() const override { return true; }
  int width() const override { return width_; }
  int height() const override { return height_; }
  const char* name() const override { return "osmesa"; }

 private:
  const OsMesaApi& api_;
  int width_;
  int height_;
  std::vector<unsigned char> buffer_;  // OSMesa's own colour buffer; frames go to an FBO
  OSMesaContext context_ = nullptr;
};

}  // namespace

std::unique_ptr<GlContext> make_osmesa_context(int width, int height) {
  return std::make_unique<OsMesaContext>(width, height);
}

}  // namespace mink::detail
