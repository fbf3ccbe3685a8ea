#pragma once

#include <span>
#include <string_view>

namespace mink {

/// Where headless frames are drawn. OSMesa is the default; EGL surfaceless is for systems
/// whose Mesa no longer ships OSMesa (removed in Mesa 25.1).
enum class GlBackend { osmesa, egl };

/// @brief The backend's name: "osmesa" or "egl".
std::string_view to_string(GlBackend backend) noexcept;
/// @brief Accepts "osmesa" and "egl".
/// @throws InvalidArgumentError naming anything else.
GlBackend parse_gl_backend(std::string_view name);
/// @brief Every backend, in declaration order.
std::span<const GlBackend> all_gl_backends() noexcept;

}  // namespace mink
