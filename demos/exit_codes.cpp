#include "exit_codes.hpp"

#include <ostream>

#include "mink/error.hpp"
#include "point_reader.hpp"

namespace mink::cli {

int report_error(const std::exception& error, std::ostream& err) {
  err << "mink: " << error.what() << '\n';
  if (dynamic_cast<const DegenerateInputError*>(&error) != nullptr) return kDegenerate;
  if (dynamic_cast<const Error*>(&error) != nullptr) return kBadInput;
  return kInternalError;
}

}  // namespace mink::cli
