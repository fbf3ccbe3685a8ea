#include "mink/render/gl_backend.hpp"

#include <array>
#include <string>

#include "mink/error.hpp"

namespace mink {

namespace {
constexpr std::array<GlBackend, 2> kBackends = {GlBackend::osmesa, GlBackend::egl};
}

std::string_view to_string(GlBackend backend) noexcept {
  switch (backend) {
    case GlBackend::osmesa:
      return "osmesa";
    case GlBackend::egl:
      return "egl";
  }
  return "unknown";
}

GlBackend parse_gl_backend(std::string_view name) {
  for (GlBackend backend : kBackends) {
    if (to_string(backend) == name) return backend;
  }
  throw InvalidArgumentError("unknown GL backend '" + std::string(name) +
                             "' (expected osmesa or egl)");
}

std::span<const GlBackend> all_gl_backends() noexcept {
  return kBackends;
}

}  // namespace mink
