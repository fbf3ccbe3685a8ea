#pragma once

#include <filesystem>

#include "mink/render/image.hpp"

namespace mink {

/// @brief Writes an 8-bit RGB or RGBA PNG.
/// @throws FileWriteError naming the file when it cannot be written; written under a
/// temporary name and renamed when complete (OutputFile), so an earlier file survives a failure
/// @throws InvalidArgumentError for an empty or inconsistent image
void write_png(const std::filesystem::path& path, const Image& image);
/// @brief Reads any PNG libpng reads, converted to 8-bit RGBA.
/// @throws OutputError naming the file when it is missing or not a PNG.
Image read_png(const std::filesystem::path& path);

}  // namespace mink
