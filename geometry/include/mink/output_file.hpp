#pragma once

#include <filesystem>
#include <fstream>
#include <string>

namespace mink {

/// A file written under a temporary name beside its final path, then flushed, synced to disk
/// and renamed over the path by commit(). Whoever reads the path, and a process killed at any
/// moment, sees either the file that was there before or the new complete one, never a
/// truncated one. A killed process may leave its temporary file, named
/// `.NAME.XXXXXX.partial.EXT` (hidden, in the same directory), which is safe to delete. A path
/// that exists and is not a regular file (/dev/stdout, a FIFO, /dev/full) is written in place,
/// as nothing can be renamed over it.
class OutputFile {
 public:
  /// @brief Creates the parent directories (unless `make_parents` is false) and the temporary
  /// file.
  /// @param what names the output in messages, e.g. "scene file", "--stats file"
  /// @throws FileWriteError naming the path and the reason when either cannot be made
  OutputFile(std::filesystem::path path, std::string what, bool make_parents = true);
  /// Removes the temporary file when commit() was not reached (an error part-way).
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  /// @brief The stream writing the temporary file (binary).
  std::ostream& stream() { return stream_; }
  /// @brief Where a writer that takes a path (libpng, ffmpeg) writes before commit(); it keeps
  /// the final name's extension. Do not use stream() as well.
  const std::filesystem::path& writing_path() const { return writing_path_; }
  /// @brief The final path.
  const std::filesystem::path& path() const { return path_; }

  /// @brief Closes the stream, syncs the file and renames it to path(); afterwards the file is
  /// complete on disk. Does nothing when already committed.
  /// @throws FileWriteError when anything written was lost (a full disk) or the rename failed;
  /// the temporary file is then removed and path() keeps what it held before.
  void commit();
  /// @brief Removes the temporary file without touching path(); commit() then does nothing.
  void discard() noexcept;
  /// @brief True once commit() succeeded.
  bool committed() const { return committed_; }

 private:
  [[noreturn]] void fail(const std::string& doing, int error);

  std::filesystem::path path_;
  std::filesystem::path writing_path_;
  std::string what_;
  std::ofstream stream_;
  bool in_place_ = false;
  bool committed_ = false;
  bool finished_ = false;
};

/// @brief Creates `directory` and its parents unless they exist.
/// @throws FileWriteError naming it and `what` when it cannot be made (a file of that name, no
/// permission)
void make_output_directory(const std::filesystem::path& directory, const std::string& what);

}  // namespace mink
