#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace mink::cli {

// Breaks `text` into lines of at most `columns` characters, only where `gap` separates two
// entries (a longer entry stays whole); the gap is dropped at a break and kept elsewhere.
// Existing line breaks are kept. `gap` must not be empty.
std::string wrap(std::string_view text, std::size_t columns, std::string_view gap = " ");

}  // namespace mink::cli
