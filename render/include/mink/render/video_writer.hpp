#pragma once

#include <sys/types.h>
#include <cstdio>
#include <filesystem>
#include <string>

#include "mink/render/image.hpp"

namespace mink {

struct VideoOptions {
  int fps = 60;
  // Encoder passed to ffmpeg's -c:v. Empty: libx264 when this ffmpeg has it, else mpeg4.
  std::string codec;
  std::filesystem::path ffmpeg = "ffmpeg";
};

// An MP4 (or any container ffmpeg picks from the file name) made by piping raw RGB24 frames
// into an ffmpeg process. Errors from ffmpeg, a missing ffmpeg included, surface as
// OutputError with the end of ffmpeg's own log.
class VideoWriter {
 public:
  // Starts ffmpeg. Throws InvalidArgumentError for a size that is not positive and even
  // (yuv420p needs even sizes) or fps outside 1..1000, OutputError when ffmpeg cannot start.
  VideoWriter(std::filesystem::path path, int width, int height, VideoOptions options = {});
  ~VideoWriter();  // closes if close() was not called; errors then are only logged to stderr
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  // One frame, RGB or RGBA (alpha dropped), of the writer's size. Throws
  // InvalidArgumentError for another size, OutputError when ffmpeg has gone.
  void write_frame(const Image& frame);
  // Waits for ffmpeg to finish the file; throws OutputError when it failed.
  void close();

  int frames_written() const { return frames_; }
  const std::string& codec() const { return codec_; }

 private:
  void write_bytes(const std::uint8_t* data, std::size_t size);
  std::string log_tail() const;

  std::filesystem::path path_;
  std::filesystem::path log_path_;
  int width_;
  int height_;
  std::string codec_;
  pid_t pid_ = -1;
  int pipe_fd_ = -1;
  int frames_ = 0;
  std::vector<std::uint8_t> rgb_;
};

// True when `ffmpeg -encoders` lists `codec`.
bool ffmpeg_has_encoder(const std::filesystem::path& ffmpeg, const std::string& codec);

}  // namespace mink
