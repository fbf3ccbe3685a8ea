#pragma once

#include <exception>
#include <iosfwd>

namespace mink::cli {

// The exit codes every `mink` command uses (README, "Exit codes").
enum ExitCode : int {
  kSuccess = 0,
  kInternalError = 1,   // a bug: a failure nothing else explains
  kBadInput = 2,        // usage errors, unreadable files, malformed lines, non-finite values
  kDegenerate = 3,      // a point set with no area: fewer than 3 distinct non-collinear points
  kRuntimeFailure = 4,  // the environment failed: GL, ffmpeg, a program or module missing
  kOutputFailure = 5,   // an output file or directory could not be written: no permission, a
                        // full disk, a path through a file (earlier files of its name survive)
  kDiverged = 6,        // `mink replay`: a step's state hash differs from the recording's
};

// Maps an exception from a command to its exit code and prints "mink: <message>" to `err`.
int report_error(const std::exception& error, std::ostream& err);

}  // namespace mink::cli
