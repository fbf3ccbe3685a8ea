#include "mink/output_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <system_error>
#include <utility>

#include "mink/error.hpp"

namespace mink {

namespace {

// Syncs a file or directory; `true` when done or when the kind of file cannot be synced (a
// device or FIFO reports EINVAL), which is no loss.
bool sync_path(const std::filesystem::path& path, int flags, int& error) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | flags);
  if (fd < 0) {
    error = errno;
    return false;
  }
  const bool synced = ::fsync(fd) == 0 || errno == EINVAL || errno == EROFS;
  error = synced ? 0 : errno;
  ::close(fd);
  return synced;
}

}  // namespace

void make_output_directory(const std::filesystem::path& directory, const std::string& what) {
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  // create_directories reports no error when the path exists as a regular file.
  if (error || !std::filesystem::is_directory(directory)) {
    throw FileWriteError("cannot create the directory '" + directory.string() + "' for " + what +
                         ": " +
                         (error ? error.message() : std::string("a file of that name exists")));
  }
}

OutputFile::OutputFile(std::filesystem::path path, std::string what, bool make_parents)
    : path_(std::move(path)), what_(std::move(what)) {
  if (path_.empty()) throw FileWriteError("cannot write " + what_ + ": the path is empty");
  const std::filesystem::path directory = path_.parent_path();
  if (make_parents && !directory.empty())
    make_output_directory(directory, what_ + " '" + path_.string() + "'");
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path_, error);
  if (std::filesystem::is_directory(status)) fail("write", EISDIR);
  in_place_ = std::filesystem::exists(status) && !std::filesystem::is_regular_file(status);
  if (in_place_) {
    writing_path_ = path_;
  } else {
    // The extension stays last: ffmpeg picks its container from it. Made with O_EXCL under a
    // fresh random name (mkstemp would make it private, 0600): the umask decides its mode as
    // for any new file, and a file it replaces keeps its own mode.
    const std::string extension = path_.extension().string();
    std::random_device entropy;
    int fd = -1;
    for (int attempt = 0; fd < 0; ++attempt) {
      char tag[16];
      std::snprintf(tag, sizeof tag, "%06x", entropy() & 0xffffffu);
      std::string hidden(1, '.');
      hidden += path_.filename().string();
      hidden += '.';
      hidden += tag;
      hidden += ".partial";
      hidden += extension;
      writing_path_ = directory / hidden;
      fd = ::open(writing_path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
      if (fd < 0 && (errno != EEXIST || attempt == 100)) {
        const int reason = errno;
        writing_path_.clear();
        fail("write", reason);
      }
    }
    struct stat existing;
    if (::stat(path_.c_str(), &existing) == 0) ::fchmod(fd, existing.st_mode & 07777);
    ::close(fd);
  }
  errno = 0;
  stream_.open(writing_path_, std::ios::binary | std::ios::trunc);
  if (!stream_) {
    const int reason = errno;
    discard();
    fail("write", reason);
  }
}

OutputFile::~OutputFile() {
  discard();
}

void OutputFile::fail(const std::string& doing, int error) {
  std::string message = "cannot " + doing + " " + what_ + " '" + path_.string() + "'";
  if (error != 0) message += ": " + std::string(std::strerror(error));
  throw FileWriteError(message);
}

void OutputFile::discard() noexcept {
  if (finished_) return;
  finished_ = true;
  if (stream_.is_open()) stream_.close();
  if (!in_place_ && !writing_path_.empty()) ::unlink(writing_path_.c_str());
}

void OutputFile::commit() {
  if (finished_) return;
  int error = 0;
  if (stream_.is_open()) {
    // A stream that failed earlier (a full disk) left its reason in errno, and its later
    // writes made no system calls to change it.
    if (stream_) {
      errno = 0;
      stream_.flush();
      if (stream_) stream_.close();
    }
    if (!stream_) {
      error = errno;
      discard();
      fail("write", error);
    }
  }
  if (!sync_path(writing_path_, 0, error)) {
    discard();
    fail("write", error);
  }
  if (!in_place_) {
    if (::rename(writing_path_.c_str(), path_.c_str()) != 0) {
      error = errno;
      discard();
      fail("write", error);
    }
    // The rename itself reaches the disk with the directory.
    const std::filesystem::path directory = path_.parent_path();
    sync_path(directory.empty() ? std::filesystem::path(".") : directory, O_DIRECTORY, error);
  }
  finished_ = true;
  committed_ = true;
}

}  // namespace mink
