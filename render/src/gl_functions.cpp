#include "gl_functions.hpp"

#include <string>

#include "mink/render/render_error.hpp"

namespace mink::detail {

GlFunctions::GlFunctions(const GlContext& context) {
  const auto load = [&context](auto& function, const char* name) {
    function =
        reinterpret_cast<std::remove_reference_t<decltype(function)>>(context.proc_address(name));
    if (function == nullptr) {
      throw GlContextError(std::string(context.name()) + ": GL entry point " + name +
                           " is missing");
    }
  };
#define MINK_GL_LOAD(type, name) load(name, "gl" #name);
  MINK_GL_FUNCTIONS(MINK_GL_LOAD)
#undef MINK_GL_LOAD
  GLint major = 0;
  GLint minor = 0;
  GetIntegerv(GL_MAJOR_VERSION, &major);
  GetIntegerv(GL_MINOR_VERSION, &minor);
  if (major < 3 || (major == 3 && minor < 3)) {
    const auto* version = reinterpret_cast<const char*>(GetString(GL_VERSION));
    throw GlContextError(std::string(context.name()) + ": OpenGL 3.3 core needed, got " +
                         (version != nullptr ? version : "no version string"));
  }
}

void GlFunctions::check(const char* step) const {
  const GLenum error = GetError();
  if (error != GL_NO_ERROR) {
    throw GlContextError(std::string(step) + " failed with GL error " + std::to_string(error));
  }
}

}  // namespace mink::detail
