#include "output_files.hpp"

#include <string>

namespace mink::cli {

void make_directories(const std::filesystem::path& directory, std::string_view what) {
  make_output_directory(directory, std::string(what));
}

}  // namespace mink::cli
