#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string_view>
#include <vector>

#include "mink/output_file.hpp"

namespace mink::cli {

// Files and directories the commands write. Each file is a mink::OutputFile: written under a
// temporary name and renamed when complete, so a command stopped part-way (killed, a full
// disk) never leaves a truncated output nor destroys an earlier file of that name. A failure
// is the environment's (a path through a regular file, no permission, a full disk), not the
// user's input: FileWriteError, which `mink` reports with exit code 5. `what` names the output
// in messages, e.g. "--stats file".

// Creates `directory` and its parents unless they exist.
void make_directories(const std::filesystem::path& directory, std::string_view what);

// Writes `bytes` to `file` through an OutputFile: whole or not at all.
void write_file_atomically(const std::filesystem::path& file, std::span<const std::uint8_t> bytes,
                           std::string_view what);

// What write_file_atomically wrote: the whole of `file`. Throws InvalidArgumentError naming
// `what` and the file when it cannot be read.
std::vector<std::uint8_t> read_file_bytes(const std::filesystem::path& file, std::string_view what);

}  // namespace mink::cli
