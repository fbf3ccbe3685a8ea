#include "exit_codes.hpp"

#include <filesystem>
#include <ostream>

#include "mink/error.hpp"
#include "mink/render/render_error.hpp"
#include "point_reader.hpp"

namespace mink::cli {

int report_error(const std::exception& error, std::ostream& err) {
  err << "mink: " << error.what() << '\n';
  if (dynamic_cast<const DegenerateInputError*>(&error) != nullptr) return kDegenerate;
  if (dynamic_cast<const FileWriteError*>(&error) != nullptr) return kOutputFailure;
  // Checked before Error: these derive from it but say nothing about the input.
  if (dynamic_cast<const GlContextError*>(&error) != nullptr ||
      dynamic_cast<const OutputError*>(&error) != nullptr ||
      dynamic_cast<const std::filesystem::filesystem_error*>(&error) != nullptr) {
    return kRuntimeFailure;
  }
  if (dynamic_cast<const Error*>(&error) != nullptr) return kBadInput;
  return kInternalError;
}

}  // namespace mink::cli
