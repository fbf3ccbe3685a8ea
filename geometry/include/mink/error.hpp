#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace mink {

/// Root of every error Minkowski raises at an API boundary, so callers can catch one type.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A parameter outside its documented domain (negative scale, unknown algorithm name, ...).
class InvalidArgumentError : public Error {
 public:
  using Error::Error;
};

/// A coordinate that is NaN or infinite; `index` names the offending point.
/// The message reads "point N has a non-finite coordinate".
class NonFiniteInputError : public Error {
 public:
  explicit NonFiniteInputError(std::size_t index)
      : Error("point " + std::to_string(index) + " has a non-finite coordinate"), index_(index) {}
  /// @brief Index of the offending point in the input it came from.
  std::size_t index() const noexcept { return index_; }

 private:
  std::size_t index_;
};

/// An output could not be written (a scene file, a PNG, the ffmpeg process behind a video, a
/// directory): the environment failed, not the input. The message names the path.
class OutputError : public Error {
 public:
  using Error::Error;
};

/// A file or directory could not be created or written (no permission, a full disk, a path
/// through a regular file). The message names the path and the system's reason. Files are
/// written under a temporary name and renamed when complete (OutputFile), so a file that was
/// there before is left as it was.
class FileWriteError : public OutputError {
 public:
  using OutputError::OutputError;
};

/// Input with no area: fewer than three distinct, non-collinear points.
class DegenerateInputError : public Error {
 public:
  using Error::Error;
};

}  // namespace mink
