// How a missing GL library or extension is reported: the step that checks for OSMesa's and
// EGL's libraries and extensions, which the contexts use.

#include "dynamic_library.hpp"

#include <gtest/gtest.h>

#include "mink/render/render_error.hpp"

namespace {

TEST(DynamicLibrary, AMissingLibraryIsAGlContextErrorNamingEveryCandidate) {
  try {
    mink::detail::DynamicLibrary library({"libmink-absent.so.8", "libmink-absent.so"},
                                         "osmesa backend");
    FAIL() << "opened a library that does not exist";
  } catch (const mink::GlContextError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("osmesa backend"), std::string::npos) << message;
    EXPECT_NE(message.find("libmink-absent.so.8, libmink-absent.so"), std::string::npos) << message;
  }
}

TEST(DynamicLibrary, AMissingSymbolIsAGlContextErrorNamingIt) {
  const mink::detail::DynamicLibrary library({"libEGL.so.1"}, "egl backend");
  EXPECT_NE(library.symbol("eglGetProcAddress"), nullptr);
  try {
    library.symbol("eglNoSuchFunction");
    FAIL() << "found a symbol that does not exist";
  } catch (const mink::GlContextError& error) {
    EXPECT_NE(std::string(error.what()).find("eglNoSuchFunction"), std::string::npos);
  }
}

TEST(DynamicLibrary, ExtensionsMatchWholeNamesOnly) {
  const char* list = "EGL_KHR_surfaceless_context EGL_MESA_platform_surfaceless EGL_KHR_x";
  EXPECT_TRUE(mink::detail::has_extension(list, "EGL_MESA_platform_surfaceless"));
  EXPECT_TRUE(mink::detail::has_extension(list, "EGL_KHR_x"));
  EXPECT_FALSE(mink::detail::has_extension(list, "EGL_KHR_surfaceless"));
  EXPECT_FALSE(mink::detail::has_extension(list, "EGL_MESA_platform"));
  EXPECT_FALSE(mink::detail::has_extension(nullptr, "EGL_KHR_x"));
  EXPECT_FALSE(mink::detail::has_extension("", "EGL_KHR_x"));
}

}  // namespace
