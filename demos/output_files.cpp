#include "output_files.hpp"

#include <fstream>
#include <iterator>
#include <string>

#include "mink/error.hpp"

namespace mink::cli {

void make_directories(const std::filesystem::path& directory, std::string_view what) {
  make_output_directory(directory, std::string(what));
}

void write_file_atomically(const std::filesystem::path& file, std::span<const std::uint8_t> bytes,
                           std::string_view what) {
  OutputFile out(file, std::string(what));
  out.stream().write(reinterpret_cast<const char*>(bytes.data()),
                     static_cast<std::streamsize>(bytes.size()));
  out.commit();
}

std::vector<std::uint8_t> read_file_bytes(const std::filesystem::path& file,
                                          std::string_view what) {
  std::ifstream in(file, std::ios::binary);
  if (!in)
    throw InvalidArgumentError("cannot read " + std::string(what) + " '" + file.string() + "'");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace mink::cli
