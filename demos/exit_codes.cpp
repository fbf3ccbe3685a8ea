#include "exit_codes.hpp"

#include <iostream>

#include "mink/error.hpp"
#include "point_reader.hpp"

namespace mink::cli {

int report_error(const std::exception& error) {
  std::cerr << "mink: " << error.what() << '\n';
  if (dynamic_cast<const DegenerateInputError*>(&error) != nullptr) return kDegenerate;
  if (dynamic_cast<const Error*>(&error) != nullptr) return kBadInput;
  return kInternalError;
}

}  // namespace mink::cli
