#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <span>
#include <string_view>

namespace mink::cli {

// Files and directories the commands write. A failure here is the environment's (a path
// through a regular file, no permission, a full disk), not the user's input, so these throw
// OutputError, which `mink` reports with exit code 4. `what` names the output in messages,
// e.g. "--stats file".

// Creates `directory` and its parents unless they exist.
void make_directories(const std::filesystem::path& directory, std::string_view what);

// Opens `file` for writing (text, truncated), creating its parent directories first.
std::ofstream open_output_file(const std::filesystem::path& file, std::string_view what);

// Closes `out` and throws when anything written to it was lost.
void close_output_file(std::ofstream& out, const std::filesystem::path& file,
                       std::string_view what);

// Writes `bytes` to `file` whole or not at all: into a temporary name beside it, renamed over
// `file` once complete, so an interrupted run never leaves half a file under the real name.
void write_file_atomically(const std::filesystem::path& file, std::span<const std::uint8_t> bytes,
                           std::string_view what);

}  // namespace mink::cli
