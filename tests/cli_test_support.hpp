#pragma once

// Shared by the tests of the `mink` commands: the command run in-process, and scratch files.
// Only the command's own header: no CGAL or GoogleTest, so any test target can use it.

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "commands.hpp"

namespace mink_test {

struct CliResult {
  int code;
  std::string out;
  std::string err;
};

// `mink ARGS...` in-process, reading `input` as its standard input.
inline CliResult run_cli(std::vector<std::string> args, const std::string& input = "") {
  args.insert(args.begin(), "mink");
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  std::istringstream in(input);
  std::ostringstream out;
  std::ostringstream err;
  const int code = mink::cli::run(static_cast<int>(argv.size()), argv.data(), {in, out, err});
  return {code, out.str(), err.str()};
}

// A fresh, empty directory under the system's temporary directory.
inline std::filesystem::path fresh_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("mink_command_test_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

}  // namespace mink_test
