#pragma once

#include <sys/types.h>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "mink/output_file.hpp"
#include "mink/render/image.hpp"

namespace mink {

/// @brief How a VideoWriter encodes.
struct VideoOptions {
  int fps = 60;  ///< frames per second, 1..1000
  /// Encoder passed to ffmpeg's -c:v. Empty: libx264 when this ffmpeg has it, else mpeg4.
  std::string codec;
  std::filesystem::path ffmpeg = "ffmpeg";  ///< the ffmpeg program, looked up in PATH
};

/// An MP4 (or any container ffmpeg picks from the file name) made by piping raw RGB24 frames
/// into an ffmpeg process. Errors from ffmpeg, a missing ffmpeg included, surface as
/// OutputError with the end of ffmpeg's own log. ffmpeg writes a temporary file that close()
/// renames to the path once ffmpeg has finished it (OutputFile): a run stopped part-way leaves
/// an earlier file of that name as it was.
class VideoWriter {
 public:
  /// @brief Starts ffmpeg writing `path`.
  /// @throws InvalidArgumentError for a size that is not positive and even (yuv420p needs even
  /// sizes) or fps outside 1..1000
  /// @throws OutputError when ffmpeg cannot start
  VideoWriter(std::filesystem::path path, int width, int height, VideoOptions options = {});
  ~VideoWriter();  ///< closes if close() was not called; errors then are only logged to stderr
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  /// @brief One frame, RGB or RGBA (alpha dropped), of the writer's size.
  /// @throws InvalidArgumentError for another size
  /// @throws OutputError when ffmpeg has gone
  void write_frame(const Image& frame);
  /// @brief Waits for ffmpeg to finish the file.
  /// @throws OutputError when it failed.
  void close();

  /// @brief Frames written so far.
  int frames_written() const { return frames_; }
  /// @brief The encoder in use (the chosen default when VideoOptions::codec was empty).
  const std::string& codec() const { return codec_; }

 private:
  void write_bytes(const std::uint8_t* data, std::size_t size);
  std::string log_tail() const;
  struct Ending {
    bool succeeded = false;
    std::string how;   ///< exit status or signal, as wait_for words it
    std::string tail;  ///< the end of ffmpeg's log
  };
  Ending end_ffmpeg();

  std::filesystem::path path_;
  std::unique_ptr<OutputFile> output_;  // what ffmpeg writes until close() renames it
  std::filesystem::path log_path_;
  int width_;
  int height_;
  std::string codec_;
  pid_t pid_ = -1;
  int pipe_fd_ = -1;
  int frames_ = 0;
  std::vector<std::uint8_t> rgb_;
};

/// @brief True when `ffmpeg -encoders` lists `codec`.
bool ffmpeg_has_encoder(const std::filesystem::path& ffmpeg, const std::string& codec);

}  // namespace mink
