#pragma once

#include <cstddef>
#include <fstream>
#include <istream>
#include <string>
#include <string_view>
#include <vector>

#include "mink/error.hpp"
#include "mink/geometry/types.hpp"

namespace mink::cli {

// A line of point input that is not "x y" (or "x,y"), or holds a non-finite value.
class ParseError : public Error {
 public:
  ParseError(std::size_t line, const std::string& problem)
      : Error("line " + std::to_string(line) + ": " + problem), line_(line) {}
  std::size_t line() const noexcept { return line_; }

 private:
  std::size_t line_;
};

// One point per line: two numbers separated by spaces, tabs or one comma (spaces around it are
// fine). Blank lines and lines starting with '#' are skipped. Numbers are read exactly (the
// nearest double), in any locale.
std::vector<Vec2> read_points(std::istream& input);

// The input a command reads: `standard_input` for "-", otherwise the file `path`, opened into
// `file`. Throws InvalidArgumentError "cannot open 'PATH'" when it cannot be opened.
std::istream& open_input(const std::string& path, std::istream& standard_input,
                         std::ifstream& file);

// Parses one line; returns false for a blank or comment line. Throws ParseError otherwise.
bool parse_point_line(std::string_view line, std::size_t line_number, Vec2& point);

}  // namespace mink::cli
