#include "output_files.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>

#include "mink/render/render_error.hpp"

namespace mink::cli {

namespace {

[[noreturn]] void fail(std::string_view what, const std::filesystem::path& file, int error) {
  std::string message = "cannot write " + std::string(what) + " '" + file.string() + "'";
  if (error != 0) message += ": " + std::string(std::strerror(error));
  throw OutputError(message);
}

}  // namespace

void make_directories(const std::filesystem::path& directory, std::string_view what) {
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  // create_directories reports no error when the path exists as a regular file.
  if (error || !std::filesystem::is_directory(directory)) {
    throw OutputError("cannot create the directory '" + directory.string() + "' for " +
                      std::string(what) + ": " +
                      (error ? error.message() : std::string("a file of that name exists")));
  }
}

std::ofstream open_output_file(const std::filesystem::path& file, std::string_view what) {
  if (file.has_parent_path()) make_directories(file.parent_path(), what);
  errno = 0;
  std::ofstream out(file, std::ios::binary);
  if (!out) fail(what, file, errno);
  return out;
}

void close_output_file(std::ofstream& out, const std::filesystem::path& file,
                       std::string_view what) {
  errno = 0;
  out.close();
  if (!out) fail(what, file, errno);
}

void write_file_atomically(const std::filesystem::path& file, std::span<const std::uint8_t> bytes,
                           std::string_view what) {
  std::filesystem::path temporary = file;
  temporary += ".tmp-" + std::to_string(::getpid());
  std::ofstream out = open_output_file(temporary, what);
  out.write(reinterpret_cast<const char*>(bytes.data()),
            static_cast<std::streamsize>(bytes.size()));
  try {
    close_output_file(out, temporary, what);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw;
  }
  std::error_code error;
  std::filesystem::rename(temporary, file, error);
  if (error) {
    std::filesystem::remove(temporary, error);
    fail(what, file, 0);
  }
}

}  // namespace mink::cli
