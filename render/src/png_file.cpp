#include "mink/render/png_file.hpp"

#include <png.h>

#include <cstring>
#include <string>

#include "mink/error.hpp"
#include "mink/output_file.hpp"
#include "mink/render/render_error.hpp"

namespace mink {

// libpng's simplified API reports errors in the png_image instead of longjmp, which keeps
// C++ destructors safe.
void write_png(const std::filesystem::path& path, const Image& image) {
  if (image.width <= 0 || image.height <= 0 || (image.channels != 3 && image.channels != 4) ||
      image.pixels.size() != static_cast<std::size_t>(image.width) *
                                 static_cast<std::size_t>(image.height) *
                                 static_cast<std::size_t>(image.channels)) {
    throw InvalidArgumentError("cannot write " + path.string() + ": image of " +
                               std::to_string(image.width) + " x " + std::to_string(image.height) +
                               " x " + std::to_string(image.channels) + " with " +
                               std::to_string(image.pixels.size()) + " bytes is inconsistent");
  }
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  png.width = static_cast<png_uint_32>(image.width);
  png.height = static_cast<png_uint_32>(image.height);
  png.format = image.channels == 4 ? PNG_FORMAT_RGBA : PNG_FORMAT_RGB;
  OutputFile out(path, "PNG file", false);
  if (!png_image_write_to_file(&png, out.writing_path().c_str(), 0, image.pixels.data(), 0,
                               nullptr)) {
    const std::string reason = png.message;
    png_image_free(&png);
    throw FileWriteError("cannot write " + path.string() + ": " + reason);
  }
  out.commit();
}

Image read_png(const std::filesystem::path& path) {
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&png, path.c_str())) {
    const std::string reason = png.message;
    png_image_free(&png);
    throw OutputError("cannot read " + path.string() + ": " + reason);
  }
  png.format = PNG_FORMAT_RGBA;
  Image image(static_cast<int>(png.width), static_cast<int>(png.height), 4);
  if (!png_image_finish_read(&png, nullptr, image.pixels.data(), 0, nullptr)) {
    const std::string reason = png.message;
    png_image_free(&png);
    throw OutputError("cannot read " + path.string() + ": " + reason);
  }
  return image;
}

}  // namespace mink
