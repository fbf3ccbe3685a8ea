#include "mink/render/video_writer.hpp"

#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ctime>
#include <fstream>
#include <iostream>
#include <sstream>
#include <vector>

#include "mink/error.hpp"
#include "mink/render/render_error.hpp"

extern char** environ;

namespace mink {

namespace {

// Starts `arguments` with stdin, stdout and stderr taken from the given descriptors (-1:
// /dev/null). Returns the process id; throws OutputError naming the program when it cannot
// start (posix_spawnp reports a missing program as ENOENT).
pid_t spawn(const std::vector<std::string>& arguments, int in, int out, int err) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  const int targets[3] = {STDIN_FILENO, STDOUT_FILENO, STDERR_FILENO};
  const int sources[3] = {in, out, err};
  for (int i = 0; i < 3; ++i) {
    if (sources[i] >= 0) {
      posix_spawn_file_actions_adddup2(&actions, sources[i], targets[i]);
    } else {
      posix_spawn_file_actions_addopen(&actions, targets[i], "/dev/null",
                                       i == 0 ? O_RDONLY : O_WRONLY, 0);
    }
  }
  std::vector<char*> argv;
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  pid_t pid = -1;
  const int status = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (status != 0) {
    throw OutputError("cannot start " + arguments[0] + ": " + std::strerror(status) +
                      (status == ENOENT ? " (is ffmpeg installed? apt install ffmpeg)" : ""));
  }
  return pid;
}

// Exit status of a finished child, or a description of how it died.
std::string wait_for(pid_t pid, bool& succeeded) {
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) {
      succeeded = false;
      return std::string("waitpid failed: ") + std::strerror(errno);
    }
  }
  succeeded = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  if (WIFEXITED(status)) return "exit status " + std::to_string(WEXITSTATUS(status));
  if (WIFSIGNALED(status)) return "killed by signal " + std::to_string(WTERMSIG(status));
  return "stopped";
}

}  // namespace

bool ffmpeg_has_encoder(const std::filesystem::path& ffmpeg, const std::string& codec) {
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) return false;
  pid_t pid = -1;
  try {
    pid = spawn({ffmpeg.string(), "-hide_banner", "-encoders"}, -1, fds[1], -1);
  } catch (const OutputError&) {
    close(fds[0]);
    close(fds[1]);
    return false;
  }
  close(fds[1]);
  std::string listing;
  char buffer[4096];
  for (;;) {
    const ssize_t got = read(fds[0], buffer, sizeof buffer);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) break;
    listing.append(buffer, static_cast<std::size_t>(got));
  }
  close(fds[0]);
  bool succeeded = false;
  wait_for(pid, succeeded);
  // Lines look like " V....D libx264   libx264 H.264 ...": the name is the second field.
  std::istringstream lines(listing);
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream fields(line);
    std::string flags;
    std::string name;
    if (fields >> flags >> name && name == codec) return succeeded;
  }
  return false;
}

VideoWriter::VideoWriter(std::filesystem::path path, int width, int height, VideoOptions options)
    : path_(std::move(path)), width_(width), height_(height), codec_(options.codec) {
  if (width <= 0 || height <= 0 || width % 2 != 0 || height % 2 != 0 || width > 16384 ||
      height > 16384) {
    throw InvalidArgumentError("video size " + std::to_string(width) + " x " +
                               std::to_string(height) +
                               " must be positive and even (yuv420p), at most 16384");
  }
  if (options.fps < 1 || options.fps > 1000) {
    throw InvalidArgumentError("video frame rate " + std::to_string(options.fps) +
                               " is outside 1..1000");
  }
  if (codec_.empty()) {
    codec_ = ffmpeg_has_encoder(options.ffmpeg, "libx264") ? "libx264" : "mpeg4";
  }
  // ffmpeg's messages go to a log file so a failure can quote them.
  std::string log_template =
      (std::filesystem::temp_directory_path() / "mink-ffmpeg-XXXXXX.log").string();
  const int log_fd = mkstemps(log_template.data(), 4);
  if (log_fd < 0) {
    throw OutputError("cannot create a log file for ffmpeg: " + std::string(std::strerror(errno)));
  }
  log_path_ = log_template;
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) {
    ::close(log_fd);
    throw OutputError("cannot make a pipe to ffmpeg: " + std::string(std::strerror(errno)));
  }
  std::vector<std::string> arguments = {options.ffmpeg.string(),
                                        "-hide_banner",
                                        "-loglevel",
                                        "error",
                                        "-y",
                                        "-f",
                                        "rawvideo",
                                        "-pix_fmt",
                                        "rgb24",
                                        "-s",
                                        std::to_string(width) + "x" + std::to_string(height),
                                        "-r",
                                        std::to_string(options.fps),
                                        "-i",
                                        "-",
                                        "-c:v",
                                        codec_};
  if (codec_ == "libx264") {
    arguments.insert(arguments.end(), {"-preset", "veryfast", "-crf", "20"});
  } else if (codec_ == "mpeg4") {
    arguments.insert(arguments.end(), {"-q:v", "3"});
  }
  try {
    // ffmpeg writes the temporary file; close() renames it once ffmpeg has succeeded.
    output_ = std::make_unique<OutputFile>(path_, "video", false);
    arguments.insert(arguments.end(), {"-pix_fmt", "yuv420p", output_->writing_path().string()});
    pid_ = spawn(arguments, fds[0], -1, log_fd);
  } catch (...) {
    ::close(fds[0]);
    ::close(fds[1]);
    ::close(log_fd);
    std::filesystem::remove(log_path_);
    throw;
  }
  ::close(fds[0]);
  ::close(log_fd);
  pipe_fd_ = fds[1];
}

VideoWriter::~VideoWriter() {
  if (pid_ < 0) return;
  try {
    close();
  } catch (const std::exception& error) {
    std::cerr << "mink: " << error.what() << '\n';
  }
}

std::string VideoWriter::log_tail() const {
  std::ifstream log(log_path_);
  std::string text((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
  constexpr std::size_t kTail = 800;
  if (text.size() > kTail) text = "..." + text.substr(text.size() - kTail);
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  return text.empty() ? "(ffmpeg printed nothing)" : text;
}

void VideoWriter::write_bytes(const std::uint8_t* data, std::size_t size) {
  // A dead ffmpeg turns writes into SIGPIPE, which would end the whole program: block it on
  // this thread, take the EPIPE, and discard the pending signal.
  sigset_t pipe_signal;
  sigset_t previous;
  sigemptyset(&pipe_signal);
  sigaddset(&pipe_signal, SIGPIPE);
  pthread_sigmask(SIG_BLOCK, &pipe_signal, &previous);
  const bool was_blocked = sigismember(&previous, SIGPIPE) == 1;
  int error = 0;
  while (size > 0) {
    const ssize_t written = write(pipe_fd_, data, size);
    if (written < 0) {
      if (errno == EINTR) continue;
      error = errno;
      break;
    }
    data += written;
    size -= static_cast<std::size_t>(written);
  }
  if (error == EPIPE && !was_blocked) {
    const timespec no_wait{0, 0};
    sigtimedwait(&pipe_signal, nullptr, &no_wait);
  }
  pthread_sigmask(SIG_SETMASK, &previous, nullptr);
  if (error != 0) {
    const Ending ending = end_ffmpeg();
    throw OutputError("ffmpeg stopped taking frames for " + path_.string() + " (" + ending.how +
                      "): " + ending.tail);
  }
}

void VideoWriter::write_frame(const Image& frame) {
  if (pid_ < 0) throw OutputError("video " + path_.string() + " is already closed");
  if (frame.width != width_ || frame.height != height_ ||
      (frame.channels != 3 && frame.channels != 4)) {
    throw InvalidArgumentError("frame of " + std::to_string(frame.width) + " x " +
                               std::to_string(frame.height) + " x " +
                               std::to_string(frame.channels) + " for a video of " +
                               std::to_string(width_) + " x " + std::to_string(height_) + " RGB");
  }
  if (frame.channels == 3) {
    write_bytes(frame.pixels.data(), frame.pixels.size());
  } else {
    const std::size_t count = static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_);
    rgb_.resize(count * 3);
    for (std::size_t i = 0; i < count; ++i) {
      rgb_[3 * i] = frame.pixels[4 * i];
      rgb_[3 * i + 1] = frame.pixels[4 * i + 1];
      rgb_[3 * i + 2] = frame.pixels[4 * i + 2];
    }
    write_bytes(rgb_.data(), rgb_.size());
  }
  ++frames_;
}

// Closes ffmpeg's input, waits for it to exit and removes its log.
VideoWriter::Ending VideoWriter::end_ffmpeg() {
  ::close(pipe_fd_);
  pipe_fd_ = -1;
  Ending ending;
  ending.how = wait_for(pid_, ending.succeeded);
  pid_ = -1;
  ending.tail = log_tail();
  std::filesystem::remove(log_path_);
  return ending;
}

void VideoWriter::close() {
  if (pid_ < 0) return;
  const Ending ending = end_ffmpeg();
  if (!ending.succeeded) {
    output_->discard();
    throw OutputError("ffmpeg failed to write " + path_.string() + " (" + ending.how +
                      "): " + ending.tail);
  }
  output_->commit();
}

}  // namespace mink
