#include "text_wrap.hpp"

#include <algorithm>

namespace mink::cli {

std::string wrap(std::string_view text, std::size_t columns, std::string_view gap) {
  std::string wrapped;
  std::size_t line_length = 0;
  std::size_t begin = 0;
  while (begin <= text.size()) {
    const std::size_t end = std::min({text.find(gap, begin), text.find('\n', begin), text.size()});
    const std::string_view entry = text.substr(begin, end - begin);
    if (line_length > 0 && line_length + gap.size() + entry.size() > columns) {
      wrapped += '\n';
      line_length = 0;
    } else if (line_length > 0) {
      wrapped += gap;
      line_length += gap.size();
    }
    wrapped += entry;
    line_length += entry.size();
    if (end < text.size() && text[end] == '\n') {
      wrapped += '\n';
      line_length = 0;
      begin = end + 1;
    } else {
      begin = end + gap.size();
    }
  }
  return wrapped;
}

}  // namespace mink::cli
