#include "point_reader.hpp"

#include <charconv>
#include <cmath>

namespace mink::cli {

namespace {

bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r';
}

void skip_blanks(std::string_view text, std::size_t& at) {
  while (at < text.size() && is_blank(text[at])) ++at;
}

Real parse_number(std::string_view text, std::size_t& at, std::size_t line_number,
                  const char* which) {
  const char* begin = text.data() + at;
  const char* end = text.data() + text.size();
  // from_chars takes no leading '+'; skip one, but never let "+-1" or "++1" through.
  if (begin + 1 < end && *begin == '+' && begin[1] != '-' && begin[1] != '+') ++begin;
  Real value = 0;
  const auto [stop, error] = std::from_chars(begin, end, value);
  if (error == std::errc::result_out_of_range) {
    throw ParseError(line_number, std::string(which) + " coordinate is out of range");
  }
  if (error != std::errc() || stop == begin) {
    std::size_t token_end = at;
    while (token_end < text.size() && !is_blank(text[token_end]) && text[token_end] != ',') {
      ++token_end;
    }
    const std::string token(text.substr(at, token_end - at));
    throw ParseError(line_number, token.empty() ? std::string("missing ") + which + " coordinate"
                                                : "'" + token + "' is not a number");
  }
  if (!std::isfinite(value)) {
    throw ParseError(line_number, std::string(which) + " coordinate is not finite");
  }
  at = static_cast<std::size_t>(stop - text.data());
  return value;
}

}  // namespace

bool parse_point_line(std::string_view line, std::size_t line_number, Vec2& point) {
  std::size_t at = 0;
  skip_blanks(line, at);
  if (at == line.size() || line[at] == '#') return false;
  const Real x = parse_number(line, at, line_number, "x");
  const std::size_t after_x = at;
  skip_blanks(line, at);
  if (at < line.size() && line[at] == ',') {
    ++at;
    skip_blanks(line, at);
  } else if (at == after_x && at < line.size()) {
    throw ParseError(line_number, "expected a space, tab or comma after x");
  }
  const Real y = parse_number(line, at, line_number, "y");
  skip_blanks(line, at);
  if (at != line.size()) {
    throw ParseError(line_number,
                     "unexpected '" + std::string(line.substr(at)) + "' after the two coordinates");
  }
  point = Vec2(x, y);
  return true;
}

std::vector<Vec2> read_points(std::istream& input) {
  std::vector<Vec2> points;
  std::string line;
  std::size_t line_number = 0;
  while (std::getline(input, line)) {
    ++line_number;
    Vec2 point;
    if (parse_point_line(line, line_number, point)) points.push_back(point);
  }
  return points;
}

std::istream& open_input(const std::string& path, std::istream& standard_input,
                         std::ifstream& file) {
  if (path == "-") return standard_input;
  file.open(path);
  if (!file) throw InvalidArgumentError("cannot open '" + path + "'");
  return file;
}

}  // namespace mink::cli
